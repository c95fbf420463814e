#pragma once
#include <CLI/CLI.hpp>

namespace railstab {
// `railstab sensitivity`: d(critical speed)/dp for every named parameter.
void register_sensitivity_command(CLI::App& app);
}  // namespace railstab
