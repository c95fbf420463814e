// Dense and ARPACK eigen-solvers agree on the thesis vehicle; the critical
// speeds of the thesis scenes are consistent with the time domain.
#include <railstab/setup/prepare_scene.hpp>
#include <railstab/stability/speed_analysis.hpp>

#include <gtest/gtest.h>
#include "support/test_files.hpp"

using namespace railstab;

namespace {
using railstab::test::case_path;
}  // namespace

// ARPACK (shift-invert near the hunting band) finds the same eigenvalues as
// the dense solver: each ARPACK eigenvalue matches a dense one to 1e-8
// relative to |lambda| (both are backward stable; residuals ~1e-15).
TEST(EigenOnVehicle, ArpackAgreesWithDense) {
  const PreparedScene s = prepare_scene(case_path("thesis_vehicle_tangent"), SceneOverrides::at_speed(100.0));
  StabilityOptions dense_opt, arpack_opt;
  arpack_opt.solver = EigenSolverKind::arpack;
  arpack_opt.arpack_shift = {0.0, 2.0 * M_PI * 4.0};
  const StabilityPoint dense = SpeedStability(s.model, s.equilibrium.state, s.speed_m_per_s, dense_opt).at(100.0);
  const StabilityPoint arpack = SpeedStability(s.model, s.equilibrium.state, s.speed_m_per_s, arpack_opt).at(100.0);
  ASSERT_GE(arpack.modes.size(), 10u);
  for (const ModeReport& a : arpack.modes) {
    double best = 1e300;
    for (const ModeReport& d : dense.modes) best = std::min(best, std::abs(a.eigenvalue - d.eigenvalue));
    EXPECT_LT(best, 1e-8 * std::max(1.0, std::abs(a.eigenvalue))) << a.eigenvalue;
    EXPECT_LT(a.residual, 1e-10);
  }
  // The hunting mode near 4 Hz is among them and is the least stable.
  ASSERT_GE(arpack.least_stable, 0);
  EXPECT_NEAR(arpack.modes[arpack.least_stable].eigenvalue.real(),
              dense.modes[dense.least_stable].eigenvalue.real(), 1e-8);
}

// The linear critical speed of the thesis bogie lies between the time-domain
// runs of thesis 5.5.1.1 (decays at 20 m/s, grows at 40 m/s), and its
// hunting wavelength is the rigid-bogie kinematic one to within 10 %
// (Wickens: L_bogie = L_wheelset sqrt(1 + (a/e0)^2), a = half wheelbase).
TEST(EigenOnVehicle, ThesisBogieCriticalSpeedBetweenTimeDomainRuns) {
  const PreparedScene s = prepare_scene(case_path("thesis_bogie_tangent"), {});
  CriticalSpeedOptions opt;
  opt.from_m_per_s = 5.0;
  opt.to_m_per_s = 60.0;
  opt.grid_step_m_per_s = 5.0;
  const CriticalSpeedResult r = find_critical_speed(s.model, s.equilibrium.state, s.speed_m_per_s, opt);
  ASSERT_TRUE(r.critical_speed_found);
  EXPECT_GT(r.critical_speed_m_per_s, 20.0);
  EXPECT_LT(r.critical_speed_m_per_s, 40.0);
  EXPECT_LT(r.at_critical.speed_m_per_s, r.critical_speed_m_per_s + 1e-9);
  EXPECT_GT(r.at_critical.speed_m_per_s, r.critical_speed_m_per_s - 0.01);
  const double f = r.at_critical.modes[r.at_critical.least_stable].frequency_hz;
  const double t = std::tan(0.1);
  const double lambda_eff = t * 0.75 / (0.75 - 0.45 * t);
  const double wheelset_L = 2.0 * M_PI * std::sqrt(0.45 * 0.75 / lambda_eff);
  const double bogie_L = wheelset_L * std::sqrt(1.0 + (1.5 / 0.75) * (1.5 / 0.75));
  EXPECT_NEAR(r.critical_speed_m_per_s / f, bogie_L, 0.1 * bogie_L);
}

// auto picks dense below kSparseFromStates states (the thesis vehicle: 82)
// and the sparse band solver from there, the crossover measured by
// analysis/bench_scaling; ARPACK at one shift only when asked.
TEST(EigenOnVehicle, AutomaticSolverChoice) {
  EXPECT_EQ(resolved_solver(EigenSolverKind::automatic, 78), EigenSolverKind::dense);
  EXPECT_EQ(resolved_solver(EigenSolverKind::automatic, kSparseFromStates - 1),
            EigenSolverKind::dense);
  EXPECT_EQ(resolved_solver(EigenSolverKind::automatic, kSparseFromStates),
            EigenSolverKind::sparse);
  EXPECT_EQ(resolved_solver(EigenSolverKind::dense, 500), EigenSolverKind::dense);
  EXPECT_EQ(resolved_solver(EigenSolverKind::arpack, 10), EigenSolverKind::arpack);
  const PreparedScene s =
      prepare_scene(std::string(RAILSTAB_CASES_DIR) + "/thesis_vehicle_tangent.toml", {});
  SpeedStability stability(s.model, s.equilibrium.state, s.speed_m_per_s, StabilityOptions{});
  const StabilityPoint p = stability.at(60.0);
  EXPECT_EQ(p.solver_used, EigenSolverKind::dense);
  EXPECT_EQ(p.modes.size(), size_t(p.linear.A.rows()));  // all modes
}
