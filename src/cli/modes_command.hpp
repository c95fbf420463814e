#pragma once
#include <CLI/CLI.hpp>

namespace railstab {
// `railstab modes SCENE --speed V`: plan-view plots of the mode shapes.
void register_modes_command(CLI::App& app);
}  // namespace railstab
