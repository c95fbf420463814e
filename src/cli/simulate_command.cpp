#include "cli/simulate_command.hpp"

#include <railstab/check/run_check.hpp>

#include "cli/scene_command.hpp"
#include "cli/numeric_flags.hpp"
#include "cli/set_flag.hpp"
#include "cli/speed_ramp_run.hpp"
#include "cli/start_flags.hpp"
#include <railstab/setup/prepare_scene.hpp>
#include <railstab/integrate/error_estimate.hpp>
#include <railstab/integrate/integrator.hpp>
#include <railstab/integrate/work_precision.hpp>
#include <railstab/io/csv.hpp>
#include <railstab/io/file_names.hpp>
#include <railstab/io/gnuplot.hpp>
#include <railstab/io/output_files.hpp>
#include <railstab/io/output_set.hpp>
#include <railstab/io/ride_files.hpp>
#include <railstab/model/equations_of_motion.hpp>
#include <railstab/report/simulation_report.hpp>
#include <railstab/report/ride_plots.hpp>
#include <railstab/report/time_plots.hpp>
#include <railstab/ride/ride_history.hpp>

#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>

namespace railstab {

namespace {

struct SimulateArgs : SceneCommandArgs {
  StartFlags start;
  RampFlags ramp;
  double t_end = 0.0;
  std::string csv;
  std::string integrator;  // label, e.g. "cvode_bdf_q2"; empty: the scene's
  std::optional<double> rtol, atol;
  bool estimate_error = true;
  bool stop_on_lift_off = false;
};

IntegrationOptions integration_options(const SimulateArgs& args, const SimulationSpec& sim) {
  IntegrationOptions opt = integration_options_for(sim);
  if (!args.integrator.empty()) {
    const IntegratorVariant v = parse_integrator_variant(args.integrator);
    opt.kind = v.kind;
    opt.order = v.order;
  }
  opt.relative_tolerance = args.rtol.value_or(sim.relative_tolerance);
  opt.absolute_tolerance = args.atol.value_or(sim.absolute_tolerance);
  opt.stop_on_lift_off = args.stop_on_lift_off;
  return opt;
}

void run_simulate(const SimulateArgs& args) {
  check_start_flags(args.overrides, args.start);
  const bool ramp = !args.ramp.rates_m_per_s2.empty();
  if (!ramp && args.ramp.end_speed_m_per_s)
    throw std::invalid_argument("--ramp-to: expected --ramp-rate A too");
  if (args.plots && !ramp) require_gnuplot();  // before the run, not after it
  PreparedScene scene = prepare_command_scene(args);
  const Model& model = scene.model;
  std::cerr << "scene " << model.name << ": " << model.bodies.size() << " bodies, "
            << model.state_size() << " states, speed " << scene.speed_m_per_s << " m/s\n"
            << "static equilibrium: " << scene.equilibrium.iterations
            << " Newton iterations, residual " << scene.equilibrium.max_acceleration << "\n";

  IntegrationOptions opt = integration_options(args, scene.spec.simulation);
  opt.progress = [&](double t) {
    std::cerr << "  t = " << t << " / " << opt.t_end_s << " s\n";
  };
  RunStart start;
  for (const OffsetSetting& o : args.overrides.offsets) start.offset_settings.push_back(o.text);
  Eigen::VectorXd x0;
  if (const std::optional<ModeStart> mode = mode_start_from_flags(scene, args.start)) {
    x0 = mode->state;
    start.on_mode = true;
    start.mode_name = mode->mode_name;
    start.eigenvalue = mode->eigenvalue;
    start.leading_wheelset = mode->leading_wheelset;
    start.amplitude_m = mode->amplitude_m;
    std::cerr << "start on mode '" << mode->mode_name << "' (" << mode->eigenvalue.real()
              << " 1/s), " << mode->leading_wheelset << " lateral " << mode->amplitude_m << " m\n";
  } else {
    x0 = perturbed_initial_state(scene);
  }
  if (ramp) {  // a ramp per rate instead of the run at one speed
    run_speed_ramps(scene, args.scene, x0, start, opt, args.ramp, args.out_dir);
    return;
  }
  const Trajectory traj = integrate(model, scene.speed_m_per_s, x0, opt);
  if (!traj.stopped_early.empty())
    std::cout << "stopped early: " << traj.stopped_early << "\n";
  if (!traj.events.empty())
    std::cout << traj.events.size() << " wheel-rail contact losses/regains, first: "
              << traj.events.front().description << "\n";
  for (const ModelWarning& w : check_run(model, traj)) std::cout << "warning: " << w.message << "\n";
  std::optional<ErrorEstimate> error;
  if (args.estimate_error) {
    std::cerr << "error estimate: the same run at 100x tighter tolerances\n";
    error = estimate_integration_error(model, scene.speed_m_per_s, x0, opt, traj);
  }

  // All files are staged and committed together (io/output_set.hpp): data
  // files, run summary, then the plots, which are views of the CSVs.
  const std::string stem = scene_file_stem(args.scene) + "_" + speed_file_tag(scene.speed_m_per_s);
  // Wheel forces and accelerations at every output time (ride/ride_history.hpp),
  // computed once: the CSVs, the plots and the summary read them.
  const RideHistory ride =
      ride_history(model, scene.speed_m_per_s, traj, scene.spec.assessment.prudhomme_factor);
  const std::string summary =
      simulation_run_json(model, scene.speed_m_per_s, opt, traj, error, start, &ride);
  OutputSet outputs(args.out_dir);
  for (const std::string& name : time_plot_file_names(stem)) outputs.replaces(name);
  for (const std::string& name : ride_plot_file_names(stem)) outputs.replaces(name);
  PlottedCsv trajectory_csv, roll_csv;
  auto write_trajectory = [&](std::ostream& out) { write_trajectory_csv(out, model, scene.speed_m_per_s, traj); };
  if (args.csv.empty()) {
    trajectory_csv.final_path = stem + ".csv";
    trajectory_csv.staged_path = outputs.write(trajectory_csv.final_path, write_trajectory);
  } else {
    outputs.replaces(stem + ".csv");  // an earlier default CSV would not match this run
    trajectory_csv.final_path = std::filesystem::absolute(args.csv).string();
    trajectory_csv.staged_path = outputs.write_at(args.csv, write_trajectory);
  }
  trajectory_csv.staged_path = std::filesystem::absolute(trajectory_csv.staged_path).string();
  trajectory_csv.header_lines = csv_physical_lines(trajectory_csv_header(model));
  roll_csv.final_path = stem + "_absolute_roll.csv";
  roll_csv.staged_path = std::filesystem::absolute(outputs.write(
      roll_csv.final_path, [&](std::ostream& out) { write_absolute_roll_csv(out, model, scene.speed_m_per_s, traj); }));
  roll_csv.header_lines = csv_physical_lines(absolute_roll_csv_header(model));
  PlottedCsv forces_csv, accelerations_csv;
  forces_csv.final_path = stem + "_wheel_forces.csv";
  forces_csv.staged_path = std::filesystem::absolute(outputs.write(
      forces_csv.final_path, [&](std::ostream& out) { write_wheel_forces_csv(out, model, ride); }));
  forces_csv.header_lines = csv_physical_lines(wheel_forces_csv_header(model, ride));
  accelerations_csv.final_path = stem + "_accelerations.csv";
  accelerations_csv.staged_path = std::filesystem::absolute(outputs.write(
      accelerations_csv.final_path, [&](std::ostream& out) { write_accelerations_csv(out, ride); }));
  accelerations_csv.header_lines = csv_physical_lines(accelerations_csv_header(ride));
  outputs.write(stem + "_run.json", [&](std::ostream& out) { out << summary; });
  if (args.plots) {
    plot_time_histories(model, scene.speed_m_per_s, outputs, stem, trajectory_csv, roll_csv, opt.t_start_s,
                        traj.times_s.back());
    plot_ride_quantities(model, scene.speed_m_per_s, outputs, stem, ride, forces_csv,
                         accelerations_csv, opt.t_start_s, traj.times_s.back());
  }
  list_written(outputs.commit(), std::cout);
  const double simulated = traj.times_s.back() - opt.t_start_s;
  std::cout << "integrator " << IntegratorVariant{opt.kind, opt.order}.label() << " rtol "
            << opt.relative_tolerance << " atol " << opt.absolute_tolerance << ": "
            << traj.stats.steps << " steps, " << traj.stats.rhs_evaluations
            << " rhs evaluations, " << traj.stats.jacobian_evaluations << " AD Jacobians, wall "
            << traj.stats.wall_seconds << " s for " << simulated << " s simulated";
  if (simulated > 0.0 && traj.stats.wall_seconds > 0.0)
    std::cout << " (real-time factor " << simulated / traj.stats.wall_seconds << ")";
  std::cout << "\n";
  if (!error)
    std::cout << "error not estimated (--no-error-estimate)\n";
  else if (!error->available)
    std::cout << "error not estimated: " << error->reason << "\n";
  else if (error->limit_cycle.settled)
    std::cout << "estimated error on the limit cycle (" << error->limit_cycle.signal << ", last "
              << error->limit_cycle.periods_compared << " periods): amplitude "
              << error->limit_cycle.amplitude_error_m << " m of " << error->limit_cycle.amplitude_m
              << " m, period " << error->limit_cycle.period_error_s << " s of "
              << error->limit_cycle.period_s << " s; phase drift between the runs (not an error "
              << "of the cycle) " << error->position_error << " at " << error->where
              << "; from the same run at 100x tighter tolerances (wall " << error->wall_seconds
              << " s, CPU " << error->cpu_seconds << " s)\n";
  else
    std::cout << "estimated error: " << error->position_error << " (m or rad, at " << error->where
              << "), lateral shift/yaw " << error->lateral_error
              << ", from the same run at 100x tighter tolerances (wall " << error->wall_seconds
              << " s, CPU " << error->cpu_seconds << " s)\n";
  if (error && error->available && error->reference_stopped_early != traj.stopped_early)
    std::cout << "note: the tighter run "
              << (error->reference_stopped_early.empty() ? "did not stop early"
                                                         : "stopped: " + error->reference_stopped_early)
              << "\n";
}

}  // namespace

void register_simulate_command(CLI::App& app) {
  auto args = std::make_shared<SimulateArgs>();
  args->overrides.apply_track_irregularities = true;
  CLI::App* cmd = app.add_subcommand("simulate", "integrate the nonlinear model in time");
  SceneFlags flags;
  flags.speed = flags.arc_length = flags.plots = true;
  flags.arc_length_help = "arc length (m) of the reference point at t = 0";
  add_scene_flags(cmd, *args, flags);
  add_start_flags(cmd, args->overrides, args->start);
  add_ramp_flags(cmd, args->ramp);
  cmd->add_option("--t-end", args->overrides.t_end_s, "end time in s (overrides the scene)")
      ->check(finite_in(flag_ranges::t_end_s));
  cmd->add_option("--csv", args->csv, "CSV output file (default OUT/<scene>_<V>mps.csv)");
  cmd->add_option("--integrator", args->integrator,
                  "cvode_bdf, cvode_adams, arkode_erk, arkode_dirk or arkode_imex; _qN sets the "
                  "(maximum) order, e.g. cvode_bdf_q2 (default: the scene's [simulation] "
                  "integrator, arkode_dirk)");
  cmd->add_option("--rtol", args->rtol, "relative tolerance (default: the scene's, 1e-3)")
      ->check(finite_in(flag_ranges::relative_tolerance));
  cmd->add_option("--atol", args->atol, "absolute tolerance (default: the scene's, 1e-6)")
      ->check(finite_in(flag_ranges::absolute_tolerance));
  cmd->add_flag("!--no-error-estimate", args->estimate_error,
                "skip the second run at 100x tighter tolerances that estimates the error");
  cmd->add_flag("--stop-on-lift-off", args->stop_on_lift_off,
                "stop at the first wheel that loses contact (otherwise lift-offs are listed and "
                "the run goes on)");
  cmd->callback([args] { run_simulate(*args); });
}

}  // namespace railstab
