#pragma once
#include <CLI/CLI.hpp>

namespace railstab {
// `railstab verify SCENE --speed V [--amplitude A] [--json FILE] [--out DIR]`
void register_verify_command(CLI::App& app);
}  // namespace railstab
