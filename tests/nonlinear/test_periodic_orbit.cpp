// Periodic orbits by shooting, their Floquet multipliers and the branch's
// continuation, against references no one tuned to:
// - the Hopf normal form (supercritical) with a stiff slave state: the orbit
//   r = sqrt(alpha), T = 2 pi / omega, multipliers 1, exp(-2 alpha T) and
//   exp(-50 T) in closed form;
// - the Bautin normal form r' = r (alpha + r^2 - r^4) (subcritical Hopf
//   with a fold of cycles at alpha = -1/4, r^2 = 1/2): the branch from the
//   Hopf point goes round the fold, unstable below it and stable above, with
//   the multiplier exp(T (2 r^2 - 4 r^4)), and a perturbed run decays like it;
// - on the thesis bogie (knife-edge, Hertz, Kalker: smooth) the monodromy
//   matrix and d phi/dV against central differences of the flow;
// - on the thesis vehicle, the branch from the Hopf point starts at the
//   linear critical speed with the period 2 pi / Im(lambda) and follows the
//   first Lyapunov coefficient's square-root law; a plain time-domain run
//   from an orbit returns to it after one period.
#include <gtest/gtest.h>

#include <railstab/integrate/integrator.hpp>
#include <railstab/model/equations_of_motion.hpp>
#include <railstab/nonlinear/flow_sensitivity.hpp>
#include <railstab/nonlinear/hopf_criticality.hpp>
#include <railstab/nonlinear/model_orbits.hpp>
#include <railstab/nonlinear/orbit_continuation.hpp>
#include <railstab/nonlinear/bifurcation_analysis.hpp>
#include <railstab/nonlinear/periodic_orbit.hpp>
#include <railstab/nonlinear/variational_pass.hpp>
#include <railstab/setup/prepare_scene.hpp>
#include <railstab/stability/speed_analysis.hpp>

#include <cmath>
#include <complex>
#include <cstdlib>
#include <cstdio>
#include <ctime>
#include <numbers>
#include <string>
#include <vector>

using namespace railstab;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kOmega = 2.0 * kPi;  // 1 Hz
constexpr double kHopfSpeed = 10.0;   // alpha = V - kHopfSpeed

// x' = a x - w y + s x g(r^2), y' = w x + a y + s y g(r^2), z' = -50 z + x^2;
// supercritical: g = -r^2; Bautin: g = r^2 - r^4.
FlowSystem normal_form(bool bautin) {
  FlowSystem s;
  s.size = 3;
  s.state_names = {"x", "y", "z"};
  s.rhs = [bautin](const Eigen::VectorXd& x, double V, Eigen::VectorXd& f) {
    const double a = V - kHopfSpeed, r2 = x(0) * x(0) + x(1) * x(1);
    const double g = bautin ? r2 - r2 * r2 : -r2;
    f.resize(3);
    f << a * x(0) - kOmega * x(1) + x(0) * g, kOmega * x(0) + a * x(1) + x(1) * g,
        -50.0 * x(2) + x(0) * x(0);
  };
  s.jacobian = [bautin](const Eigen::VectorXd& x, double V, Eigen::MatrixXd& J) {
    const double a = V - kHopfSpeed, r2 = x(0) * x(0) + x(1) * x(1);
    const double g = bautin ? r2 - r2 * r2 : -r2, dg = bautin ? 1.0 - 2.0 * r2 : -1.0;
    J.setZero(3, 3);
    J(0, 0) = a + g + 2.0 * x(0) * x(0) * dg;
    J(0, 1) = -kOmega + 2.0 * x(0) * x(1) * dg;
    J(1, 0) = kOmega + 2.0 * x(0) * x(1) * dg;
    J(1, 1) = a + g + 2.0 * x(1) * x(1) * dg;
    J(2, 0) = 2.0 * x(0);
    J(2, 2) = -50.0;
  };
  return s;  // df/dV by the central difference (FlowSystem's default)
}

// Section: y = 0 (the rate of x at its maximum up to the factor -w);
// excursion: x.
const OrbitCoordinates kNormalFormCoords{1, 0};

// The slave state on the orbit x = r cos(w t): z = r^2 (1/100 + (50 cos 2wt
// + 2w sin 2wt) / (2 (2500 + 4 w^2))) at the section (t = 0).
double slave_at_section(double r) {
  return r * r * (1.0 / 100.0 + 50.0 / (2.0 * (2500.0 + 4.0 * kOmega * kOmega)));
}

// The closed-form checks test the method, so the flow runs far tighter than
// the defaults (state rtol 1e-8, sensitivities 1e-5, Newton 1e-7, which
// leave errors of about 1e-7 in r and 1e-8 in T on these systems).
ShootingOptions tight_shooting() {
  ShootingOptions o;
  o.flow.relative_tolerance = 1e-11;
  o.flow.absolute_tolerance = 1e-14;
  o.flow.sensitivity_relative_tolerance = 1e-10;
  o.flow.sensitivity_absolute_tolerance = 1e-13;
  o.newton_relative_tolerance = 1e-9;
  return o;
}

// The supercritical orbit at alpha 0.09 (r = 0.3, T = 1 s) from a guess
// near it, and its radius, period and multipliers against the closed form.
PeriodicOrbit closed_form_orbit(const ShootingOptions& options) {
  const FlowSystem s = normal_form(false);
  const double V = kHopfSpeed + 0.09;
  Eigen::VectorXd guess(3);
  guess << 0.28, 0.0, 0.0;
  return solve_periodic_orbit(s, kNormalFormCoords, OrbitConstraint::fixed_speed(V), guess, 1.02, V,
                              options);
}

void expect_closed_form_orbit(const PeriodicOrbit& o) {
  const double T = 1.0 / (kOmega / (2.0 * kPi));
  EXPECT_NEAR(o.start(0), 0.3, 1e-9);
  EXPECT_NEAR(o.period_s, T, 1e-9 * T);
  ASSERT_EQ(o.floquet_multipliers.size(), 3);
  EXPECT_LT(o.trivial_multiplier_error, 1e-7);
  EXPECT_NEAR(std::abs(o.critical_multiplier - std::exp(-2.0 * 0.09 * T)), 0.0, 1e-7);
  EXPECT_NEAR(std::abs(o.floquet_multipliers(2)), std::exp(-50.0 * T), 1e-9);
  EXPECT_TRUE(o.stable);
}

}  // namespace

TEST(PeriodicOrbitNormalForm, RadiusPeriodAndMultipliersMatchTheClosedForm) {
  const PeriodicOrbit o = closed_form_orbit(tight_shooting());
  expect_closed_form_orbit(o);
  EXPECT_NEAR(o.start(2), slave_at_section(0.3), 1e-9);
  EXPECT_NEAR(o.speed_m_per_s, kHopfSpeed + 0.09, 0.0);
  EXPECT_NEAR(o.amplitude(0), 0.3, 1e-6);  // from 200 interpolated samples
  EXPECT_LT(o.periodicity_residual, 1e-8);
  EXPECT_LE(o.newton_iterations, 6);
}

// The same orbit with the variational equations in a second pass along the
// recorded state (what profile contact uses): the same closed form, to the
// same tolerances. Small enough to run under the sanitizers, where the
// profile-contact orbits are too long.
TEST(PeriodicOrbitNormalForm, SecondPassGivesTheClosedFormMultipliers) {
  ShootingOptions options = tight_shooting();
  options.flow.variational = FlowOptions::Variational::second_pass;
  const PeriodicOrbit o = closed_form_orbit(options);
  std::printf("[ second   ] r - 0.3 = %.2e, T - 1 = %.2e, mu - closed form = %.2e, trivial %.2e\n",
              o.start(0) - 0.3, o.period_s - 1.0,
              std::abs(o.critical_multiplier - std::exp(-2.0 * 0.09)), o.trivial_multiplier_error);
  expect_closed_form_orbit(o);
}

// A guess far from the orbit (radius 1.0 for 0.3, period 20 % long): a full
// Newton step raises the residual; shortened, it reduces it and Newton ends
// on the closed form. Without step shortening (max_step_halvings 0) the
// same guess is refused.
TEST(PeriodicOrbitNormalForm, DampedNewtonReachesTheOrbitFromAFarGuess) {
  const FlowSystem s = normal_form(false);
  const double V = kHopfSpeed + 0.09;
  Eigen::VectorXd guess(3);
  guess << 1.0, 0.0, 0.0;
  ShootingOptions o = tight_shooting();
  o.max_newton_iterations = 40;
  const PeriodicOrbit orbit =
      solve_periodic_orbit(s, kNormalFormCoords, OrbitConstraint::fixed_speed(V), guess, 1.2, V, o);
  EXPECT_NEAR(orbit.start(0), 0.3, 1e-9);
  EXPECT_NEAR(orbit.period_s, 1.0, 1e-9);
  EXPECT_GE(orbit.damped_steps, 1);
  std::printf("[ damped   ] %d iterations, %d damped steps, %d flows with sensitivities\n",
              orbit.newton_iterations, orbit.damped_steps, orbit.sensitivity_flows);
  o.max_step_halvings = 0;
  EXPECT_THROW(solve_periodic_orbit(s, kNormalFormCoords, OrbitConstraint::fixed_speed(V), guess,
                                    1.2, V, o),
               ShootingFailure);
}

// Chord iterations on a neighbour's derivatives (the continuation's case)
// end on the same orbit as Newton with fresh derivatives, to the
// tolerance, with fewer flows carrying the variational equations (the
// dear ones on a railway model: one AD Jacobian per step).
TEST(PeriodicOrbitNormalForm, ChordIterationsEndOnTheSameOrbit) {
  const FlowSystem s = normal_form(false);
  Eigen::VectorXd guess(3);
  guess << 0.3, 0.0, slave_at_section(0.3);
  const ShootingOptions o = tight_shooting();
  const PeriodicOrbit near = solve_periodic_orbit(
      s, kNormalFormCoords, OrbitConstraint::fixed_speed(kHopfSpeed + 0.09), guess, 1.0, kHopfSpeed + 0.09, o);
  const double V = kHopfSpeed + 0.1;  // r = sqrt(0.1)
  guess << 0.31, 0.0, slave_at_section(0.31);
  const PeriodicOrbit chord = solve_periodic_orbit(s, kNormalFormCoords, OrbitConstraint::fixed_speed(V),
                                                   guess, 1.0, V, o, &near);
  const PeriodicOrbit exact = solve_periodic_orbit(s, kNormalFormCoords, OrbitConstraint::fixed_speed(V),
                                                   guess, 1.0, V, o);
  EXPECT_NEAR(chord.start(0), std::sqrt(0.1), 1e-9);
  EXPECT_NEAR(exact.start(0), std::sqrt(0.1), 1e-9);
  EXPECT_NEAR(std::abs(chord.critical_multiplier - std::exp(-2.0 * 0.1)), 0.0, 1e-7);
  EXPECT_NEAR(chord.period_s, exact.period_s, 1e-9);
  EXPECT_GE(exact.sensitivity_flows, exact.newton_iterations);
  EXPECT_LE(chord.sensitivity_flows, 2);
  EXPECT_LT(chord.sensitivity_flows, exact.sensitivity_flows);
  std::printf("[ chord    ] chord: %d iterations, %d with sensitivities; Newton: %d iterations\n",
              chord.newton_iterations, chord.sensitivity_flows, exact.newton_iterations);
}

// Every Newton iteration is reported once, numbered, with the orbit's CPU
// so far; the first (no chord neighbour) with exact derivatives.
TEST(PeriodicOrbitNormalForm, IterationProgressIsCalledOncePerIteration) {
  ShootingOptions options = tight_shooting();
  std::vector<ShootingIteration> seen;
  options.iteration_progress = [&seen](const ShootingIteration& it) { seen.push_back(it); };
  const PeriodicOrbit o = closed_form_orbit(options);
  expect_closed_form_orbit(o);
  ASSERT_EQ(int(seen.size()), o.newton_iterations);
  for (size_t k = 0; k < seen.size(); ++k) {
    EXPECT_EQ(seen[k].iteration, int(k) + 1);
    if (k > 0) {
      EXPECT_GE(seen[k].cpu_seconds, seen[k - 1].cpu_seconds);
    }
    EXPECT_TRUE(seen[k].exact_derivatives);
  }
  EXPECT_NEAR(seen.front().period_s, 1.02, 1e-15);  // the guess's
  EXPECT_LE(seen.back().step_norm, options.stagnation_step_norm);
}

// A time-domain start (orbit_guess_from_samples) on a cycle with two maxima
// per period, as flange hunting has where the flange throws the wheelset
// back: x = sin(th) + 0.3 sin(3 th) + 0.05 sin(2 th), th = 2 pi t / T, has a
// higher and a lower maximum each period (x'' > 0 at th = pi/2 between
// them). The guess is the cycle (period T), starting at the higher maximum,
// not a bounce between the two; its spread is nil.
TEST(OrbitGuess, PrincipalMaximumGivesTheCycleNotTheBounce) {
  const double T = 0.4873, w = 2.0 * kPi / T, dt = 1e-3;
  auto x_of = [w](double t) {
    return std::sin(w * t) + 0.3 * std::sin(3.0 * w * t) + 0.05 * std::sin(2.0 * w * t);
  };
  auto rate_of = [w](double t) {
    return w * (std::cos(w * t) + 0.9 * std::cos(3.0 * w * t) + 0.1 * std::cos(2.0 * w * t));
  };
  std::vector<double> times;
  std::vector<Eigen::VectorXd> states;
  int maxima = 0;
  for (double t = 0.0; t <= 3.0; t += dt) {
    times.push_back(t);
    states.emplace_back(Eigen::Vector2d(x_of(t), rate_of(t)));
    if (states.size() > 1 && states[states.size() - 2](1) > 0.0 && states.back()(1) <= 0.0) ++maxima;
  }
  double x_max = -1e300;  // the higher maximum, on a fine grid
  for (double t = 0.0; t < T; t += 1e-7) x_max = std::max(x_max, x_of(t));
  const OrbitGuess g = orbit_guess_from_samples(times, states, kNormalFormCoords);
  EXPECT_GE(maxima, 2 * 6);  // two maxima a period: counting every one would halve the cycle
  EXPECT_NEAR(g.period_s, T, 1e-5 * T);
  // Linear interpolation between samples at the maximum: dt^2 / 8 |x''| ~ 1e-4.
  EXPECT_NEAR(g.start(0), x_max, 1e-4);
  EXPECT_NEAR(g.start(1), 0.0, 1e-12);
  // 6.2 periods: 5 or 6 complete cycles between upward mid-range crossings.
  EXPECT_GE(g.cycles, 5);
  EXPECT_LE(g.cycles, 6);
  EXPECT_LT(g.spread(), 1e-4);
}

// A motion whose cycles differ (amplitude modulated by 10 % over 1.7 s):
// its spread says so, above the bifurcation start's 1 % limit.
TEST(OrbitGuess, SpreadMeasuresCyclesThatDiffer) {
  const double T = 0.2, w = 2.0 * kPi / T;
  std::vector<double> times;
  std::vector<Eigen::VectorXd> states;
  for (double t = 0.0; t <= 2.0; t += 1e-4) {
    const double a = 1.0 + 0.1 * std::sin(2.0 * kPi * t / 1.7);
    const double da = 0.1 * (2.0 * kPi / 1.7) * std::cos(2.0 * kPi * t / 1.7);
    times.push_back(t);
    states.emplace_back(Eigen::Vector2d(a * std::sin(w * t), da * std::sin(w * t) + a * w * std::cos(w * t)));
  }
  const OrbitGuess g = orbit_guess_from_samples(times, states, kNormalFormCoords);
  EXPECT_GT(g.excursion_max - g.excursion_min, 0.1);  // of a half range near 1.1
  EXPECT_GT(g.spread(), 0.1);
  EXPECT_GT(g.spread(), kSettledCycleSpreadLimit);
}

TEST(PeriodicOrbitNormalForm, BadGuessesAndCoordinatesAreRefused) {
  const FlowSystem s = normal_form(false);
  Eigen::VectorXd guess(3);
  guess << 0.25, 0.0, 0.0;
  EXPECT_THROW(solve_periodic_orbit(s, {0, 0}, OrbitConstraint::fixed_speed(10.1), guess, 1.0, 10.1),
               std::invalid_argument);
  EXPECT_THROW(solve_periodic_orbit(s, kNormalFormCoords, OrbitConstraint::fixed_speed(10.1),
                                    Eigen::VectorXd::Zero(2), 1.0, 10.1),
               std::invalid_argument);
  // Below the Hopf point there is no cycle: Newton collapses onto the
  // steady state (a "periodic orbit" of any period), which is refused.
  EXPECT_THROW(solve_periodic_orbit(s, kNormalFormCoords, OrbitConstraint::fixed_speed(9.9), guess,
                                    1.0, 9.9),
               ShootingFailure);
}

// The Bautin normal form's Hopf point (subcritical: l1 > 0, cycles below
// V_c; r^2 = -alpha near 0), the start of its branch of orbits.
HopfStart bautin_hopf_start() {
  HopfStart start;
  start.equilibrium = Eigen::VectorXd::Zero(3);
  start.critical_speed_m_per_s = kHopfSpeed;
  start.eigenvalue = {0.0, kOmega};
  start.eigenvector = Eigen::VectorXcd::Zero(3);
  start.eigenvector << 1.0, std::complex<double>(0.0, -1.0), 0.0;  // x = cos, y = sin
  start.cycle_side = -1;
  start.amplitude_per_sqrt_speed = 1.0;
  return start;
}

// The Bautin branch's continuation: tight shooting, up to r = 1.1, with the
// plane's excursion scale and the step's start and limit.
ContinuationOptions bautin_continuation(double amplitude_scale, double initial_step, double max_step) {
  ContinuationOptions opt;
  opt.shooting = tight_shooting();
  opt.amplitude_scale = amplitude_scale;
  opt.initial_step = initial_step;
  opt.max_step = max_step;
  opt.max_amplitude = 1.1;
  return opt;
}

TEST(OrbitContinuationBautin, BranchFromTheHopfPointGoesRoundTheFold) {
  const FlowSystem s = normal_form(true);
  const HopfStart start = bautin_hopf_start();
  ContinuationOptions opt = bautin_continuation(0.1, 0.5, 1.0);
  const OrbitBranch b = continue_from_hopf(s, kNormalFormCoords, start, 0.05, opt);
  ASSERT_GE(b.orbits.size(), 10u);
  EXPECT_EQ(b.stop_reason, "amplitude limit reached");
  const double T = 1.0;
  int stable = 0, unstable = 0;
  for (const PeriodicOrbit& o : b.orbits) {
    const double r = o.start(0), r2 = r * r;
    // On the branch alpha = r^4 - r^2; period 1 s; multiplier exp(T (2 r^2 - 4 r^4)).
    EXPECT_NEAR(o.speed_m_per_s - kHopfSpeed, r2 * r2 - r2, 1e-8) << "r = " << r;
    EXPECT_NEAR(o.period_s, T, 1e-9);
    const double mu = std::exp(T * (2.0 * r2 - 4.0 * r2 * r2));
    EXPECT_NEAR(o.critical_multiplier.real(), mu, 1e-6 * mu) << "r = " << r;
    if (std::abs(r2 - 0.5) > 0.02) {
      EXPECT_EQ(o.stable, r2 > 0.5) << "r = " << r;
      (o.stable ? stable : unstable)++;
    }
  }
  EXPECT_GT(stable, 2);
  EXPECT_GT(unstable, 2);
  // One fold, at alpha = -1/4 (the parabola through three orbits: its error
  // is third order in the step).
  ASSERT_EQ(b.bifurcations.size(), 1u);
  EXPECT_EQ(b.bifurcations[0].kind, OrbitBifurcationKind::fold);
  EXPECT_NEAR(b.bifurcations[0].speed_m_per_s, kHopfSpeed - 0.25, 2e-3);
  EXPECT_NEAR(b.bifurcations[0].amplitude, std::sqrt(0.5), 0.05);
  EXPECT_NEAR(lowest_stable_speed(b), kHopfSpeed - 0.25, 2e-3);
  // The first orbits: small excursions at the predicted speeds.
  EXPECT_NEAR(b.orbits[0].start(0), 0.05, 1e-12);
  EXPECT_NEAR(b.orbits[1].start(0), 0.10, 1e-12);
  std::printf("[ bautin   ] %zu orbits, %d failed correctors, fold at %.6f (exact %.6f), CPU %.2f s\n",
              b.orbits.size(), b.failed_correctors, b.bifurcations[0].speed_m_per_s,
              kHopfSpeed - 0.25, b.cpu_seconds);

  // Stopped at the first fold: the same fold, two orbits past it, no more.
  opt.stop_at_first_fold = true;
  const OrbitBranch short_branch = continue_from_hopf(s, kNormalFormCoords, start, 0.05, opt);
  EXPECT_EQ(short_branch.stop_reason, "stopped past the first fold (stop at fold)");
  ASSERT_EQ(short_branch.bifurcations.size(), 1u);
  EXPECT_EQ(short_branch.orbits.size(), size_t(short_branch.bifurcations[0].after_orbit) + 3);
  EXPECT_LT(short_branch.orbits.size(), b.orbits.size());
  EXPECT_NEAR(short_branch.bifurcations[0].speed_m_per_s, b.bifurcations[0].speed_m_per_s, 1e-12);
}

// A fold sharp in the scaled plane: with the excursion scaled by 10 (100
// times the radius), the secant near the fold points along V and its
// predictions go past the fold's speed, where the plane's corrector has no
// orbit to find. The fixed-excursion step after a failure
// (ContinuationOptions::excursion_step_after_failure) crosses the fold
// instead of halving the step down to it: every orbit on the closed form,
// round the fold in fewer orbits than without it. The fold at alpha = -1/4:
// the parabola V(a) through the three orbits round it (0.2-0.3 apart in r^2)
// misses by 5.9e-3; refined by one more orbit at the vertex's excursion
// (ContinuationOptions::refine_folds) within 1e-3 (measured 2.2e-4).
TEST(OrbitContinuationBautin, FixedExcursionStepCrossesAFoldTooSharpForThePlane) {
  const FlowSystem s = normal_form(true);
  const HopfStart start = bautin_hopf_start();
  ContinuationOptions opt = bautin_continuation(10.0, 0.05, 0.2);
  opt.max_orbits = 40;
  const OrbitBranch b = continue_from_hopf(s, kNormalFormCoords, start, 0.05, opt);
  double r2_max = 0.0;
  for (const PeriodicOrbit& o : b.orbits) {
    const double r2 = o.start(0) * o.start(0);
    EXPECT_NEAR(o.speed_m_per_s - kHopfSpeed, r2 * r2 - r2, 1e-8) << "r^2 = " << r2;
    r2_max = std::max(r2_max, r2);
  }
  std::printf("[ bautin   ] sharp fold: %zu orbits, %d failed correctors, largest r^2 %.3f, %s\n",
              b.orbits.size(), b.failed_correctors, r2_max, b.stop_reason.c_str());
  EXPECT_GT(b.failed_correctors, 0);  // the plane's corrector did fail
  EXPECT_GT(r2_max, 0.6);             // round the fold (r^2 = 1/2)
  ASSERT_EQ(b.bifurcations.size(), 1u);
  EXPECT_EQ(b.bifurcations[0].kind, OrbitBifurcationKind::fold);
  EXPECT_NEAR(b.bifurcations[0].speed_m_per_s, kHopfSpeed - 0.25, 1e-3);
  ContinuationOptions unrefined = opt;
  unrefined.refine_folds = false;
  const OrbitBranch coarse = continue_from_hopf(s, kNormalFormCoords, start, 0.05, unrefined);
  ASSERT_EQ(coarse.bifurcations.size(), 1u);
  std::printf("[ bautin   ] the fold unrefined %.6f, refined %.6f (exact %.6f)\n",
              coarse.bifurcations[0].speed_m_per_s, b.bifurcations[0].speed_m_per_s,
              kHopfSpeed - 0.25);
  EXPECT_EQ(coarse.orbits.size(), b.orbits.size());  // the extra orbit is not the branch's
  EXPECT_GT(std::abs(coarse.bifurcations[0].speed_m_per_s - (kHopfSpeed - 0.25)),
            5.0 * std::abs(b.bifurcations[0].speed_m_per_s - (kHopfSpeed - 0.25)));

  opt.excursion_step_after_failure = false;
  const OrbitBranch without = continue_from_hopf(s, kNormalFormCoords, start, 0.05, opt);
  ASSERT_EQ(without.bifurcations.size(), 1u);
  std::printf("[ bautin   ] without the fixed-excursion step: %zu orbits, %d failed correctors, "
              "fold at %.6f; with it %.6f (exact %.6f)\n",
              without.orbits.size(), without.failed_correctors,
              without.bifurcations[0].speed_m_per_s, b.bifurcations[0].speed_m_per_s,
              kHopfSpeed - 0.25);
  EXPECT_EQ(without.stop_reason, b.stop_reason);
  EXPECT_LT(b.orbits.size(), without.orbits.size());
}

// A fold whose turn in speed is below the continuation's speed resolution
// (10 x the Newton tolerance x V: here 10 x 2e-3 x 10 = 0.2 m/s, larger than
// the speed steps round the vertex) is still found, by the real multiplier
// passing +1 between a stable and an unstable orbit (the S1002 bogie's
// branch turned by 0.005 m/s over two orbits): one fold, between the two
// orbits where |mu| crosses 1, at alpha = -1/4 to the branch's step.
TEST(OrbitContinuationBautin, FoldFlatterThanTheSpeedResolutionIsFoundByItsMultiplier) {
  const FlowSystem s = normal_form(true);
  const HopfStart start = bautin_hopf_start();
  ContinuationOptions opt = bautin_continuation(0.1, 0.5, 1.0);
  opt.shooting.newton_relative_tolerance = 2e-3;
  const OrbitBranch b = continue_from_hopf(s, kNormalFormCoords, start, 0.05, opt);
  int folds = 0;
  double fold_speed = 0.0;
  for (const OrbitBifurcation& f : b.bifurcations)
    if (f.kind == OrbitBifurcationKind::fold) ++folds, fold_speed = f.speed_m_per_s;
  ASSERT_EQ(folds, 1);
  // The vertex speed changes by ~(step)^2 near the fold: within 0.02 of it.
  EXPECT_NEAR(fold_speed, kHopfSpeed - 0.25, 0.02);
  EXPECT_NEAR(lowest_stable_speed(b), kHopfSpeed - 0.25, 0.02);
  std::printf("[ bautin   ] coarse speed resolution: fold at %.6f (exact %.6f)\n", fold_speed,
              kHopfSpeed - 0.25);
}

// The multiplier against the decay of a perturbed run: on the stable orbit
// r^2 = 0.8 (alpha = 0.64 - 0.8), a start at radius r + d returns after k
// periods at r + mu^k d (to first order in d).
// The bifurcation between two orbits is named by the multiplier that left
// (or entered) the unit circle, not by the one nearest it: the S1002
// vehicle's fold had a weakly damped pair at |mu| 0.996 beside the real
// multiplier that passed +1 (0.99 -> 1.008), and was once named a torus.
TEST(OrbitContinuation, TheCrossingMultiplierIsTheOneThatLeftTheCircle) {
  using C = std::complex<double>;
  auto orbit = [](std::vector<C> mu) {
    PeriodicOrbit o;
    o.floquet_multipliers = Eigen::Map<Eigen::VectorXcd>(mu.data(), Eigen::Index(mu.size()));
    o.trivial_multiplier = 0;
    return o;
  };
  const C pair = std::polar(0.996, 0.5);
  const PeriodicOrbit stable = orbit({1.0, pair, std::conj(pair), 0.99, 0.2});
  const PeriodicOrbit past_fold = orbit({1.0, pair, std::conj(pair), 1.008, 0.2});
  EXPECT_EQ(crossing_multiplier(stable, past_fold, 1e-6), C(1.008));  // losing stability
  EXPECT_EQ(crossing_multiplier(past_fold, stable, 1e-6), C(1.008));  // regaining it
  const C out = std::polar(1.01, 0.5);
  const PeriodicOrbit torus = orbit({1.0, out, std::conj(out), 0.99, 0.2});
  EXPECT_NEAR(std::abs(crossing_multiplier(stable, torus, 1e-6)), 1.01, 1e-15);
  EXPECT_GT(std::abs(crossing_multiplier(stable, torus, 1e-6).imag()), 0.4);
  const PeriodicOrbit doubling = orbit({1.0, pair, std::conj(pair), 0.99, -1.02});
  EXPECT_EQ(crossing_multiplier(stable, doubling, 1e-6), C(-1.02));
  // The trivial multiplier (index 0) never counts, whatever its modulus.
  const PeriodicOrbit trivial_off = orbit({1.5, pair, std::conj(pair), 1.008, 0.2});
  EXPECT_EQ(crossing_multiplier(stable, trivial_off, 1e-6), C(1.008));
}

TEST(OrbitContinuationBautin, MultiplierOfAStableOrbitMatchesThePerturbedRunsDecay) {
  const FlowSystem s = normal_form(true);
  const double r = std::sqrt(0.8), V = kHopfSpeed + 0.64 - 0.8;
  Eigen::VectorXd guess(3);
  guess << r, 0.0, 0.0;
  const PeriodicOrbit o = solve_periodic_orbit(s, kNormalFormCoords, OrbitConstraint::fixed_speed(V),
                                               guess, 1.0, V, tight_shooting());
  ASSERT_TRUE(o.stable);
  const double d = 1e-5;
  Eigen::VectorXd x = o.start;
  x(0) += d;
  FlowOptions plain;
  plain.sensitivities = false;
  plain.relative_tolerance = 1e-11;
  plain.absolute_tolerance = 1e-14;
  const FlowResult run = integrate_flow(s, x, V, 3.0 * o.period_s, plain);
  const double measured = (run.end_state.head(2).norm() - r) / d;
  const double mu3 = std::pow(o.critical_multiplier.real(), 3);
  EXPECT_NEAR(measured, mu3, 2e-3 * std::abs(mu3) + 1e-4);
}

namespace {

struct PreparedModelFlow {
  PreparedScene scene;
  std::vector<int> reduced;
  FlowSystem system;
};

PreparedModelFlow model_flow(const std::string& case_name) {
  PreparedModelFlow p{prepare_scene(std::string(RAILSTAB_CASES_DIR) + "/" + case_name, {}), {}, {}};
  p.system = model_flow_system(p.scene.model, 0.0, &p.reduced);
  return p;
}

double cpu_now() { return double(std::clock()) / CLOCKS_PER_SEC; }

}  // namespace

// The flow's sensitivities against central differences of the flow itself,
// on the thesis bogie at its scene speed over 0.2 s (about a quarter of the slowly
// decaying hunting period) from a state on a settled motion: 1 s of a plain
// run from the steady state with wheelset1 displaced 1 mm (a raw
// displacement would start with the wheels bouncing on the rail, contact
// lost and regained, where the flow is not differentiable). Steps: 1e-6 of
// each state's size (1e-3 floor); the flows at rtol 1e-11, the
// sensitivities at rtol 1e-9. Column-wise error relative to the column's
// norm.
TEST(FlowSensitivity, MonodromyAndSpeedSensitivityMatchCentralDifferencesOfTheFlow) {
  const PreparedModelFlow p = model_flow("thesis_bogie_tangent.toml");
  const FlowSystem& s = p.system;
  const double V = p.scene.speed_m_per_s, T = 0.2;
  const OrbitCoordinates c = wheelset_orbit_coordinates(p.scene.model, p.reduced);
  Eigen::VectorXd start = p.scene.equilibrium.state;
  start(p.reduced[size_t(c.amplitude_state)]) += 1e-3;
  IntegrationOptions settle;
  settle.t_end_s = settle.output_interval_s = 1.0;
  const Trajectory run = integrate(p.scene.model, V, start, settle);
  for (const ContactEvent& e : run.events)  // the start's bounce only
    ASSERT_LT(e.time_s, 0.5) << e.description;
  const Eigen::VectorXd x0 = reduce_state(p.reduced, run.states.back());
  FlowOptions tight;
  tight.relative_tolerance = 1e-11;
  tight.absolute_tolerance = 1e-14;
  tight.sensitivity_relative_tolerance = 1e-9;
  tight.sensitivity_absolute_tolerance = 1e-12;
  const double cpu0 = cpu_now();
  const FlowResult exact = integrate_flow(s, x0, V, T, tight);
  const double cpu_sens = cpu_now() - cpu0;
  // The same derivatives in a second pass along the state's recorded steps
  // (variational_pass.hpp).
  FlowOptions second_pass = tight;
  second_pass.variational = FlowOptions::Variational::second_pass;
  const FlowResult second = integrate_flow(s, x0, V, T, second_pass);
  FlowOptions plain = tight;
  plain.sensitivities = false;
  double worst = 0.0, worst_second = 0.0;
  for (int j = 0; j < s.size; ++j) {
    // 1e-5 (m, rad, m/s, rad/s; relative for the spin rates): the spin
    // rates' integration noise (rtol 1e-11 of 44 rad/s) must stay small
    // against h times the column. The wheelsets' vertical and roll
    // positions compress the Hertz contact (force ~ delta^1.5 over ~0.1 mm):
    // 1e-7 there keeps the truncation error small.
    const std::string& name = s.state_names[size_t(j)];
    const bool hertz = name.find("wheelset") == 0 && (name.ends_with(".z_m") || name.ends_with(".roll_rad"));
    const double h = (hertz ? 1e-7 : 1e-5) * std::max(std::abs(x0(j)), 1.0);
    Eigen::VectorXd up = x0, down = x0;
    up(j) += h, down(j) -= h;
    const Eigen::VectorXd fd = (integrate_flow(s, up, V, T, plain).end_state -
                                integrate_flow(s, down, V, T, plain).end_state) / (2.0 * h);
    const double err = (fd - exact.state_sensitivity.col(j)).norm() /
                       std::max(exact.state_sensitivity.col(j).norm(), 1e-12);
    worst_second = std::max(worst_second, (fd - second.state_sensitivity.col(j)).norm() /
                                              std::max(second.state_sensitivity.col(j).norm(), 1e-12));
    if (err > 1e-3)
      std::printf("  column %d (%s): error %.2e, |exact| %.2e, |fd| %.2e, h %.1e\n", j,
                  s.state_names[size_t(j)].c_str(), err, exact.state_sensitivity.col(j).norm(),
                  fd.norm(), h);
    worst = std::max(worst, err);
  }
  const double hV = 1e-4;
  const Eigen::VectorXd fdV = (integrate_flow(s, x0, V + hV, T, plain).end_state -
                               integrate_flow(s, x0, V - hV, T, plain).end_state) / (2.0 * hV);
  const double errV = (fdV - exact.speed_sensitivity).norm() / exact.speed_sensitivity.norm();
  const double errV_second = (fdV - second.speed_sensitivity).norm() / second.speed_sensitivity.norm();
  std::printf("[ bogie    ] %d states: monodromy vs central differences %.2e (worst column), "
              "d phi/dV %.2e; flow with sensitivities %.3f s CPU, %ld steps, %ld Jacobians; "
              "second pass %.2e, %.2e, %.3f s CPU, %ld + %ld steps\n",
              s.size, worst, errV, cpu_sens, exact.steps, exact.jacobian_evaluations, worst_second,
              errV_second, second.cpu_seconds, second.steps - second.variational_steps,
              second.variational_steps);
  // The differences' own error (truncation and noise, see the steps) is
  // the limit here, not X's (rtol 1e-9).
  EXPECT_LT(worst, 2e-3);
  EXPECT_LT(errV, 1e-5);
  EXPECT_LT(worst_second, 2e-3);
  EXPECT_LT(errV_second, 1e-5);
  EXPECT_GT(second.variational_steps, 0);
  // The state is the plain flow's (the second pass does not touch it).
  EXPECT_EQ((second.end_state - integrate_flow(s, x0, V, T, plain).end_state).cwiseAbs().maxCoeff(), 0.0);
}

// The second pass's state between the recorded steps: cubic Hermite
// interpolation is exact for a cubic (x = t^3 - 2 t, x' = 3 t^2 - 2, and a
// constant), on uneven steps, at the steps' ends and clamped outside.
TEST(FlowSensitivity, RecordedTrajectoryInterpolatesACubicExactly) {
  RecordedTrajectory r;
  for (double t : {0.0, 0.1, 0.35, 0.4, 1.0}) {
    r.times_s.push_back(t);
    r.states.push_back(Eigen::Vector2d(t * t * t - 2.0 * t, 5.0));
    r.rates.push_back(Eigen::Vector2d(3.0 * t * t - 2.0, 0.0));
  }
  Eigen::VectorXd x;
  for (double t : {0.0, 0.05, 0.1, 0.2, 0.37, 0.4, 0.99, 1.0}) {
    r.state_at(t, x);
    EXPECT_NEAR(x(0), t * t * t - 2.0 * t, 1e-15) << t;
    EXPECT_NEAR(x(1), 5.0, 1e-15) << t;
  }
  r.state_at(1.5, x);
  EXPECT_NEAR(x(0), -1.0, 1e-15);
  r.state_at(-0.5, x);
  EXPECT_NEAR(x(0), 0.0, 1e-15);
}

// The spin angles are the reduced state's only omission, and f does not
// depend on them (so the reduced flow is the model's).
TEST(FlowSensitivity, ReducedModelDropsOnlyTheSpinAnglesWhichDoNotEnterF) {
  const PreparedModelFlow p = model_flow("thesis_bogie_tangent.toml");
  const Model& m = p.scene.model;
  EXPECT_EQ(int(p.reduced.size()), m.state_size() - 2);  // two wheelsets
  Eigen::VectorXd full = p.scene.equilibrium.state;
  full(3) += 0.0;
  Eigen::VectorXd f_reduced;
  p.system.rhs(reduce_state(p.reduced, full), 30.0, f_reduced);
  for (int k = 0; k < m.state_size(); ++k)
    if (std::find(p.reduced.begin(), p.reduced.end(), k) == p.reduced.end()) {
      Eigen::VectorXd turned = full;
      turned(k) += 1.234;  // any spin angle
      const Eigen::VectorXd f = rhs(m, 30.0, 0.0, turned);
      EXPECT_EQ((reduce_state(p.reduced, f) - f_reduced).cwiseAbs().maxCoeff(), 0.0) << m.state_name(k);
    }
}

namespace {

struct ThesisBranchStart {
  PreparedModelFlow flow;
  CriticalSpeedResult critical;
  HopfCriticality hopf;
  OrbitCoordinates coords;
  HopfStart start;
  OrbitBranch first_two;  // the branch's first two orbits, a = 0.05 and 0.1 mm
  double first_two_cpu_s = 0.0;
};

const ThesisBranchStart& thesis_vehicle_start() {
  static const ThesisBranchStart t = [] {
    ThesisBranchStart s{model_flow("thesis_vehicle_tangent.toml"), {}, {}, {}, {}, {}, 0.0};
    CriticalSpeedOptions opt;
    opt.from_m_per_s = 80.0;
    opt.to_m_per_s = 130.0;
    opt.grid_step_m_per_s = 5.0;
    opt.tolerance_m_per_s = 1e-6;
    s.critical = find_critical_speed(s.flow.scene.model, s.flow.scene.equilibrium.state,
                                     s.flow.scene.speed_m_per_s, opt);
    s.hopf = hopf_criticality(s.flow.scene.model, s.critical);
    s.coords = wheelset_orbit_coordinates(s.flow.scene.model, s.flow.reduced);
    s.start = model_hopf_start(s.flow.scene.model, s.flow.reduced, s.critical.at_critical.equilibrium.state,
                               s.hopf, s.coords);
    ContinuationOptions copt;
    copt.max_orbits = 2;
    const double cpu0 = cpu_now();
    s.first_two = continue_from_hopf(s.flow.system, s.coords, s.start, 5e-5, copt);
    s.first_two_cpu_s = cpu_now() - cpu0;
    return s;
  }();
  return t;
}

}  // namespace

// The branch's first orbits at excursions a = 0.05 and 0.1 mm of wheelset1:
// V(a) = V_c + (a / k)^2 and T(a) = T0 + O(a^2), so (4 V1 - V2) / 3 and
// (4 T1 - T2) / 3 are the zero-amplitude limits (error O(a^4)).
TEST(OrbitContinuationThesisVehicle, BranchStartsAtTheHopfPointFollowsTheSquareRootLawAndIsATimeDomainSolution) {
  const ThesisBranchStart& t = thesis_vehicle_start();
  ASSERT_TRUE(t.critical.critical_speed_found);
  ASSERT_EQ(t.hopf.kind, HopfKind::supercritical);
  const OrbitBranch& b = t.first_two;
  const double cpu = t.first_two_cpu_s;
  ASSERT_GE(b.orbits.size(), 2u);
  const PeriodicOrbit &o1 = b.orbits[0], &o2 = b.orbits[1];
  const double Vc = t.critical.critical_speed_m_per_s;
  const double T0 = 2.0 * kPi / t.hopf.hopf.eigenvalue.imag();
  const double V0 = (4.0 * o1.speed_m_per_s - o2.speed_m_per_s) / 3.0;
  const double Tlim = (4.0 * o1.period_s - o2.period_s) / 3.0;
  EXPECT_NEAR(V0, Vc, 0.01);
  EXPECT_NEAR(Tlim, T0, 1e-6 * T0);
  for (const PeriodicOrbit* o : {&o1, &o2}) {
    const double a = o->amplitude(t.coords.amplitude_state);
    const double predicted = predicted_amplitude(t.hopf, "wheelset1.y_m", o->speed_m_per_s);
    EXPECT_NEAR(a, predicted, 0.01 * a) << "at " << o->speed_m_per_s << " m/s";
    // Supercritical: the small cycles are stable, their multiplier
    // exp(-2 Re(lambda(V)) T) within 1e-6 of 1 this near V_c: not above it.
    EXPECT_LT(std::abs(o->critical_multiplier), 1.0 + 1e-6);
  }
  std::printf("[ thesis   ] Hopf %.6f m/s, T0 %.8f s; orbits at a = %.3f, %.3f mm: V - Vc = %.3e, "
              "%.3e m/s, limit V0 - Vc %.2e m/s, T %.8f s; %zu orbits in %.2f s CPU (%ld steps, "
              "%ld Jacobians for the first)\n",
              Vc, T0, 1e3 * o1.amplitude(t.coords.amplitude_state),
              1e3 * o2.amplitude(t.coords.amplitude_state), o1.speed_m_per_s - Vc,
              o2.speed_m_per_s - Vc, V0 - Vc, Tlim, b.orbits.size(), cpu, o1.integration_steps,
              o1.jacobian_evaluations);
  // An orbit of the branch is a solution of the product's time domain: a
  // plain run (integrate(), CVODE BDF at rtol 1e-10) from the second
  // orbit's start returns to it after one period within 1e-6 of the
  // amplitude. (One test: ctest runs every test in its own process, and the
  // orbits are the expensive part.)
  {
    const PeriodicOrbit& o = b.orbits.back();
    IntegrationOptions io;
    io.t_end_s = o.period_s;
    io.output_interval_s = o.period_s;
    io.relative_tolerance = 1e-10;
    io.absolute_tolerance = 1e-13;
    const Trajectory run = integrate(t.flow.scene.model, o.speed_m_per_s,
                                     embed_state(t.flow.scene.model, t.flow.reduced, o.start), io);
    ASSERT_TRUE(run.stopped_early.empty()) << run.stopped_early;
    const Eigen::VectorXd back = reduce_state(t.flow.reduced, run.states.back());
    const double scale = o.amplitude.cwiseAbs().maxCoeff();
    EXPECT_LT((back - o.start).cwiseAbs().maxCoeff(), 1e-6 * scale);
  }
}
