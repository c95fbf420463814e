#pragma once
#include <CLI/CLI.hpp>

namespace railstab {
// `railstab bifurcation`: the branch of hunting orbits from the Hopf point
// (and from a time-domain cycle), the nonlinear critical speed, the diagram.
void register_bifurcation_command(CLI::App& app);
}  // namespace railstab
