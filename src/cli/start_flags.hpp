#pragma once
// How a time-domain run starts, for simulate and verify:
//   --offset BODY.COORDINATE=VALUE  (repeatable) initial offsets on top of the
//                                   scene's (setup/initial_offsets.hpp)
//   --mode hunting|NAME --mode-amplitude M
//                                   the steady state plus the mode scaled to
//                                   M metres of the leading wheelset's lateral
//                                   shift (stability/mode_start.hpp); the
//                                   scene's initial offsets are not used
// --mode and --offset exclude each other; --mode needs --mode-amplitude.
#include "cli/scene_command.hpp"

#include <railstab/stability/mode_start.hpp>

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace railstab {

struct StartFlags {
  std::string mode;  // empty: no mode start
  std::optional<double> mode_amplitude_m;
};

void add_start_flags(CLI::App* cmd, SceneOverrides& overrides, StartFlags& start);

// Throws std::invalid_argument naming the flags when they do not go together.
void check_start_flags(const SceneOverrides& overrides, const StartFlags& start);

// The mode start when --mode is given, else nothing.
std::optional<ModeStart> mode_start_from_flags(const PreparedScene& scene, const StartFlags& start);

}  // namespace railstab
