// Where a periodic orbit's cost goes (issue 22, performance): the thesis bogie
// on S1002/UIC60 in flange hunting at 45 m/s. A time-domain run settles on the
// cycle (6 s from a 5 mm displacement, as `bifurcation --cycle-speed`), one
// period from the settled state is then integrated by the shooting's flow
// (flow_sensitivity.hpp) with and without the variational equations and at
// several tolerances: CVODES steps, AD Jacobians, error-test failures and CPU
// time (CLOCK_PROCESS_CPUTIME_ID, median of 3 runs each, all in this one run).
// The variational equations alongside the state (CVODES's sensitivity
// module) and in a second pass (variational_pass.hpp); each monodromy
// matrix against a reference at X rtol 1e-8 (largest entry difference, and
// the 10 largest reference multipliers' distance to the nearest of its own).
//   build/bench_orbit_flow [scene] [speed m/s]
// (default: cases/thesis_bogie_s1002_tangent.toml at 45 m/s)
#include "cpu_timing.hpp"
#include <railstab/nonlinear/flow_sensitivity.hpp>
#include <railstab/nonlinear/model_orbits.hpp>
#include <railstab/nonlinear/periodic_orbit.hpp>
#include <railstab/setup/prepare_scene.hpp>
#include <railstab/equilibrium/speed_continuation.hpp>

#include <algorithm>
#include <complex>
#include <cstdio>
#include <string>
#include <vector>

using namespace railstab;

int main(int argc, char** argv) {
  const std::string scene_path = argc > 1 ? argv[1] : "cases/thesis_bogie_s1002_tangent.toml";
  const double V = argc > 2 ? std::stod(argv[2]) : 45.0;
  const PreparedScene scene = prepare_scene(scene_path, {});
  const Model& model = scene.model;
  std::vector<int> reduced;
  const FlowSystem system = model_flow_system(model, 0.0, &reduced);
  const OrbitCoordinates coords = wheelset_orbit_coordinates(model, reduced);
  const EquilibriumResult eq =
      continue_equilibrium_in_speed(model, scene.speed_m_per_s, scene.equilibrium.state, V, {});
  const double settle0 = bench::cpu_seconds();
  const OrbitGuess guess = settled_cycle_guess(model, V, eq.state, reduced, coords, 0.005, 6.0);
  const double settle_s = bench::cpu_seconds() - settle0;
  std::printf("%s, %.1f m/s, %d states: settling run 6 s %.2f s CPU; "
              "period %.4f s, wheelset1 excursion %.2f mm\n",
              scene_path.c_str(), V, system.size, settle_s, guess.period_s, 1e3 * guess.start(coords.amplitude_state));
  struct Variant {
    const char* name;
    FlowOptions options;
  };
  std::vector<Variant> variants;
  using Variational = FlowOptions::Variational;
  auto add = [&](const char* name, double rtol, double atol, bool sens, bool errcon, double srtol,
                 Variational how = Variational::alongside) {
    FlowOptions o;
    o.variational = how;
    o.relative_tolerance = rtol;
    o.absolute_tolerance = atol;
    o.sensitivities = sens;
    o.sensitivity_error_control = errcon;
    o.sensitivity_relative_tolerance = srtol;
    o.samples = 200;
    variants.push_back({name, o});
  };
  add("state only, rtol 1e-8 (the shooting's)", 1e-8, 1e-11, false, true, 1e-5);
  add("state only, rtol 1e-6", 1e-6, 1e-9, false, true, 1e-5);
  add("alongside, rtol 1e-8, X rtol 1e-5 (the default)", 1e-8, 1e-11, true, true, 1e-5);
  add("alongside, rtol 1e-8, X rtol 1e-3", 1e-8, 1e-11, true, true, 1e-3);
  add("alongside, rtol 1e-7, X rtol 1e-4", 1e-7, 1e-10, true, true, 1e-4);
  add("alongside, rtol 1e-6, X rtol 1e-4", 1e-6, 1e-9, true, true, 1e-4);
  add("alongside, rtol 1e-8, X out of the error test", 1e-8, 1e-11, true, false, 1e-5);
  add("second pass, rtol 1e-8, X rtol 1e-5 (profile contact)", 1e-8, 1e-11, true, true, 1e-5,
      Variational::second_pass);
  add("second pass, rtol 1e-8, X rtol 1e-6", 1e-8, 1e-11, true, true, 1e-6,
      Variational::second_pass);
  add("second pass, rtol 1e-8, X rtol 1e-4", 1e-8, 1e-11, true, true, 1e-4,
      Variational::second_pass);
  // The reference monodromy: alongside, X at rtol 1e-8 (once).
  FlowOptions tight;
  tight.variational = FlowOptions::Variational::alongside;
  tight.sensitivity_relative_tolerance = 1e-8;
  tight.sensitivity_absolute_tolerance = 1e-11;
  const FlowResult truth = integrate_flow(system, guess.start, V, guess.period_s, tight);
  const Eigen::MatrixXd reference = truth.state_sensitivity;
  const Eigen::VectorXcd mu_ref = Eigen::EigenSolver<Eigen::MatrixXd>(reference).eigenvalues();
  std::vector<std::complex<double>> largest_ref(mu_ref.data(), mu_ref.data() + mu_ref.size());
  std::sort(largest_ref.begin(), largest_ref.end(),
            [](auto a, auto b) { return std::abs(a) > std::abs(b); });
  largest_ref.resize(std::min<size_t>(10, largest_ref.size()));
  std::vector<double> moduli;
  for (Eigen::Index i = 0; i < mu_ref.size(); ++i) moduli.push_back(std::abs(mu_ref(i)));
  std::sort(moduli.rbegin(), moduli.rend());
  std::printf("reference monodromy (X rtol 1e-8): %ld steps, %.2f s CPU, max |M| %.3g; |mu| sorted:",
              truth.steps, truth.cpu_seconds, reference.cwiseAbs().maxCoeff());
  for (size_t i = 0; i < moduli.size() && i < 40; ++i) std::printf(" %.3g", moduli[i]);
  std::printf("\n");
  for (double level : {0.5, 0.2, 0.1, 0.05, 0.01}) {
    int count = 0;
    for (double m : moduli) count += m > level ? 1 : 0;
    std::printf("  multipliers with |mu| > %.2f: %d\n", level, count);
  }
  std::printf("%-52s %8s %8s %8s %9s %12s %12s %12s\n", "flow over one period", "steps", "Jacs",
              "errfail", "CPU s", "|end-start|", "|M-M_ref|", "max|dmu|");
  for (const Variant& v : variants) {
    FlowResult f;
    // Median of 3 single calls (a flow lasts 0.05-5 s).
    const double cpu = bench::median_of_batches(
        [&] { f = integrate_flow(system, guess.start, V, guess.period_s, v.options); }, 3, 0.0);
    double dM = 0.0, dmu = 0.0;
    if (f.state_sensitivity.size() > 0) {
      dM = (f.state_sensitivity - reference).cwiseAbs().maxCoeff();
      // The largest multipliers' error: each of the 10 largest reference
      // multipliers against the nearest of this flow's.
      const Eigen::VectorXcd mu = Eigen::EigenSolver<Eigen::MatrixXd>(f.state_sensitivity).eigenvalues();
      for (const std::complex<double>& r : largest_ref) {
        double nearest = 1e300;
        for (Eigen::Index j = 0; j < mu.size(); ++j) nearest = std::min(nearest, std::abs(mu(j) - r));
        dmu = std::max(dmu, nearest);
      }
    }
    std::printf("%-52s %8ld %8ld %8ld %9.3f %12.3e %12.3e %12.3e\n", v.name, f.steps,
                f.jacobian_evaluations, f.error_test_failures, cpu,
                (f.end_state - guess.start).cwiseAbs().maxCoeff(), dM, dmu);
  }
  return 0;
}
