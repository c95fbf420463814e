#include "cli/simulate_command.hpp"

#include "cli/scene_setup.hpp"
#include "integrate/integrator.hpp"
#include "io/output_files.hpp"
#include "model/equations_of_motion.hpp"
#include "report/time_plots.hpp"

#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>

namespace railstab {

namespace {

struct SimulateArgs {
  std::string scene;
  SceneOverrides overrides;
  double t_end = 0.0;
  std::string csv;
  std::string out_dir = "out";
  bool plots = true;
};

void run_simulate(const SimulateArgs& args) {
  PreparedScene scene = prepare_scene(args.scene, args.overrides);
  const Model& model = scene.model;
  std::cerr << "scene " << model.name << ": " << model.bodies.size() << " bodies, "
            << model.state_size() << " states, speed " << model.speed_m_per_s << " m/s\n"
            << "static equilibrium: " << scene.equilibrium.iterations
            << " Newton iterations, residual " << scene.equilibrium.max_acceleration << "\n";

  IntegrationOptions opt;
  opt.t_end_s = scene.spec.simulation.t_end_s;
  opt.output_interval_s = scene.spec.simulation.output_interval_s;
  opt.relative_tolerance = scene.spec.simulation.relative_tolerance;
  opt.absolute_tolerance = scene.spec.simulation.absolute_tolerance;
  opt.progress = [&](double t) {
    std::cerr << "  t = " << t << " / " << opt.t_end_s << " s\n";
  };
  const Trajectory traj = integrate(model, perturbed_initial_state(scene), opt);
  if (!traj.stopped_early.empty())
    std::cout << "stopped early: " << traj.stopped_early << "\n";

  const std::string base =
      (std::filesystem::path(args.out_dir) / (model.name + "_" +
                                              std::to_string(int(std::lround(model.speed_m_per_s))) +
                                              "mps")).string();
  const std::string csv = args.csv.empty() ? base + ".csv" : args.csv;
  write_trajectory_csv(csv, model, traj);
  std::cout << "wrote " << csv << "\n";
  const std::string roll_csv = base + "_absolute_roll.csv";
  write_absolute_roll_csv(roll_csv, model, traj);
  std::cout << "wrote " << roll_csv << "\n";
  if (args.plots)
    for (const std::string& png : plot_time_histories(model, csv, roll_csv, base))
      std::cout << "wrote " << png << "\n";
  const double simulated = traj.times_s.back() - opt.t_start_s;
  std::cout << "integrator " << integrator_name(opt.kind) << " rtol " << opt.relative_tolerance
            << " atol " << opt.absolute_tolerance << ": " << traj.stats.steps << " steps, "
            << traj.stats.rhs_evaluations << " rhs evaluations, "
            << traj.stats.jacobian_evaluations << " AD Jacobians, wall "
            << traj.stats.wall_seconds << " s for " << simulated << " s simulated (real-time factor "
            << simulated / traj.stats.wall_seconds << ")\n";
}

}  // namespace

void register_simulate_command(CLI::App& app) {
  auto args = std::make_shared<SimulateArgs>();
  CLI::App* cmd = app.add_subcommand("simulate", "integrate the nonlinear model in time");
  cmd->add_option("scene", args->scene, "scene file (TOML)")->required()->check(CLI::ExistingFile);
  cmd->add_option("--speed", args->overrides.speed_m_per_s, "speed V in m/s (overrides the scene)");
  cmd->add_option("--t-end", args->overrides.t_end_s, "end time in s (overrides the scene)");
  cmd->add_option("--csv", args->csv, "CSV output file (default OUT/<scene>_<V>mps.csv)");
  cmd->add_option("--out", args->out_dir, "output directory")->capture_default_str();
  cmd->add_flag("!--no-plots", args->plots, "do not run gnuplot");
  cmd->callback([args] { run_simulate(*args); });
}

}  // namespace railstab
