// Issue 11 at scale: trains of N thesis vehicles (cases/thesis_train_4.toml
// with cars = N, N = 1, 2, 4, 8, 16), measured in one run. For each N:
//  - states (and linear states after the cyclic spin angles);
//  - the coloured AD Jacobian (sparse result), colours and AD passes;
//  - the steady state at 100 m/s from the nominal state at that speed
//    (solve_equilibrium, coloured Newton);
//  - one eigen-solve near the hunting band at 100 m/s: the sparse band
//    solver (eigen/band_eigen.hpp: every mode with Re in [-2, 2] 1/s up to
//    20 Hz, the default box), the 12 eigenpairs nearest the least stable
//    oscillatory one (eigen_sparse_nearest: the tracked bisection's solve, a
//    fixed number of modes) and, up to N = 8 (and N = 16 once), the dense one;
//  - a 12-speed critical-speed search (grid 60..115 m/s, step 5, no
//    bisection: 12 evaluations), automatic solver (dense below 300 states,
//    sparse from there), and the same forced dense up to N = 4;
//  - 1 s simulated (the scene's integrator: ARKODE SDIRK, rtol 1e-3) from the
//    steady state with the 1 mm disturbance on car 1, CPU against 1 s.
// CPU time of this process (clock_gettime(CLOCK_PROCESS_CPUTIME_ID)); calls
// under 2 s are repeated (5 batches of >= 0.2 s, median of the batch means),
// longer ones run once (stated). The growth exponent is the least-squares
// slope of log(CPU) against log(states) over N = 1..16.
//   build/bench_scaling [cases-dir]            the table
//   build/bench_scaling --memory N [cases-dir] peak memory (getrusage maxrss)
//                                              of one full default-range search
//                                              (CLI defaults: 5..150 m/s, grid
//                                              2.5 m/s, tolerance 0.01) for N cars
//   build/bench_scaling --profile N [cases-dir] stages of one evaluation of
//                                              N cars at 100 m/s (ARPACK restarts per
//                                              shift), one 12-speed search, a bisection
//                                              105..115 m/s with and without tracking
//   build/bench_scaling --band N [cases-dir]    only the band eigen-solve of N cars at
//                                              100 m/s, per shift, and the dense
//                                              eigenvalues in the box for comparison
#include "cpu_timing.hpp"
#include <railstab/eigen/band_eigen.hpp>
#include <railstab/eigen/eigen_analysis.hpp>
#include <railstab/equilibrium/equilibrium.hpp>
#include <railstab/integrate/integrator.hpp>
#include <railstab/io/regular_file.hpp>
#include <railstab/scene_reading/load_scene.hpp>
#include <railstab/linear/jacobian.hpp>
#include <railstab/linear/linearization.hpp>
#include <railstab/setup/prepare_scene.hpp>
#include <railstab/stability/speed_analysis.hpp>

#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <functional>
#include <complex>
#include <numbers>
#include <regex>
#include <string>
#include <vector>

using namespace railstab;

namespace {

using bench::cpu_seconds;

// CPU seconds per call: a first call; if it took under 2 s, 5 batches of at
// least 0.2 s each and the median of the batch means; else the first call.
struct Timing {
  double seconds;
  bool repeated;
};
Timing time_call(const std::function<void()>& call) {
  const double t0 = cpu_seconds();
  call();
  const double first = cpu_seconds() - t0;
  if (first > 2.0) return {first, false};
  return {bench::median_of_batches(call), true};
}

// The train of cases/thesis_train_4.toml with `cars` cars, its reference
// point far enough along the tangent for the whole train.
SceneSpec train_scene(const std::string& cases_dir, int cars) {
  std::string text = read_regular_file(cases_dir + "/thesis_train_4.toml");
  text = std::regex_replace(text, std::regex("\ncars = 4\n"), "\ncars = " + std::to_string(cars) + "\n");
  const double reference = std::max(200.0, 26.0 * cars + 80.0);
  text = std::regex_replace(text, std::regex("reference_arc_length_m = 200.0"),
                            "reference_arc_length_m = " + std::to_string(reference));
  return load_scene_text(text, "thesis_train_" + std::to_string(cars));
}

CriticalSpeedOptions twelve_speeds(EigenSolverKind solver) {
  CriticalSpeedOptions o;
  o.from_m_per_s = 60.0;
  o.to_m_per_s = 115.0;
  o.grid_step_m_per_s = 5.0;
  o.tolerance_m_per_s = 5.0;  // the grid only: 12 evaluations
  o.stability.solver = solver;
  return o;
}

double slope(const std::vector<double>& x, const std::vector<double>& y) {
  const int n = int(x.size());
  double mx = 0, my = 0;
  for (int i = 0; i < n; ++i) mx += std::log(x[i]) / n, my += std::log(y[i]) / n;
  double sxy = 0, sxx = 0;
  for (int i = 0; i < n; ++i) {
    sxy += (std::log(x[i]) - mx) * (std::log(y[i]) - my);
    sxx += (std::log(x[i]) - mx) * (std::log(x[i]) - mx);
  }
  return sxy / sxx;
}

int memory_run(const std::string& cases_dir, int cars) {
  const PreparedScene s = prepare_scene(train_scene(cases_dir, cars));
  CriticalSpeedOptions o;  // CLI defaults
  o.from_m_per_s = 5.0;
  o.to_m_per_s = 150.0;
  o.grid_step_m_per_s = 2.5;
  o.tolerance_m_per_s = 0.01;
  const double t0 = cpu_seconds();
  const CriticalSpeedResult r = find_critical_speed(s.model, s.equilibrium.state, s.speed_m_per_s, o);
  const double cpu = cpu_seconds() - t0;
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  std::printf("N = %d (%d states): full default-range search (5..150 m/s, grid 2.5, tol 0.01): "
              "%d evaluations, %.2f s CPU, critical speed %s %.4f m/s; peak memory (maxrss) "
              "%.1f MB\n",
              cars, s.model.state_size(), r.evaluations, cpu,
              r.critical_speed_found ? "" : "(not found)", r.critical_speed_m_per_s,
              double(usage.ru_maxrss) / 1024.0);
  return 0;
}

// Where one evaluation of the N-car train at 100 m/s goes, stage by stage
// (CPU seconds, each stage once after a warm-up evaluation), and one
// 12-speed search.
int profile_run(const std::string& cases_dir, int cars) {
  const PreparedScene s = prepare_scene(train_scene(cases_dir, cars));
  const Model& model = s.model;
  const double V = 100.0;
  SpeedStability sweep(model, s.equilibrium.state, s.speed_m_per_s);
  const StabilityPoint warm = sweep.at(V - 5.0);
  const RhsJacobianPlan plan = plan_rhs_jacobian(model);
  const RhsJacobianPlan eq_plan = equilibrium_jacobian_plan(model);
  EquilibriumOptions eq_opt;
  eq_opt.jacobian_plan = &eq_plan;
  double t0 = cpu_seconds();
  const EquilibriumResult eq = solve_equilibrium(model, V, warm.equilibrium.state, eq_opt);
  const double eq_s = cpu_seconds() - t0;
  LinearizationOptions lo;
  lo.jacobian_plan = &plan;
  lo.sparse = true;
  t0 = cpu_seconds();
  const LinearModel lin = linearize(model, V, eq.state, lo);
  const double lin_s = cpu_seconds() - t0;
  t0 = cpu_seconds();
  const BandEigenResult band = eigen_sparse_band(lin.A_sparse, BandCoverOptions{});
  const double eig_s = cpu_seconds() - t0;
  t0 = cpu_seconds();
  const std::vector<ModeReport> modes = describe_modes(model, lin, band.pairs, V);
  const double describe_s = cpu_seconds() - t0;
  t0 = cpu_seconds();
  const StabilityPoint whole = sweep.at(V);
  const double at_s = cpu_seconds() - t0;
  std::printf("N = %d (%d states, %d linear, A: %ld non-zeros): equilibrium from 95 m/s %.4f s "
              "(%d Newton iterations), linearisation %.4f s, band eigen-solve %.4f s (%zu shifts, "
              "%zu modes, diagonal blocks %d), describe_modes %.4f s; SpeedStability::at %.4f s\n",
              cars, model.state_size(), lin.states(), long(lin.A_sparse.nonZeros()), eq_s,
              eq.iterations, lin_s, eig_s, band.discs.size(), band.pairs.size(), band.blocks,
              describe_s, at_s);
  for (const ShiftDisc& d : band.discs)
    std::printf("  block %d shift %+.3f%+.3fi radius %.3f k %d: %d restarts, %d OP applications\n",
                d.block, d.shift.real(), d.shift.imag(), d.radius, d.eigenvalues, d.restarts,
                d.operator_applications);
  t0 = cpu_seconds();
  const CriticalSpeedResult r = find_critical_speed(model, s.equilibrium.state, s.speed_m_per_s,
                                                    twelve_speeds(EigenSolverKind::automatic));
  std::printf("12-speed search %.3f s CPU (%d evaluations)\n", cpu_seconds() - t0, r.evaluations);
  // A bisection (105..115 m/s, grid 5, tolerance 0.01) with and without
  // tracking the crossing mode.
  for (bool track : {false, true}) {
    CriticalSpeedOptions o = twelve_speeds(EigenSolverKind::automatic);
    o.from_m_per_s = 105.0;
    o.tolerance_m_per_s = 0.01;
    o.track_in_bisection = track;
    t0 = cpu_seconds();
    const CriticalSpeedResult b = find_critical_speed(model, s.equilibrium.state, s.speed_m_per_s, o);
    std::printf("bisection 105..115 m/s, tracking %s: %.3f s CPU, %d evaluations, critical speed "
                "%.6f m/s\n",
                track ? "on" : "off", cpu_seconds() - t0, b.evaluations, b.critical_speed_m_per_s);
  }
  return 0;
}

// The band solve alone at 100 m/s (CPU of 3 solves, median), per-shift
// work, and every dense eigenvalue in the box matched by a band one (1e-8
// relative) and vice versa.
int band_run(const std::string& cases_dir, int cars) {
  const PreparedScene s = prepare_scene(train_scene(cases_dir, cars));
  const double V = 100.0;
  SpeedStability sweep(s.model, s.equilibrium.state, s.speed_m_per_s);
  const StabilityPoint at_v = sweep.at(V);
  const RhsJacobianPlan plan = plan_rhs_jacobian(s.model);
  LinearizationOptions lo;
  lo.jacobian_plan = &plan;
  lo.sparse = true;
  const LinearModel lin = linearize(s.model, V, at_v.equilibrium.state, lo);
  const BandCoverOptions o;
  std::vector<double> cpu;
  BandEigenResult band;
  for (int run = 0; run < 3; ++run) {
    const double t0 = cpu_seconds();
    band = eigen_sparse_band(lin.A_sparse, o);
    cpu.push_back(cpu_seconds() - t0);
  }
  std::sort(cpu.begin(), cpu.end());
  int ops = 0, restarts = 0;
  for (const ShiftDisc& d : band.discs) {
    std::printf("  shift %+.3f%+.3fi radius %.3f k %d: %d restarts, %d OP applications\n",
                d.shift.real(), d.shift.imag(), d.radius, d.eigenvalues, d.restarts,
                d.operator_applications);
    ops += d.operator_applications;
    restarts += d.restarts;
  }
  std::printf("N = %d (%d linear states): band solve %.3f s CPU (median of 3: %.3f %.3f %.3f), "
              "%zu solves, %zu modes, %d restarts, %d OP applications, covered %d\n",
              cars, lin.states(), cpu[1], cpu[0], cpu[1], cpu[2], band.discs.size(),
              band.pairs.size(), restarts, ops, int(band.covered));
  // Every dense eigenvalue in the box must be in the band result (1e-8
  // relative), and every band value must be a dense eigenvalue.
  const std::vector<EigenPair> dense = eigen_dense(Eigen::MatrixXd(lin.A_sparse));
  const double top = 2.0 * std::numbers::pi * o.max_frequency_hz;
  const auto check_against_dense = [&](const BandEigenResult& result, const char* label) {
    int in_box = 0, missing = 0, extra = 0;
    std::vector<bool> used(result.pairs.size(), false);
    for (const EigenPair& p : dense) {
      const std::complex<double> l = p.value;
      if (!(l.real() >= o.min_real_part_per_s && l.real() <= o.max_real_part_per_s &&
            l.imag() >= -1e-12 * std::max(1.0, std::abs(l)) && l.imag() <= top))
        continue;
      ++in_box;
      int best = -1;
      double best_d = 1e300;
      for (size_t j = 0; j < result.pairs.size(); ++j)
        if (!used[j] && std::abs(result.pairs[j].value - l) < best_d) {
          best_d = std::abs(result.pairs[j].value - l);
          best = int(j);
        }
      if (best < 0 || best_d > 1e-8 * std::max(1.0, std::abs(l))) {
        ++missing;
        std::printf("  missing %+.9f%+.9fi\n", l.real(), l.imag());
      } else {
        used[size_t(best)] = true;
      }
    }
    for (const EigenPair& p : result.pairs) {
      double best_d = 1e300;
      for (const EigenPair& q : dense) best_d = std::min(best_d, std::abs(p.value - q.value));
      if (best_d > 1e-8 * std::max(1.0, std::abs(p.value))) ++extra;
    }
    std::printf("dense: %d eigenvalues in the box, %d missing from the %s band result, %d band values "
                "not dense eigenvalues\n",
                in_box, missing, label, extra);
  };
  check_against_dense(band, "unplanned");
  // As a sweep solves it: planned from the discs of the solve at V - 5 m/s
  // (the 12-speed search's grid step).
  {
    const double V_before = V - 5.0;
    const StabilityPoint at_before = sweep.at(V_before);
    const LinearModel lin_before = linearize(s.model, V_before, at_before.equilibrium.state, lo);
    const std::vector<ShiftDisc> plan = eigen_sparse_band(lin_before.A_sparse, o).discs;
    std::vector<double> planned_cpu;
    BandEigenResult planned;
    for (int run = 0; run < 3; ++run) {
      const double t0 = cpu_seconds();
      planned = eigen_sparse_band(lin.A_sparse, o, plan);
      planned_cpu.push_back(cpu_seconds() - t0);
    }
    std::sort(planned_cpu.begin(), planned_cpu.end());
    int planned_ops = 0, planned_restarts = 0;
    for (const ShiftDisc& d : planned.discs) {
      planned_ops += d.operator_applications;
      planned_restarts += d.restarts;
      std::printf("  planned shift %+.3f%+.3fi radius %.3f k %d: %d restarts, %d OP applications\n",
                  d.shift.real(), d.shift.imag(), d.radius, d.eigenvalues, d.restarts,
                  d.operator_applications);
    }
    int same = 0;
    for (const EigenPair& p : planned.pairs)
      for (const EigenPair& q : band.pairs)
        if (std::abs(p.value - q.value) <= 1e-8 * std::abs(q.value)) {
          ++same;
          break;
        }
    std::printf("planned from the solve at %.0f m/s (%zu discs): band solve %.3f s CPU (median of 3), "
                "%zu solves, %zu modes (%d equal to the unplanned ones to 1e-8), %d restarts, %d OP "
                "applications, covered %d; planned / unplanned CPU %.2f\n",
                V_before, plan.size(), planned_cpu[1], planned.discs.size(), planned.pairs.size(), same,
                planned_restarts, planned_ops, int(planned.covered), planned_cpu[1] / cpu[1]);
    check_against_dense(planned, "planned");
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::string cases_dir = "cases";
  if (argc >= 3 && std::string(argv[1]) == "--profile")
    return profile_run(argc >= 4 ? argv[3] : cases_dir, std::atoi(argv[2]));
  if (argc >= 3 && std::string(argv[1]) == "--band")
    return band_run(argc >= 4 ? argv[3] : cases_dir, std::atoi(argv[2]));
  if (argc >= 3 && std::string(argv[1]) == "--memory")
    return memory_run(argc >= 4 ? argv[3] : cases_dir, std::atoi(argv[2]));
  if (argc >= 2) cases_dir = argv[1];
  const std::vector<int> sizes = {1, 2, 4, 8, 16};
  std::vector<double> states, jac_s, eq_s, sparse_s, nearest_s, search_s, sim_s;
  std::printf("%4s %6s %6s %7s %6s %10s %10s %10s %7s %10s %10s %10s %12s %12s %10s %8s\n", "N",
              "states", "linear", "colours", "passes", "jacobian_s", "equilib_s", "sparse_eig",
              "shifts", "nearest12", "dense_eig", "search12_s", "search_dense", "crit/12grid", "sim1s_cpu",
              "RTF");
  for (int cars : sizes) {
    const PreparedScene s = prepare_scene(train_scene(cases_dir, cars));
    const Model& model = s.model;
    const double V = 100.0;
    const RhsJacobianPlan plan = plan_rhs_jacobian(model);
    SpeedStability sweep(model, s.equilibrium.state, s.speed_m_per_s);
    const StabilityPoint at_v = sweep.at(V);  // the steady state at V
    const Eigen::VectorXd x = at_v.equilibrium.state;
    const Timing jac = time_call([&] { rhs_jacobian_ad_sparse(model, plan, V, 0.0, x); });
    const RhsJacobianPlan eq_plan = equilibrium_jacobian_plan(model);
    EquilibriumOptions eq_opt;
    eq_opt.jacobian_plan = &eq_plan;
    const Eigen::VectorXd nominal = nominal_state(model, V);
    const Timing eq = time_call([&] { solve_equilibrium(model, V, nominal, eq_opt); });
    LinearizationOptions lo;
    lo.jacobian_plan = &plan;
    lo.sparse = true;
    const LinearModel lin = linearize(model, V, x, lo);
    BandCoverOptions band;
    int shifts = 0;
    BandEigenResult covered;
    const Timing sparse = time_call([&] {
      covered = eigen_sparse_band(lin.A_sparse, band);
      shifts = int(covered.discs.size());
    });
    // The tracked bisection's solve: the 12 eigenpairs nearest the least
    // stable oscillatory eigenvalue of the box (a fixed number of modes).
    std::complex<double> hunting{0.0, 2.0 * std::numbers::pi * 4.0};
    for (const EigenPair& p : covered.pairs)  // least stable first
      if (p.value.imag() > 0.0) {
        hunting = p.value;
        break;
      }
    const Timing nearest = time_call([&] { eigen_sparse_nearest(lin.A_sparse, hunting, 12); });
    Timing dense{NAN, false};
    if (cars <= 16) {
      const Eigen::MatrixXd A = Eigen::MatrixXd(lin.A_sparse);
      if (cars <= 8)
        dense = time_call([&] { eigen_dense(A); });
      else {
        const double t0 = cpu_seconds();
        eigen_dense(A);
        dense = {cpu_seconds() - t0, false};
      }
    }
    CriticalSpeedResult r12;
    const Timing search = time_call([&] {
      r12 = find_critical_speed(model, s.equilibrium.state, s.speed_m_per_s,
                                twelve_speeds(EigenSolverKind::automatic));
    });
    Timing search_dense{NAN, false};
    if (cars <= 4)
      search_dense = time_call([&] {
        find_critical_speed(model, s.equilibrium.state, s.speed_m_per_s,
                            twelve_speeds(EigenSolverKind::dense));
      });
    // 1 s simulated from the steady state at V plus the disturbance.
    IntegrationOptions io = integration_options_for(s.spec.simulation);
    io.t_end_s = 1.0;
    io.output_interval_s = 0.01;
    io.cpu_time_budget_s = 300.0;
    Eigen::VectorXd x0 = x;
    const PreparedScene at_speed{s.spec, s.model, V, at_v.equilibrium};
    x0 = perturbed_initial_state(at_speed);
    double sim = NAN;
    {
      const double t0 = cpu_seconds();
      try {
        integrate(model, V, x0, io);
        sim = cpu_seconds() - t0;
      } catch (const std::exception& e) {
        std::printf("  (simulation: %s)\n", e.what());
      }
    }
    std::printf("%4d %6d %6d %7d %6d %10.5f %10.5f %10.5f %7d %10.5f %10.5f %10.4f %12.4f %12s %10.3f %8.3f\n",
                cars, model.state_size(), lin.states(), plan.colouring.colours, plan.passes(),
                jac.seconds, eq.seconds, sparse.seconds, shifts, nearest.seconds, dense.seconds,
                search.seconds,
                search_dense.seconds,
                (r12.critical_speed_found ? std::to_string(r12.critical_speed_m_per_s).substr(0, 7)
                                          : std::string(r12.stable_in_range ? "stable" : "none"))
                    .c_str(),
                sim, std::isfinite(sim) ? 1.0 / sim : NAN);
    std::fflush(stdout);
    states.push_back(model.state_size());
    jac_s.push_back(jac.seconds);
    eq_s.push_back(eq.seconds);
    sparse_s.push_back(sparse.seconds);
    nearest_s.push_back(nearest.seconds);
    search_s.push_back(search.seconds);
    sim_s.push_back(std::isfinite(sim) ? sim : 1e9);
  }
  std::printf("growth exponents (slope of log CPU on log states, N = 1..16): jacobian %.2f, "
              "equilibrium %.2f, sparse eigen-solve (covering) %.2f, 12 nearest the hunting mode "
              "%.2f, 12-speed search %.2f, 1 s simulated %.2f\n",
              slope(states, jac_s), slope(states, eq_s), slope(states, sparse_s),
              slope(states, nearest_s), slope(states, search_s), slope(states, sim_s));
  std::printf("(search: automatic solver, dense below %d states; a run over 2 s CPU is timed "
              "once, shorter ones as the median of 5 batches)\n",
              kSparseFromStates);
  return 0;
}
