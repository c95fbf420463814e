#pragma once
// `railstab track SCENE`: the scene's track irregularities ([track.irregularities])
// as synthesised, their PSDs against the target, plots.
#include <CLI/CLI.hpp>

namespace railstab {

void register_track_command(CLI::App& app);

}  // namespace railstab
