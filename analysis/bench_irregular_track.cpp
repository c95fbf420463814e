// Cost of irregular track (issue 25's performance target: under 10 %): the
// thesis vehicle with S1002/UIC60 profile contact at 80 m/s, 1 km of track,
// from the scene's initial offsets, on perfect track, on ERRI B176 low
// track (seed 1, 3-150 m, 1100 m from s = 0) and on the same spectrum at
// amplitude 0 (the irregularities' machinery without their motion: the run
// is the perfect track's step for step), measured in one run:
//   - one right-hand side (median of batches): perfect, amplitude 0;
//   - the whole run (the scene's integrator and tolerances): CPU seconds per
//     simulated second, steps and Jacobians, medians of `repeats` runs;
//   - synthesising the irregularities (building the track).
// CPU time (CLOCK_PROCESS_CPUTIME_ID).
//   build/bench_irregular_track [repeats=3] [cases-dir=cases]   (from the repository root)
#include "cpu_timing.hpp"
#include <railstab/integrate/integrator.hpp>
#include <railstab/model/equations_of_motion.hpp>
#include <railstab/setup/prepare_scene.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace railstab;

namespace {

struct RunFigures {
  double cpu_per_simulated_s = 0.0;
  long steps = 0, jacobians = 0;
  double largest_lateral_m = 0.0;
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

RunFigures run(const PreparedScene& s, int repeats, double distance_m) {
  IntegrationOptions opt = integration_options_for(s.spec.simulation);
  opt.t_end_s = distance_m / s.speed_m_per_s;
  const Eigen::VectorXd x0 = perturbed_initial_state(s);
  std::vector<double> cpu;
  RunFigures f;
  int y = 0;
  for (int i = 0; i < s.model.state_size(); ++i)
    if (s.model.state_name(i) == "wheelset1.y_m") y = i;
  for (int r = 0; r < repeats; ++r) {
    const double start = bench::cpu_seconds();
    const Trajectory traj = integrate(s.model, s.speed_m_per_s, x0, opt);
    cpu.push_back((bench::cpu_seconds() - start) / (traj.times_s.back() - opt.t_start_s));
    f.steps = long(traj.stats.steps);
    f.jacobians = long(traj.stats.jacobian_evaluations);
    f.largest_lateral_m = 0.0;
    for (const Eigen::VectorXd& x : traj.states) f.largest_lateral_m = std::max(f.largest_lateral_m, std::abs(x(y)));
    if (!traj.stopped_early.empty()) std::printf("  (stopped early: %s)\n", traj.stopped_early.c_str());
  }
  f.cpu_per_simulated_s = median(cpu);
  return f;
}

}  // namespace

int main(int argc, char** argv) {
  const int repeats = argc > 1 ? std::max(1, std::atoi(argv[1])) : 3;
  const std::string cases = argc > 2 ? argv[2] : "cases";
  const std::string path = cases + "/thesis_vehicle_s1002_tangent.toml";
  const double V = 80.0, distance_m = 1000.0;
  SceneOverrides o;
  o.speed_m_per_s = V;
  const SceneSpec perfect_spec = load_scene_with_overrides(path, o);
  SceneSpec irregular_spec = perfect_spec;
  IrregularitySpec irr;
  irr.spectrum = IrregularitySpectrum::erri_b176_low;
  irr.length_m = 1100.0;
  irregular_spec.track.irregularities = irr;
  SceneSpec zero_spec = irregular_spec;
  zero_spec.track.irregularities->amplitude_scale = 0.0;
  const PreparedScene perfect = prepare_scene(perfect_spec);
  const double synth_start = bench::cpu_seconds();
  const PreparedScene irregular = prepare_scene(irregular_spec, true);
  const double build_s = bench::cpu_seconds() - synth_start;
  const PreparedScene zero = prepare_scene(zero_spec, true);

  const Eigen::VectorXd x = perfect.equilibrium.state;
  Workspace<double> ws_p(perfect.model), ws_i(zero.model);
  Eigen::VectorXd xdot;
  // A new time per call, so the track frames (and the irregularities) are
  // evaluated every time, as in a run.
  double t_p = 0.0, t_i = 0.0;
  const double rhs_p = bench::median_of_batches([&] {
    t_p += 1e-4;
    evaluate_rhs<double>(perfect.model, ws_p, t_p, V, x, xdot);
  });
  const double rhs_i = bench::median_of_batches([&] {
    t_i += 1e-4;
    evaluate_rhs<double>(zero.model, ws_i, t_i, V, x, xdot);
  });
  std::printf("thesis vehicle, S1002/UIC60, %.0f m/s, %.0f m, %d repeats (CPU time, medians)\n", V, distance_m,
              repeats);
  std::printf("right-hand side at the same state: perfect %.2f us, amplitude 0 %.2f us, ratio %.3f\n", rhs_p * 1e6,
              rhs_i * 1e6, rhs_i / rhs_p);
  std::printf("prepare_scene with the irregularities (synthesis, table, equilibrium): %.2f s CPU\n", build_s);
  const RunFigures a = run(perfect, repeats, distance_m);
  const RunFigures z = run(zero, repeats, distance_m);
  const RunFigures b = run(irregular, repeats, distance_m);
  std::printf("run, perfect track:   %.3f CPU s per simulated s, %ld steps, %ld Jacobians, max |y1| %.2f mm\n",
              a.cpu_per_simulated_s, a.steps, a.jacobians, a.largest_lateral_m * 1e3);
  std::printf("run, amplitude 0:     %.3f CPU s per simulated s, %ld steps, %ld Jacobians, max |y1| %.2f mm\n",
              z.cpu_per_simulated_s, z.steps, z.jacobians, z.largest_lateral_m * 1e3);
  std::printf("run, ERRI B176 low:   %.3f CPU s per simulated s, %ld steps, %ld Jacobians, max |y1| %.2f mm\n",
              b.cpu_per_simulated_s, b.steps, b.jacobians, b.largest_lateral_m * 1e3);
  std::printf("ratio amplitude 0 / perfect: %.3f CPU (the machinery)\n", z.cpu_per_simulated_s / a.cpu_per_simulated_s);
  std::printf("ratio irregular / perfect: %.3f CPU, %.3f steps, %.3f Jacobians\n",
              b.cpu_per_simulated_s / a.cpu_per_simulated_s, double(b.steps) / double(a.steps),
              double(b.jacobians) / double(a.jacobians));
  return 0;
}
