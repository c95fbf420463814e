#include "cli/assess_command.hpp"

#include "cli/numeric_flags.hpp"
#include "cli/scene_command.hpp"
#include "cli/start_flags.hpp"

#include <railstab/assessment/assessment_run.hpp>
#include <railstab/io/file_names.hpp>
#include <railstab/io/gnuplot.hpp>
#include <railstab/report/assessment_report.hpp>

#include <iostream>
#include <memory>

namespace railstab {
namespace {

struct AssessArgs : SceneCommandArgs {
  StartFlags start;
};

void run_assess(const AssessArgs& args) {
  check_start_flags(args.overrides, args.start);
  if (args.plots) require_gnuplot();
  PreparedScene scene = prepare_command_scene(args);
  const Model& model = scene.model;
  // The start: the scene's initial offsets (with any --offset), or a mode.
  std::string start = "the scene's initial offsets and rates";
  for (const OffsetSetting& o : args.overrides.offsets) start += ", --offset " + o.text;
  Eigen::VectorXd x0;
  if (const std::optional<ModeStart> mode = mode_start_from_flags(scene, args.start)) {
    x0 = mode->state;
    start = mode_start_description(*mode);
  } else {
    x0 = perturbed_initial_state(scene);
  }
  const double t_end = scene.spec.simulation.t_end_s;
  std::cerr << "assess " << model.name << " at " << scene.speed_m_per_s << " m/s: " << t_end
            << " s (" << model.distance_at(t_end, scene.speed_m_per_s) << " m) from " << start << "\n";
  const AssessmentRun run = run_running_stability_assessment(
      model, scene.speed_m_per_s, x0, start, scene.spec.simulation, scene.spec.assessment,
      [&](double t) { std::cerr << "  t = " << t << " / " << t_end << " s\n"; });
  OutputSet outputs(args.out_dir);
  const std::string stem = scene_file_stem(args.scene) + "_" + speed_file_tag(scene.speed_m_per_s);
  const std::string shown =
      write_assessment_report(model, run.assessment, scene.spec.assessment, run.conditions, outputs,
                              stem, args.plots);
  std::cout << shown;
  list_written(outputs.commit(), std::cout);
}

}  // namespace

void register_assess_command(CLI::App& app) {
  auto args = std::make_shared<AssessArgs>();
  args->overrides.apply_track_irregularities = true;
  CLI::App* cmd = app.add_subcommand(
      "assess", "EN 14363 running stability from a time-domain run: Sum Y rms and bogie frame lateral "
                "acceleration rms (band-passed around f0, sliding windows) and the 2 m safety quantities "
                "against their limits");
  SceneFlags flags;
  flags.speed = flags.arc_length = flags.plots = true;
  add_scene_flags(cmd, *args, flags);
  add_start_flags(cmd, args->overrides, args->start);
  cmd->add_option("--t-end", args->overrides.t_end_s, "end time in s (overrides the scene)")
      ->check(finite_in(flag_ranges::t_end_s));
  cmd->callback([args] { run_assess(*args); });
}

}  // namespace railstab
