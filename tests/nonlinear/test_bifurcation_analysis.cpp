// analyse_bifurcation and the nonlinear critical speed it reports, against
// references no one tuned to:
// - the Bautin normal form r' = r (alpha + r^2 - r^4), alpha = V - 10: the
//   branch from the (subcritical) Hopf point goes round the fold of cycles
//   at alpha = -1/4, so the nonlinear critical speed is 9.75 exactly, bounded
//   by a fold; the supercritical normal form r' = r (alpha - r^2): stable
//   from the Hopf point, so the nonlinear critical speed is V_c; with the
//   Bautin branch cut before the fold: not found, and why;
// - the thesis bogie (knife-edge cone, Hertz, Kalker: smooth): the branch
//   from the Hopf point starts at the linear critical speed (0.01 m/s) with
//   the period 2 pi / Im(lambda) (1e-6 relative) and the amplitude of the
//   first Lyapunov coefficient's square-root law (1 %); supercritical, so
//   the nonlinear critical speed is the linear one.
#include <gtest/gtest.h>

#include <railstab/nonlinear/bifurcation_analysis.hpp>
#include <railstab/nonlinear/orbit_continuation.hpp>
#include <railstab/setup/prepare_scene.hpp>

#include <cmath>
#include <cstdio>
#include <ctime>
#include <numbers>

using namespace railstab;

namespace {

constexpr double kOmega = 2.0 * std::numbers::pi;  // 1 Hz
constexpr double kHopfSpeed = 10.0;                // alpha = V - kHopfSpeed

// x' = a x - w y + x g(r^2), y' = w x + a y + y g(r^2); Bautin: g = r^2 -
// r^4 (fold of cycles at a = -1/4, r^2 = 1/2), else g = -r^2.
FlowSystem normal_form(bool bautin) {
  FlowSystem s;
  s.size = 2;
  s.state_names = {"x", "y"};
  s.rhs = [bautin](const Eigen::VectorXd& x, double V, Eigen::VectorXd& f) {
    const double a = V - kHopfSpeed, r2 = x.squaredNorm();
    const double g = bautin ? r2 - r2 * r2 : -r2;
    f.resize(2);
    f << a * x(0) - kOmega * x(1) + x(0) * g, kOmega * x(0) + a * x(1) + x(1) * g;
  };
  s.jacobian = [bautin](const Eigen::VectorXd& x, double V, Eigen::MatrixXd& J) {
    const double a = V - kHopfSpeed, r2 = x.squaredNorm();
    const double g = bautin ? r2 - r2 * r2 : -r2, dg = bautin ? 1.0 - 2.0 * r2 : -1.0;
    J.resize(2, 2);
    J << a + g + 2.0 * x(0) * x(0) * dg, -kOmega + 2.0 * x(0) * x(1) * dg,
        kOmega + 2.0 * x(0) * x(1) * dg, a + g + 2.0 * x(1) * x(1) * dg;
  };
  return s;
}

// The branch from the Hopf point of the normal form as analyse_bifurcation
// would hold it (the linear part: V_c and the kind).
BifurcationResult normal_form_result(bool bautin, int max_orbits) {
  HopfStart start;
  start.equilibrium = Eigen::VectorXd::Zero(2);
  start.critical_speed_m_per_s = kHopfSpeed;
  start.eigenvalue = {0.0, kOmega};
  start.eigenvector = Eigen::VectorXcd::Zero(2);
  start.eigenvector << 1.0, std::complex<double>(0.0, -1.0);
  start.cycle_side = bautin ? -1 : 1;
  start.amplitude_per_sqrt_speed = 1.0;
  ContinuationOptions opt;
  opt.amplitude_scale = 0.1;
  opt.initial_step = 0.5;
  opt.max_step = 1.0;
  opt.max_amplitude = 1.1;
  opt.max_orbits = max_orbits;
  opt.min_speed_m_per_s = 5.0;
  opt.max_speed_m_per_s = 15.0;
  BifurcationResult r;
  r.linear.critical_speed_found = true;
  r.linear.critical_speed_m_per_s = kHopfSpeed;
  r.hopf_kind = bautin ? "subcritical" : "supercritical";
  r.from_m_per_s = 5.0;
  r.to_m_per_s = 15.0;
  r.coords = {1, 0};
  BranchResult b;
  b.origin = "hopf";
  b.branch = continue_from_hopf(normal_form(bautin), r.coords, start, 0.05, opt);
  r.branches.push_back(b);
  return r;
}

}  // namespace

TEST(NonlinearCriticalSpeed, BautinBranchIsBoundedByItsFoldAtAlphaMinusAQuarter) {
  const BifurcationResult r = normal_form_result(true, 200);
  const NonlinearCriticalSpeed n = nonlinear_critical_speed(r);
  ASSERT_TRUE(n.found) << n.explanation;
  EXPECT_EQ(n.bound, StableBound::fold);
  // The parabola through three orbits: its error is third order in the step.
  EXPECT_NEAR(n.speed_m_per_s, kHopfSpeed - 0.25, 2e-3);
  EXPECT_EQ(n.branch, 0);
  EXPECT_NE(n.explanation.find("fold"), std::string::npos) << n.explanation;
}

TEST(NonlinearCriticalSpeed, SupercriticalBranchIsStableFromTheHopfPoint) {
  const BifurcationResult r = normal_form_result(false, 12);
  const NonlinearCriticalSpeed n = nonlinear_critical_speed(r);
  ASSERT_TRUE(n.found) << n.explanation;
  EXPECT_EQ(n.bound, StableBound::hopf_point);
  // The first orbit, excursion 0.05: alpha = r^2 = 0.0025.
  EXPECT_NEAR(n.speed_m_per_s, kHopfSpeed + 0.0025, 1e-6);
}

// Cut after the unstable small cycles (before the fold): no stable orbit.
// Cut just after the fold's first stable orbits: the lowest stable orbit
// is the branch's last one, which bounds nothing below.
TEST(NonlinearCriticalSpeed, BranchCutShortGivesNotFoundWithTheReason) {
  const BifurcationResult none = normal_form_result(true, 3);
  const NonlinearCriticalSpeed a = nonlinear_critical_speed(none);
  EXPECT_FALSE(a.found);
  EXPECT_EQ(a.bound, StableBound::none);
  EXPECT_EQ(a.explanation.rfind("not found: no stable orbit", 0), 0u) << a.explanation;
  EXPECT_NE(a.explanation.find("orbit limit reached"), std::string::npos) << a.explanation;
  EXPECT_EQ(a.speed_m_per_s, 0.0);

  // The full branch's first stable orbit, then the branch cut there with no
  // fold recorded (as when the turn of the speed lies within the corrector's
  // resolution, or past the cut): the stable orbit is an end of the branch,
  // what lies below it is not known. Built from the full branch rather than
  // by rerunning with an orbit limit, whose fold detection depends on where
  // the step control puts the orbits.
  const BifurcationResult full = normal_form_result(true, 200);
  const auto& o = full.branches[0].branch.orbits;
  size_t first_stable = 0;
  while (first_stable < o.size() && !o[first_stable].stable) ++first_stable;
  ASSERT_LT(first_stable, o.size());
  BifurcationResult cut = full;
  OrbitBranch& branch = cut.branches[0].branch;
  branch.orbits.resize(first_stable + 1);
  branch.bifurcations.clear();
  branch.stop_reason = "orbit limit reached";
  const NonlinearCriticalSpeed b = nonlinear_critical_speed(cut);
  EXPECT_FALSE(b.found) << b.explanation;
  EXPECT_EQ(b.bound, StableBound::branch_end);
  EXPECT_NEAR(b.lowest_stable_speed_m_per_s, o[first_stable].speed_m_per_s, 1e-9);
  EXPECT_NE(b.explanation.find("not known"), std::string::npos) << b.explanation;
}

// ~10 s CPU in Release (two orbits of 0.69 s with 32 x 32 sensitivities,
// about 5,000 BDF steps per flow, and the critical-speed search).
TEST(BifurcationAnalysisThesisBogie, HopfBranchStartsAtTheLinearCriticalSpeedWithItsPeriodAndAmplitudeLaw) {
  const PreparedScene s = prepare_scene(std::string(RAILSTAB_CASES_DIR) + "/thesis_bogie_tangent.toml", {});
  BifurcationOptions o;
  o.linear.from_m_per_s = 30.0;
  o.linear.to_m_per_s = 45.0;
  o.linear.grid_step_m_per_s = 2.5;
  // Bisected to 1e-6 m/s: the period is compared with the critical pair's
  // frequency at the bisection's end, which moves ~1e-5 relative per 0.01 m/s.
  o.linear.tolerance_m_per_s = 1e-6;
  o.continuation.max_orbits = 2;
  const std::clock_t cpu0 = std::clock();
  const BifurcationResult r = analyse_bifurcation(s.model, s.equilibrium.state, s.speed_m_per_s, o);
  const double cpu = double(std::clock() - cpu0) / CLOCKS_PER_SEC;
  ASSERT_TRUE(r.linear.critical_speed_found);
  ASSERT_TRUE(r.hopf_computed);
  EXPECT_EQ(r.hopf_kind, "supercritical");
  EXPECT_EQ(r.hopf_assessment.result.kind, HopfKind::supercritical);
  ASSERT_EQ(r.branches.size(), 1u);
  ASSERT_TRUE(r.branches[0].error.empty()) << r.branches[0].error;
  const OrbitBranch& b = r.branches[0].branch;
  ASSERT_EQ(b.orbits.size(), 2u);
  EXPECT_EQ(b.stop_reason, "orbit limit reached");
  const PeriodicOrbit &o1 = b.orbits[0], &o2 = b.orbits[1];
  const double Vc = r.linear.critical_speed_m_per_s;
  const double V0 = (4.0 * o1.speed_m_per_s - o2.speed_m_per_s) / 3.0;
  const double T0 = (4.0 * o1.period_s - o2.period_s) / 3.0;
  EXPECT_NEAR(V0, Vc, 0.01);
  // The Hopf point's own frequency (hopf_criticality at the bisection's end,
  // V_c extrapolated from the real part there).
  const HopfCriticality& h = r.hopf_assessment.result;
  EXPECT_NEAR(V0, h.critical_speed_m_per_s, 1e-4);
  EXPECT_NEAR(T0, 2.0 * std::numbers::pi / h.hopf.eigenvalue.imag(), 1e-6 * T0);
  for (const PeriodicOrbit* orbit : {&o1, &o2}) {
    const double a = orbit->amplitude(r.coords.amplitude_state);
    EXPECT_NEAR(a, predicted_amplitude(h, "wheelset1.y_m", orbit->speed_m_per_s), 0.01 * a);
    EXPECT_LT(std::abs(orbit->critical_multiplier), 1.0 + 1e-5);
  }
  // Supercritical: the stable orbits start at the Hopf point.
  ASSERT_TRUE(r.nonlinear.found) << r.nonlinear.explanation;
  EXPECT_EQ(r.nonlinear.bound, StableBound::hopf_point);
  EXPECT_NEAR(r.nonlinear.speed_m_per_s, Vc, 0.01);
  ASSERT_EQ(r.wheelsets.size(), 2u);
  EXPECT_GT(o2.amplitude(r.wheelsets[1].lateral_state), 0.0);
  EXPECT_GT(o2.amplitude(r.wheelsets[0].yaw_state), 0.0);
  std::printf("[ bogie    ] V_c %.4f m/s, V0 %.6f, T0 %.8f s (2 pi / w %.8f); 2 orbits: %ld + %ld "
              "steps, %.2f s CPU in all\n",
              Vc, V0, T0, 2.0 * std::numbers::pi / h.hopf.eigenvalue.imag(), o1.integration_steps,
              o2.integration_steps, cpu);
}
