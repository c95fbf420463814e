#pragma once
#include <CLI/CLI.hpp>

namespace railstab {
// `railstab simulate SCENE [--speed V] [--t-end T] [--csv FILE] [--out DIR]`
void register_simulate_command(CLI::App& app);
}  // namespace railstab
