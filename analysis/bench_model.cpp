// Benchmark of the model's hot path on the thesis vehicle (and bogie):
// one right-hand side, one AD Jacobian, one forward-difference Jacobian,
// and a 20 s time-domain run. Prints timings and ratios.
//   build/bench_model [cases-dir]
#include "cpu_timing.hpp"
#include <railstab/setup/prepare_scene.hpp>
#include <railstab/integrate/integrator.hpp>
#include <railstab/linear/jacobian.hpp>
#include <railstab/linear/linearization.hpp>
#include <railstab/model/equations_of_motion.hpp>
#include <railstab/stability/speed_analysis.hpp>

#include <cstdio>
#include <functional>
#include <string>

using namespace railstab;

namespace {

// CPU seconds per call (analysis/cpu_timing.hpp): a warm-up call, then
// five batches of at least 0.1 s, the median of the batch means.
double time_per_call(const std::function<void()>& f) {
  f();
  return bench::median_of_batches(f, 5, 0.1);
}

// The 20 s run below is timed by the integrator's own statistics (wall
// clock: stats.wall_seconds) and by this process's CPU clock; the
// real-time factor is quoted on CPU time.

void bench_scene(const std::string& path) {
  const PreparedScene scene = prepare_scene(path, {});
  const Model& model = scene.model;
  const Eigen::VectorXd x = perturbed_initial_state(scene);
  Workspace<double> ws(model);
  const double V = scene.speed_m_per_s;
  Eigen::VectorXd xdot;
  const double t_rhs = time_per_call([&] { evaluate_rhs<double>(model, ws, 0.0, V, x, xdot); });
  const double t_rhs_frames = time_per_call([&] { xdot = rhs(model, scene.speed_m_per_s, 0.0, x); });
  const double t_ad = time_per_call([&] { rhs_jacobian_ad(model, scene.speed_m_per_s, 0.0, x); });
  const double t_fd = time_per_call([&] { rhs_jacobian_forward_difference(model, scene.speed_m_per_s, 0.0, x); });
  const double t_cd = time_per_call([&] { rhs_jacobian_central_difference(model, scene.speed_m_per_s, 0.0, x); });
  std::printf("%s: %d bodies, %d states\n", model.name.c_str(), int(model.bodies.size()),
              model.state_size());
  std::printf("  rhs (workspace reused)    %10.2f us\n", t_rhs * 1e6);
  std::printf("  rhs (fresh workspace)     %10.2f us\n", t_rhs_frames * 1e6);
  std::printf("  AD Jacobian               %10.2f us  (%.1f rhs)\n", t_ad * 1e6, t_ad / t_rhs);
  std::printf("  forward-diff Jacobian     %10.2f us  (%.1f rhs)\n", t_fd * 1e6, t_fd / t_rhs);
  std::printf("  5-point central Jacobian  %10.2f us  (%.1f rhs)\n", t_cd * 1e6, t_cd / t_rhs);
  std::printf("  ratio AD / forward diff   %10.2f\n", t_ad / t_fd);

  // Eigen-analysis at the steady state, dense vs ARPACK (16 modes near a
  // lightly damped 3 Hz), and a full critical-speed search.
  const LinearModel lin = linearize(model, scene.speed_m_per_s, scene.equilibrium.state);
  StabilityOptions arpack;
  arpack.solver = EigenSolverKind::arpack;
  const double t_dense = time_per_call([&] { eigen_dense(lin.A); });
  const double t_arpack = time_per_call([&] { solve_eigen(lin.A, arpack); });
  std::printf("  dense eigen (%d states)   %10.2f us\n", int(lin.A.rows()), t_dense * 1e6);
  std::printf("  ARPACK 16 eigenvalues     %10.2f us  (dense/ARPACK %.2f)\n", t_arpack * 1e6,
              t_dense / t_arpack);
  CriticalSpeedOptions cs;
  cs.from_m_per_s = 5.0;
  cs.to_m_per_s = 150.0;
  cs.grid_step_m_per_s = 2.5;
  CriticalSpeedResult r;
  const double t_search = time_per_call([&] { r = find_critical_speed(model, scene.equilibrium.state, scene.speed_m_per_s, cs); });
  std::printf("  critical-speed search     %10.3f s   (%d speeds, V_crit %s%.2f m/s)\n", t_search,
              r.evaluations, r.critical_speed_found ? "" : "none; ",
              r.critical_speed_found ? r.critical_speed_m_per_s : 0.0);

  // The scene's integrator and tolerances (the default users get).
  IntegrationOptions opt = integration_options_for(scene.spec.simulation);
  opt.t_end_s = 20.0;
  opt.output_interval_s = 0.01;
  const double cpu_start = bench::cpu_seconds();
  const Trajectory traj = integrate(model, scene.speed_m_per_s, x, opt);
  const double cpu_run = bench::cpu_seconds() - cpu_start;
  const double simulated = traj.times_s.back();
  std::printf("  20 s run (%s, rtol %.0e): CPU %.3f s (wall %.3f s), real-time factor %.1f (CPU), "
              "%ld steps, %ld rhs, %ld Jacobians%s\n",
              integrator_name(opt.kind).c_str(), opt.relative_tolerance, cpu_run,
              traj.stats.wall_seconds, simulated / cpu_run,
              traj.stats.steps, traj.stats.rhs_evaluations, traj.stats.jacobian_evaluations,
              traj.stopped_early.empty() ? "" : " (stopped early)");
}

}  // namespace

int main(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : "cases";
  for (const char* name : {"thesis_bogie_tangent", "thesis_vehicle_tangent", "thesis_vehicle_curve"})
    bench_scene(dir + "/" + name + ".toml");
  return 0;
}
