#include "cli/start_flags.hpp"

#include "cli/numeric_flags.hpp"

#include <stdexcept>

namespace railstab {

void add_start_flags(CLI::App* cmd, SceneOverrides& overrides, StartFlags& start) {
  CLI::Validator form(
      [](std::string& text) -> std::string {
        try {
          parse_offset_setting(text);
          return {};
        } catch (const std::invalid_argument& e) {
          return e.what();
        }
      },
      "");
  cmd->add_option_function<std::vector<std::string>>(
         "--offset",
         [&overrides](const std::vector<std::string>& texts) {
           overrides.offsets.clear();
           for (const std::string& text : texts) overrides.offsets.push_back(parse_offset_setting(text));
         },
         "initial offset of a body, e.g. --offset wheelset1.y_m=0.005 or --offset "
         "bogie1.y_m=0.003 (a bogie frame's name moves it and its wheelsets); keys x_m, y_m, "
         "z_m, roll_rad, pitch_rad, yaw_rad; replaces that value of the scene's initial_offset "
         "(repeatable)")
      ->type_name("BODY.COORDINATE=VALUE")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
      ->check(form);
  cmd->add_option("--mode", start.mode,
                  "start on a mode of the steady state at the run's speed: 'hunting' (the least "
                  "stable lateral mode) or a mode name as `railstab eigen` prints it; with "
                  "--mode-amplitude, instead of the scene's initial offsets");
  cmd->add_option("--mode-amplitude", start.mode_amplitude_m,
                  "lateral shift (m) of the leading wheelset at the start on --mode")
      ->check(finite_in(flag_ranges::amplitude_m));
}

void check_start_flags(const SceneOverrides& overrides, const StartFlags& start) {
  if (!start.mode.empty() && !overrides.offsets.empty())
    throw std::invalid_argument(
        "--mode and --offset: give one of them (a start on a mode replaces the initial offsets)");
  if (!start.mode.empty() && !start.mode_amplitude_m)
    throw std::invalid_argument("--mode " + start.mode +
                                ": expected --mode-amplitude M too (the leading wheelset's "
                                "lateral shift at the start, in m)");
  if (start.mode.empty() && start.mode_amplitude_m)
    throw std::invalid_argument("--mode-amplitude: expected --mode hunting or --mode NAME too");
}

std::optional<ModeStart> mode_start_from_flags(const PreparedScene& scene, const StartFlags& start) {
  if (start.mode.empty()) return std::nullopt;
  return mode_start_state(scene.model, scene.speed_m_per_s, scene.equilibrium.state, start.mode,
                          *start.mode_amplitude_m);
}

}  // namespace railstab
