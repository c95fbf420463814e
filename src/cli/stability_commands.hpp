#pragma once
#include <CLI/CLI.hpp>

namespace railstab {
// `railstab equilibrium`, `eigen`, `critical-speed` and `sweep`.
void register_stability_commands(CLI::App& app);
}  // namespace railstab
