#pragma once
// `railstab assess SCENE --speed V`: EN 14363's running-stability assessment
// from a time-domain run (docs/assessment.md).
#include <CLI/CLI.hpp>

namespace railstab {

void register_assess_command(CLI::App& app);

}  // namespace railstab
