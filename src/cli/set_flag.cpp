#include "cli/set_flag.hpp"

#include <stdexcept>
#include <string>

namespace railstab {

void add_set_flag(CLI::App* cmd, std::vector<SceneValueSetting>& values) {
  CLI::Validator form(
      [](std::string& text) -> std::string {
        try {
          parse_scene_value_setting(text);
          return {};
        } catch (const std::invalid_argument& e) {
          return e.what();
        }
      },
      "");  // the type name says the form
  cmd->add_option_function<std::vector<std::string>>(
         "--set",
         [&values](const std::vector<std::string>& texts) {
           values.clear();
           for (const std::string& text : texts) values.push_back(parse_scene_value_setting(text));
         },
         "override or add a scene value by its key path, e.g. --set "
         "elements.yaw_damper.damping_N_s_per_m[0]=2.5e5, --set bodies.carbody.mass_kg=32000 or "
         "--set 'bodies.wheelset1.initial_offset={y_m = 0.001}' (a number or a TOML value: "
         "{...}, [...], \"...\", true/false; repeatable; as if the file said so)")
      ->type_name("KEY=VALUE")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
      ->check(form);
}

}  // namespace railstab
