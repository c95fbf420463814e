#include "cli/assess_command.hpp"

#include "cli/numeric_flags.hpp"
#include "cli/scene_command.hpp"
#include "cli/start_flags.hpp"

#include <railstab/assessment/running_stability.hpp>
#include <railstab/integrate/integrator.hpp>
#include <railstab/integrate/work_precision.hpp>
#include <railstab/io/file_names.hpp>
#include <railstab/io/gnuplot.hpp>
#include <railstab/report/assessment_report.hpp>
#include <railstab/ride/ride_history.hpp>

#include <algorithm>
#include <iostream>
#include <memory>
#include <sstream>

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
  IntegrationOptions opt = integration_options_for(scene.spec.simulation);
  // EN 14363 steps its 2 m means by 0.5 m: an output at least every 0.5 m.
  opt.output_interval_s = std::min(opt.output_interval_s, 0.5 / scene.speed_m_per_s);
  opt.progress = [&](double t) { std::cerr << "  t = " << t << " / " << opt.t_end_s << " s\n"; };
  // The start: the scene's initial offsets (with any --offset), or a mode.
  std::string start = "the scene's initial offsets and rates";
  for (const OffsetSetting& o : args.overrides.offsets) start += ", --offset " + o.text;
  Eigen::VectorXd x0;
  if (const std::optional<ModeStart> mode = mode_start_from_flags(scene, args.start)) {
    x0 = mode->state;
    std::ostringstream text;
    text << "mode '" << mode->mode_name << "', " << mode->leading_wheelset << " lateral " << mode->amplitude_m << " m";
    start = text.str();
  } else {
    x0 = perturbed_initial_state(scene);
  }
  std::cerr << "assess " << model.name << " at " << scene.speed_m_per_s << " m/s: " << opt.t_end_s
            << " s (" << model.distance_at(opt.t_end_s, scene.speed_m_per_s) << " m) from " << start << "\n";
  const Trajectory traj = integrate(model, scene.speed_m_per_s, x0, opt);
  const RideHistory ride = ride_history(model, scene.speed_m_per_s, traj, scene.spec.assessment.prudhomme_factor);
  const RunningStabilityAssessment a =
      assess_running_stability(model, ride, scene.spec.assessment, traj.stopped_early);
  AssessmentRunConditions run;
  run.speed_m_per_s = scene.speed_m_per_s;
  if (const TrackIrregularities* irr = model.track.irregularities())
    run.excitation = "irregular track (" + irregularity_description(*irr) + "), starting at t = 0 from " + start;
  else
    run.excitation = "perfect track, disturbed at t = 0 by " + start +
                     " (no [track.irregularities]: EN 14363 runs on measured track)";
  run.integrator = IntegratorVariant{opt.kind, opt.order}.label();
  run.relative_tolerance = opt.relative_tolerance;
  run.output_interval_s = opt.output_interval_s;
  run.simulated_s = traj.times_s.back() - opt.t_start_s;
  OutputSet outputs(args.out_dir);
  const std::string stem = scene_file_stem(args.scene) + "_" + speed_file_tag(scene.speed_m_per_s);
  const std::string shown =
      write_assessment_report(model, a, scene.spec.assessment, run, outputs, stem, args.plots);
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
