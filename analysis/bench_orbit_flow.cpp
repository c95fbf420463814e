// Where a periodic orbit's cost goes (issue 22, performance): the thesis bogie
// on S1002/UIC60 in flange hunting at 45 m/s. A time-domain run settles on the
// cycle (6 s from a 5 mm displacement, as `bifurcation --cycle-speed`), one
// period from the settled state is then integrated by the shooting's flow
// (flow_sensitivity.hpp) with and without the variational equations and at
// several tolerances: CVODES steps, AD Jacobians, error-test failures and CPU
// time (CLOCK_PROCESS_CPUTIME_ID, median of 3 runs each, all in this one run).
//   build/bench_orbit_flow [cases-dir]
#include "cpu_timing.hpp"
#include <railstab/nonlinear/flow_sensitivity.hpp>
#include <railstab/nonlinear/model_orbits.hpp>
#include <railstab/nonlinear/periodic_orbit.hpp>
#include <railstab/setup/prepare_scene.hpp>
#include <railstab/equilibrium/speed_continuation.hpp>

#include <cstdio>
#include <string>
#include <vector>

using namespace railstab;

int main(int argc, char** argv) {
  const std::string cases = argc > 1 ? argv[1] : "cases";
  const double V = 45.0;
  const PreparedScene scene = prepare_scene(cases + "/thesis_bogie_s1002_tangent.toml", {});
  const Model& model = scene.model;
  std::vector<int> reduced;
  const FlowSystem system = model_flow_system(model, 0.0, &reduced);
  const OrbitCoordinates coords = wheelset_orbit_coordinates(model, reduced);
  const EquilibriumResult eq =
      continue_equilibrium_in_speed(model, scene.speed_m_per_s, scene.equilibrium.state, V, {});
  const double settle0 = bench::cpu_seconds();
  const OrbitGuess guess = settled_cycle_guess(model, V, eq.state, reduced, coords, 0.005, 6.0);
  const double settle_s = bench::cpu_seconds() - settle0;
  std::printf("thesis bogie, S1002/UIC60, %.0f m/s, %d states: settling run 6 s %.2f s CPU; "
              "period %.4f s, wheelset1 excursion %.2f mm\n",
              V, system.size, settle_s, guess.period_s, 1e3 * guess.start(coords.amplitude_state));
  struct Variant {
    const char* name;
    FlowOptions options;
  };
  std::vector<Variant> variants;
  auto add = [&](const char* name, double rtol, double atol, bool sens, bool errcon, double srtol) {
    FlowOptions o;
    o.relative_tolerance = rtol;
    o.absolute_tolerance = atol;
    o.sensitivities = sens;
    o.sensitivity_error_control = errcon;
    o.sensitivity_relative_tolerance = srtol;
    o.samples = 200;
    variants.push_back({name, o});
  };
  add("state only, rtol 1e-8 (shooting's default)", 1e-8, 1e-11, false, true, 1e-5);
  add("state only, rtol 1e-6", 1e-6, 1e-9, false, true, 1e-5);
  add("with X and s_V, rtol 1e-8, X rtol 1e-5 (default)", 1e-8, 1e-11, true, true, 1e-5);
  add("with X and s_V, rtol 1e-8, X rtol 1e-3", 1e-8, 1e-11, true, true, 1e-3);
  add("with X and s_V, rtol 1e-7, X rtol 1e-4", 1e-7, 1e-10, true, true, 1e-4);
  add("with X and s_V, rtol 1e-6, X rtol 1e-4", 1e-6, 1e-9, true, true, 1e-4);
  add("with X and s_V, rtol 1e-8, X out of the error test", 1e-8, 1e-11, true, false, 1e-5);
  std::printf("%-52s %8s %8s %8s %9s %12s\n", "flow over one period", "steps", "Jacs", "errfail",
              "CPU s", "|end-start|");
  for (const Variant& v : variants) {
    FlowResult f;
    // Median of 3 single calls (a flow lasts 0.05-5 s).
    const double cpu = bench::median_of_batches(
        [&] { f = integrate_flow(system, guess.start, V, guess.period_s, v.options); }, 3, 0.0);
    std::printf("%-52s %8ld %8ld %8ld %9.3f %12.3e\n", v.name, f.steps, f.jacobian_evaluations,
                f.error_test_failures, cpu, (f.end_state - guess.start).cwiseAbs().maxCoeff());
  }
  return 0;
}
