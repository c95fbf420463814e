// Benchmark of the integrators on the thesis bogie and vehicle (tangent,
// 20 m/s, 20 s, the cases' 1 mm initial offset): for each integrator, the
// loosest tolerance of the ladder 1e-3..1e-8 (atol = rtol * 1e-3) whose
// error reaches 1e-6 (max position error over the 0.01 s outputs, m and rad,
// wheelset spin excluded; see integrate/work_precision.hpp), with its CPU
// time (this process's CPU clock: the machine is shared, so wall time is
// printed for information only) and real-time factor (20 s / CPU time).
//
// Reference: CVODE Adams at rtol 1e-10, checked against CVODE BDF at rtol
// 1e-9 (the difference is printed). Adams is the cheapest accurate method
// here (work-precision study), which keeps the whole run near a minute.
//   build/bench_integrators [cases-dir]
#include "cpu_timing.hpp"
#include <railstab/setup/prepare_scene.hpp>
#include <railstab/integrate/work_precision.hpp>

#include <cmath>
#include <cstdio>
#include <string>

using namespace railstab;

namespace {

constexpr double kTargetError = 1e-6;

void bench_scene(const std::string& path) {
  const PreparedScene scene = prepare_scene(path, {});
  const Model& model = scene.model;
  const Eigen::VectorXd x0 = perturbed_initial_state(scene);
  WorkPrecisionSettings s;
  s.t_end_s = 20.0;
  s.output_interval_s = 0.01;
  s.reference_kind = IntegratorKind::cvode_adams;
  s.reference_rtol = 1e-10;
  s.reference_check_kind = IntegratorKind::cvode_bdf;
  s.reference_check_rtol = 1e-9;
  s.cpu_budget_per_run_s = 8.0;
  const ReferenceSolution ref = compute_reference(model, scene.speed_m_per_s, x0, s);
  std::printf("%s: %d states, %.0f m/s, %.0f s; reference %s rtol %.0e (CPU %.2f s), "
              "differs from %s rtol %.0e by %.2g\n",
              model.name.c_str(), model.state_size(), scene.speed_m_per_s, s.t_end_s,
              integrator_name(ref.kind).c_str(), ref.rtol, ref.cpu_seconds,
              integrator_name(ref.check_kind).c_str(), ref.check_rtol, ref.check_difference);
  std::printf("  %-13s %7s %10s %10s %8s %8s %8s %8s %8s\n", "integrator", "rtol", "error",
              "lateral", "wall s", "CPU s", "steps", "Jacobians", "RTF (CPU)");
  for (const IntegratorVariant& v : s.variants) {
    bool reached = false;
    for (double rtol : s.relative_tolerances) {
      const WorkPrecisionRun r = run_against_reference(model, scene.speed_m_per_s, x0, s, v, rtol, ref);
      if (r.status != "ok") {
        std::printf("  %-13s %7.0e  %s\n", r.label.c_str(), rtol, r.status.c_str());
        break;
      }
      if (r.error > kTargetError) continue;
      std::printf("  %-13s %7.0e %10.2g %10.2g %8.3f %8.3f %8ld %8ld %8.1f\n", r.label.c_str(),
                  rtol, r.error, r.lateral_error, r.wall_seconds, r.stats.cpu_seconds,
                  r.stats.steps, r.stats.jacobian_evaluations, s.t_end_s / r.stats.cpu_seconds);
      reached = true;
      break;
    }
    if (!reached) std::printf("  %-13s did not reach %.0e\n", v.label().c_str(), kTargetError);
  }
  // The scene's own integrator and tolerance: what `railstab simulate` runs.
  const SimulationSpec& sim = scene.spec.simulation;
  const WorkPrecisionRun def = run_against_reference(
      model, scene.speed_m_per_s, x0, s, {sim.integrator, sim.integrator_order}, sim.relative_tolerance, ref);
  std::printf("  scene default: %s rtol %.0e: error %.2g (lateral %.2g), CPU %.3f s (wall %.3f s), "
              "real-time factor %.1f (CPU)\n",
              def.label.c_str(), sim.relative_tolerance, def.error, def.lateral_error,
              def.stats.cpu_seconds, def.wall_seconds, s.t_end_s / def.stats.cpu_seconds);
}

}  // namespace

int main(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : "cases";
  const double start = bench::cpu_seconds();
  for (const char* name : {"thesis_bogie_tangent", "thesis_vehicle_tangent"})
    bench_scene(dir + "/" + name + ".toml");
  std::printf("total %.1f s CPU\n", bench::cpu_seconds() - start);
  return 0;
}
