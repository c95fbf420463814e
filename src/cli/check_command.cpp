#include "cli/check_command.hpp"

#include "cli/scene_command.hpp"
#include <railstab/check/model_check.hpp>
#include "cli/numeric_flags.hpp"
#include "cli/set_flag.hpp"
#include <railstab/io/file_names.hpp>
#include <railstab/io/output_set.hpp>
#include <railstab/report/model_check_report.hpp>
#include <railstab/report/run_conditions.hpp>
#include <railstab/setup/prepare_scene.hpp>

#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>

namespace railstab {

namespace {

struct CheckArgs : SceneCommandArgs {
  bool natural_frequencies = true;
};

void run_check(const CheckArgs& a) {
  const SceneSpec spec = load_scene_with_overrides(a.scene, a.overrides);
  ModelCheckOptions options;
  options.natural_frequencies = a.natural_frequencies;
  const ModelCheckReport r = check_scene(spec, options);
  // The scene file's stem, the arc length in a curve and the speed the
  // equilibrium (axle loads, cant, wheel-load balance) was taken at.
  const std::string stem = steady_state_file_stem(a.scene, assemble_model(spec)) + "_check_" +
                           speed_file_tag(spec.speed_m_per_s);
  OutputSet outputs(a.out_dir);
  outputs.write(stem + ".md", [&](std::ostream& out) { write_model_check_markdown(out, r); });
  outputs.write(stem + ".json", [&](std::ostream& out) { write_model_check_json(out, r); });
  const std::vector<std::string> written = outputs.commit();
  print_model_check_summary(std::cout, r);
  list_written(written, std::cout);
  if (!r.errors.empty()) {
    std::ostringstream msg;
    msg << "model check of " << r.scene << ": " << r.errors.size()
        << " error(s) (listed above and in the report)";
    throw std::runtime_error(msg.str());
  }
}

}  // namespace

void register_check_command(CLI::App& app) {
  auto a = std::make_shared<CheckArgs>();
  CLI::App* cmd = app.add_subcommand(
      "check", "model checks before a run: masses, axle loads, static deflections, natural "
               "frequencies at rest, warnings for the usual input mistakes");
  SceneFlags flags;
  flags.speed = flags.arc_length = true;
  flags.speed_help = "speed V in m/s of the equilibrium the axle loads are taken at";
  flags.arc_length_help = "arc length (m) of the reference point at t = 0";
  add_scene_flags(cmd, *a, flags);
  cmd->add_flag("!--no-frequencies", a->natural_frequencies,
                "skip the natural frequencies at rest (one equilibrium and eigen-analysis less)");
  cmd->callback([a] { run_check(*a); });
}

}  // namespace railstab
