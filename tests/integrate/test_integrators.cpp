// Every integrator reproduces the closed-form free response of a damped and
// an undamped single-degree-of-freedom oscillator built from the model's own
// bodies and springs, to an accuracy consistent with its tolerance.
#include <railstab/equilibrium/equilibrium.hpp>
#include <railstab/setup/build_model.hpp>
#include <railstab/integrate/integrator.hpp>
#include "integrate/integration_scenes.hpp"
#include <railstab/integrate/work_precision.hpp>

#include <gtest/gtest.h>

#include <cstdio>

using namespace railstab;

namespace {

struct OscillatorCase {
  IntegratorKind kind;
  int order;
  double damping_ratio;
  // Bound on max |y - exact| relative to the amplitude at rtol 1e-8.
  double relative_bound = 1e-6;
};

std::string case_name(const ::testing::TestParamInfo<OscillatorCase>& info) {
  return integrator_name(info.param.kind) +
         (info.param.order > 0 ? "_q" + std::to_string(info.param.order) : "") +
         (info.param.damping_ratio > 0.0 ? "_damped" : "_undamped");
}

}  // namespace

class ClosedForm : public ::testing::TestWithParam<OscillatorCase> {};

// 2 Hz, 4 periods from y0 = 10 mm. rtol 1e-8 and atol 1e-11 m bound each
// step's local error by ~1e-10 m; over the ~200-2000 steps of the run the
// global error stays below 1e-6 of the amplitude (1e-8 m), the bound
// checked. BDF capped at order 2 needs ~15000 steps and its local errors add
// up to ~1e-5 of the amplitude (measured 7.4e-8 m): its bound is 1e-5. A
// wrong force sign, mass or damping term shows up at 1e-3 and more.
TEST_P(ClosedForm, LateralOscillatorMatchesExactSolution) {
  const OscillatorCase& c = GetParam();
  test::LateralOscillator osc;
  osc.damping_ratio = c.damping_ratio;
  const SceneSpec spec = osc.scene();
  const Model model = build_model(spec);
  ASSERT_EQ(model.state_size(), 2);
  IntegrationOptions opt;
  opt.kind = c.kind;
  opt.order = c.order;
  opt.t_end_s = 2.0;
  opt.output_interval_s = 0.01;
  opt.relative_tolerance = 1e-8;
  opt.absolute_tolerance = 1e-11;
  const Trajectory traj = integrate(model, spec.speed_m_per_s, initial_state(model, spec.speed_m_per_s), opt);
  ASSERT_EQ(traj.times_s.size(), 201u);
  EXPECT_NEAR(traj.times_s.back(), 2.0, 1e-12);
  EXPECT_TRUE(traj.events.empty());
  double worst = 0.0;
  for (size_t i = 0; i < traj.times_s.size(); ++i)
    worst = std::max(worst, std::abs(traj.states[i](0) - osc.exact(traj.times_s[i])));
  std::printf("  %-12s zeta %.2f: max |y - exact| = %.3g m (%ld steps)\n",
              integrator_name(c.kind).c_str(), c.damping_ratio, worst, traj.stats.steps);
  EXPECT_LT(worst, c.relative_bound * osc.y0_m);
  EXPECT_GT(traj.stats.steps, 0);
  EXPECT_GT(traj.stats.rhs_evaluations, 0);
}

// Looser tolerance, looser result: the error follows the tolerance (so the
// tolerance reaches the integrator), within a factor the test states.
TEST_P(ClosedForm, ErrorFollowsTolerance) {
  const OscillatorCase& c = GetParam();
  test::LateralOscillator osc;
  osc.damping_ratio = c.damping_ratio;
  const SceneSpec spec = osc.scene();
  const Model model = build_model(spec);
  auto error_at = [&](double rtol) {
    IntegrationOptions opt;
    opt.kind = c.kind;
    opt.order = c.order;
    opt.t_end_s = 2.0;
    opt.output_interval_s = 0.01;
    opt.relative_tolerance = rtol;
    opt.absolute_tolerance = rtol * 1e-3;
    const Trajectory traj = integrate(model, spec.speed_m_per_s, initial_state(model, spec.speed_m_per_s), opt);
    double worst = 0.0;
    for (size_t i = 0; i < traj.times_s.size(); ++i)
      worst = std::max(worst, std::abs(traj.states[i](0) - osc.exact(traj.times_s[i])));
    return worst;
  };
  const double loose = error_at(1e-4), tight = error_at(1e-8);
  // Global errors of adaptive codes scale roughly like the tolerance; four
  // decades of tolerance must buy at least two decades of error, and the
  // loose run must still be within 1 % of the amplitude.
  EXPECT_LT(tight, 1e-2 * loose);
  EXPECT_LT(loose, 1e-2 * osc.y0_m);
}

INSTANTIATE_TEST_SUITE_P(
    AllIntegrators, ClosedForm,
    ::testing::Values(OscillatorCase{IntegratorKind::cvode_bdf, 0, 0.05},
                      OscillatorCase{IntegratorKind::cvode_bdf, 0, 0.0},
                      OscillatorCase{IntegratorKind::cvode_bdf, 2, 0.05, 1e-5},
                      OscillatorCase{IntegratorKind::cvode_adams, 0, 0.05},
                      OscillatorCase{IntegratorKind::cvode_adams, 0, 0.0},
                      OscillatorCase{IntegratorKind::arkode_erk, 0, 0.05},
                      OscillatorCase{IntegratorKind::arkode_erk, 0, 0.0},
                      OscillatorCase{IntegratorKind::arkode_dirk, 0, 0.05},
                      OscillatorCase{IntegratorKind::arkode_dirk, 0, 0.0},
                      OscillatorCase{IntegratorKind::arkode_imex, 0, 0.05},
                      OscillatorCase{IntegratorKind::arkode_imex, 0, 0.0}),
    case_name);

TEST(IntegratorNames, RoundTripAndUnknownNameListsTheKnownOnes) {
  for (IntegratorKind k : all_integrator_kinds())
    EXPECT_EQ(parse_integrator_kind(integrator_name(k)), k);
  try {
    parse_integrator_kind("rk45");
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("arkode_dirk"), std::string::npos) << e.what();
  }
}

// Orders a method does not offer are refused with the ones it does, instead
// of SUNDIALS substituting another table (ARKODE) or failing with a flag
// (CVODE).
TEST(IntegratorNames, OrdersOutsideTheMethodAreRefused) {
  EXPECT_EQ(parse_integrator_variant("cvode_bdf_q2").order, 2);
  EXPECT_EQ(parse_integrator_variant("arkode_dirk_q3").order, 3);
  for (const char* bad : {"cvode_bdf_q7", "arkode_dirk_q9", "arkode_dirk_q1", "arkode_erk_q7",
                          "arkode_imex_q2", "cvode_adams_q0"}) {
    try {
      parse_integrator_variant(bad);
      ADD_FAILURE() << bad << ": expected std::invalid_argument";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("offers orders"), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(parse_integrator_variant("cvode_bdf_q99999999999"), std::invalid_argument);
  EXPECT_FALSE(order_available(IntegratorKind::cvode_bdf, 7));
  EXPECT_TRUE(order_available(IntegratorKind::arkode_erk, 8));
}
