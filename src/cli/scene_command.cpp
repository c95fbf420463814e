#include "cli/scene_command.hpp"

#include "cli/model_warnings.hpp"
#include "cli/numeric_flags.hpp"
#include "cli/set_flag.hpp"

namespace railstab {

void add_scene_flags(CLI::App* cmd, SceneCommandArgs& a, const SceneFlags& which) {
  cmd->add_option("scene", a.scene, "scene file (TOML)")->required()->check(CLI::ExistingFile);
  add_set_flag(cmd, a.overrides.values);
  if (which.speed)
    cmd->add_option("--speed", a.overrides.speed_m_per_s, which.speed_help)
        ->check(finite_in(flag_ranges::speed_m_per_s));
  if (which.arc_length)
    cmd->add_option("--arc-length", a.overrides.reference_arc_length_m, which.arc_length_help)
        ->check(finite_in(flag_ranges::arc_length_m));
  cmd->add_option("--out", a.out_dir, "output directory")->capture_default_str();
  if (which.plots) cmd->add_flag("!--no-plots", a.plots, which.plots_help);
}

PreparedScene prepare_command_scene(const SceneCommandArgs& a) {
  PreparedScene s = prepare_scene(a.scene, a.overrides);
  print_model_warnings_to_stderr(s);
  return s;
}

void list_written(const std::vector<std::string>& files, std::ostream& out) {
  for (const std::string& f : files) out << "wrote " << f << "\n";
}

}  // namespace railstab
