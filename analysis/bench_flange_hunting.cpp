// Cost and accuracy of the time domain in flange hunting (issue 22): the
// thesis vehicle on S1002/UIC60 (cases/thesis_vehicle_s1002_tangent.toml)
// at 100 m/s from the scene's initial offsets, hunting on its flanges from
// about 1 s (wheelset1 +-5.1 mm, 5.3 Hz). Per integrator and tolerances:
//   - CPU seconds per simulated second of integrate() (the run alone, not
//     the scene's preparation): median of `repeats` runs; steps, right-hand
//     sides, AD Jacobians, error-test and nonlinear failures (the same in
//     every repeat: the runs are deterministic);
//   - the error against a reference run (CVODE BDF at rtol 1e-8, atol 1e-11,
//     itself within 4e-8 m of CVODE Adams at 1e-9/1e-12): the largest
//     deviation over the 0.01 s outputs of any body position or angle
//     (wheelset spin excluded; work_precision.hpp) and of any wheel load Q.
// CPU time (CLOCK_PROCESS_CPUTIME_ID). Run from the repository root:
//   build/bench_flange_hunting [repeats=3] [t_end_s=9] [scene=cases/thesis_vehicle_s1002_tangent.toml]
//                              [speed_m_per_s=100]
// (t_end <= 9.5 s: at 9.97 s wheelset1 climbs to the contact table's edge.)
// Another scene measures another vehicle's flange hunting, e.g.
// cases/thesis_bogie_s1002_tangent.toml at 45 m/s (its initial offsets start it).
#include "cpu_timing.hpp"
#include <railstab/integrate/integrator.hpp>
#include <railstab/integrate/work_precision.hpp>
#include <railstab/model/wheel_forces.hpp>
#include <railstab/setup/prepare_scene.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace railstab;

namespace {

struct Config {
  const char* label;
  IntegratorKind kind;
  double rtol, atol;
};

struct Figures {
  double cpu_per_simulated_s = 0.0;
  IntegrationStats stats;
  Trajectory trajectory;
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

IntegrationOptions options(const PreparedScene& s, const Config& c, double t_end_s) {
  IntegrationOptions o = integration_options_for(s.spec.simulation);
  o.kind = c.kind;
  o.order = 0;
  o.relative_tolerance = c.rtol;
  o.absolute_tolerance = c.atol;
  o.t_end_s = t_end_s;
  return o;
}

Figures run(const PreparedScene& s, const Eigen::VectorXd& x0, const IntegrationOptions& o,
            int repeats) {
  Figures f;
  std::vector<double> cpu;
  for (int r = 0; r < repeats; ++r) {
    const double start = bench::cpu_seconds();
    f.trajectory = integrate(s.model, s.speed_m_per_s, x0, o);
    cpu.push_back((bench::cpu_seconds() - start) / (f.trajectory.times_s.back() - o.t_start_s));
  }
  f.cpu_per_simulated_s = median(cpu);
  f.stats = f.trajectory.stats;
  return f;
}

// Largest |Q - Q_ref| over the wheels and the output times both runs have.
double wheel_load_error(const PreparedScene& s, const Trajectory& run, const Trajectory& ref) {
  double worst = 0.0;
  size_t j = 0;
  for (size_t i = 0; i < run.times_s.size(); ++i) {
    while (j < ref.times_s.size() && ref.times_s[j] < run.times_s[i] - 1e-9) ++j;
    if (j == ref.times_s.size() || std::abs(ref.times_s[j] - run.times_s[i]) > 1e-9) continue;
    const auto a = wheel_forces(s.model, s.speed_m_per_s, run.times_s[i], run.states[i]);
    const auto b = wheel_forces(s.model, s.speed_m_per_s, ref.times_s[j], ref.states[j]);
    // wheel_forces lists the loaded wheels only: match by wheel.
    for (const WheelForces& w : a) {
      double q_ref = 0.0;
      for (const WheelForces& v : b)
        if (v.body == w.body && v.side == w.side) q_ref = v.Q_N;
      worst = std::max(worst, std::abs(w.Q_N - q_ref));
    }
    for (const WheelForces& v : b) {
      bool found = false;
      for (const WheelForces& w : a) found = found || (v.body == w.body && v.side == w.side);
      if (!found) worst = std::max(worst, std::abs(v.Q_N));
    }
  }
  return worst;
}

}  // namespace

int main(int argc, char** argv) {
  const int repeats = argc > 1 ? std::max(1, std::atoi(argv[1])) : 3;
  const double t_end_s = argc > 2 ? std::atof(argv[2]) : 9.0;
  const std::string scene = argc > 3 ? argv[3] : "cases/thesis_vehicle_s1002_tangent.toml";
  SceneOverrides overrides;
  overrides.speed_m_per_s = argc > 4 ? std::atof(argv[4]) : 100.0;
  const PreparedScene s = prepare_scene(load_scene_with_overrides(scene, overrides));
  const Eigen::VectorXd x0 = perturbed_initial_state(s);
  const SimulationSpec& sim = s.spec.simulation;
  std::printf("%s, %g m/s, %.2f s from the scene's offsets, %d repeats (CPU time, medians); "
              "scene's integrator: %s rtol %g atol %g\n",
              scene.c_str(), s.speed_m_per_s, t_end_s, repeats, integrator_name(sim.integrator).c_str(),
              sim.relative_tolerance, sim.absolute_tolerance);

  const Config reference{"reference", IntegratorKind::cvode_bdf, 1e-8, 1e-11};
  const Figures ref = run(s, x0, options(s, reference, t_end_s), 1);
  std::printf("reference cvode_bdf rtol 1e-8 atol 1e-11: %.3f CPU s per simulated s, %ld steps\n",
              ref.cpu_per_simulated_s, ref.stats.steps);

  const std::vector<Config> configs = {
      {"arkode_dirk 1e-3/1e-6 (the knife-edge default)", IntegratorKind::arkode_dirk, 1e-3, 1e-6},
      {"cvode_adams 1e-4/1e-8", IntegratorKind::cvode_adams, 1e-4, 1e-8},
      {"cvode_adams 1e-3/1e-6", IntegratorKind::cvode_adams, 1e-3, 1e-6},
      {"cvode_bdf 1e-3/1e-6", IntegratorKind::cvode_bdf, 1e-3, 1e-6},
      {"cvode_bdf 1e-4/1e-8", IntegratorKind::cvode_bdf, 1e-4, 1e-8},
      {"arkode_erk 1e-3/1e-6", IntegratorKind::arkode_erk, 1e-3, 1e-6},
  };
  std::printf("\n| integrator rtol/atol | CPU s per simulated s | real-time factor | steps | rhs | "
              "AD Jacobians | error-test failures | nonlinear failures | position error (m) | "
              "wheel-load error (kN) |\n|---|---|---|---|---|---|---|---|---|---|\n");
  for (const Config& c : configs) {
    const Figures f = run(s, x0, options(s, c, t_end_s), repeats);
    const double position = trajectory_position_error(s.model, f.trajectory, ref.trajectory);
    const double load = wheel_load_error(s, f.trajectory, ref.trajectory);
    std::printf("| %s | %.3f | %.1f | %ld | %ld | %ld | %ld | %ld | %.2e | %.2f |\n", c.label,
                f.cpu_per_simulated_s, 1.0 / f.cpu_per_simulated_s, f.stats.steps,
                f.stats.rhs_evaluations, f.stats.jacobian_evaluations, f.stats.error_test_failures,
                f.stats.nonlinear_failures, position, 1e-3 * load);
    std::fflush(stdout);
  }
  return 0;
}
