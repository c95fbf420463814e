#pragma once
// The model check's warnings, printed (stderr) by every command that runs a
// scene before its analysis starts.
#include <railstab/setup/prepare_scene.hpp>

namespace railstab {

// Runs check_model without the natural frequencies (one linearisation about
// the scene's equilibrium, no extra equilibrium) and prints its warnings to
// stderr. A failing check is reported as a note, never stops the command.
void print_model_warnings_to_stderr(const PreparedScene& scene);

}  // namespace railstab
