#pragma once
#include <CLI/CLI.hpp>

namespace railstab {
// `railstab check SCENE [--speed V] [--arc-length S] [--out DIR]`: masses,
// axle loads, static deflections, natural frequencies at rest and warnings
// for the usual input mistakes (check/model_check.hpp); Markdown and JSON.
void register_check_command(CLI::App& app);
}  // namespace railstab
