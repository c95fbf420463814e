#pragma once
#include <CLI/CLI.hpp>

namespace railstab {
// `railstab curving`: steady curving over a range of cant deficiency (at one
// radius) or of radius (at one cant deficiency), with wheel forces per
// wheelset, to the physical limit (curving/steady_curving.hpp).
void register_curving_command(CLI::App& app);
}  // namespace railstab
