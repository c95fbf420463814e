// Steady curving with flange contact (curving/steady_curving.hpp,
// docs/steady_curving.md) on the coach of cases/coach_s1002_curve.toml and
// the thesis vehicle on S1002/UIC60, against references no one tuned to:
// - the cant deficiency h_d = D V^2 / (g R) - h and its inverse, by hand;
// - the quasi-static lateral force balance: the rails' lateral forces on
//   all wheels along the track plane equal m a_y, a_y = V^2 / R cos(phi) -
//   g sin(phi), sin(phi) = h / D (m (V^2/R - g h/D) to first order);
// - a continuation result is a Newton solution of its own point (Newton
//   from it, to a tolerance 10x tighter, moves it by less than 1e-9);
// - where Newton alone converges the continuation finds the same state;
// - a limit said to be physical is physical: the wheel it names has Y/Q at
//   Nadal's limit on its flange, recomputed here from the state.
// Run times (Release, one core of a loaded 2-core machine) are stated per
// test; none is heavy (each below 5 s).
#include <railstab/contact_geometry/characteristic_functions.hpp>
#include <railstab/curving/steady_curving.hpp>
#include <railstab/equilibrium/arclength_continuation.hpp>
#include <railstab/equilibrium/equilibrium.hpp>
#include <railstab/model/wheel_forces.hpp>
#include <railstab/setup/build_model.hpp>
#include <railstab/setup/prepare_scene.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace railstab;

namespace {

const std::string kCoach = std::string(RAILSTAB_CASES_DIR) + "/coach_s1002_curve.toml";
const std::string kThesis = std::string(RAILSTAB_CASES_DIR) + "/thesis_vehicle_s1002_curve.toml";

Model model_of(const std::string& path, std::vector<SceneValueSetting> values = {},
               std::optional<double> reference_m = std::nullopt) {
  SceneOverrides o;
  o.values = std::move(values);
  o.reference_arc_length_m = reference_m;
  return build_model(load_scene_with_overrides(path, o));
}

EquilibriumOptions newton_only(double tolerance = 1e-7) {
  EquilibriumOptions eo;
  eo.pseudo_transient_fallback = false;
  eo.acceleration_tolerance = tolerance;
  return eo;
}

// |sum of the rails' lateral forces - m a_y| against m a_y. The tolerance,
// 1e-3 of m a_y: the bodies sit off the centreline by up to 0.05 m, which
// changes their path radius by 3e-5 of R, and their track frames are turned
// against each other by up to (vehicle length) / R = 14 mrad at R 1500 m
// (86 mrad at 250 m), which turns a part of the longitudinal suspension
// forces into each frame's lateral direction (measured: 7e-5 at R 1500 m).
void expect_force_balance(const CurvingPoint& p) {
  const double m_a = p.mass_times_lateral_acceleration_N;
  EXPECT_NEAR(p.rail_lateral_force_N, m_a, 1e-3 * std::abs(m_a) + 50.0)
      << "cant deficiency " << p.state.cant_deficiency_m;
}

}  // namespace

// By hand: R 1500 m, h 150 mm, V 57.5 m/s (the issue's point):
// 1.5 * 57.5^2 / (9.81 * 1500) - 0.15 = 4959.375 / 14715 - 0.15 = 0.187029...
TEST(CurvingConditions, CantDeficiencyAndItsSpeedByHand) {
  const double D = 1.5, g = 9.81;
  const CurvingCondition left{1.0 / 1500.0, 0.15, 57.5};
  EXPECT_NEAR(cant_deficiency_m(left, D, g), 4959.375 / 14715.0 - 0.15, 1e-15);
  EXPECT_NEAR(speed_for_cant_deficiency(1.0 / 1500.0, 0.15, 4959.375 / 14715.0 - 0.15, D, g), 57.5,
              1e-12);
  // A right-hand curve with the left rail raised: the same.
  const CurvingCondition right{-1.0 / 1500.0, -0.15, 57.5};
  EXPECT_NEAR(cant_deficiency_m(right, D, g), cant_deficiency_m(left, D, g), 1e-15);
  // 300 mm at R 1500 m: V = sqrt(9.81 * 1500 * 0.45 / 1.5) = 66.44 m/s.
  EXPECT_NEAR(speed_for_cant_deficiency(1.0 / 1500.0, 0.15, 0.30, D, g),
              std::sqrt(9.81 * 1500.0 * 0.45 / 1.5), 1e-12);
  // A cant excess beyond the cant needs a speed of zero or less.
  EXPECT_THROW(speed_for_cant_deficiency(1.0 / 1500.0, 0.15, -0.15, D, g), std::invalid_argument);
  EXPECT_THROW(speed_for_cant_deficiency(0.0, 0.0, 0.1, D, g), std::invalid_argument);
}

// Issue 23: the coach at 57.5 m/s (187 mm) in R 1500 m, 150 mm cant. Newton
// from the nominal position fails there (the issue's message); the
// continuation finds the steady state, and it is a Newton solution of that
// point. About 1.5 s.
TEST(SteadyCurvingCoach, IssuePointFoundByContinuationIsNewtonsSolutionThere) {
  const Model scene = model_of(kCoach);
  const CurvingCondition c{1.0 / 1500.0, 0.15, 57.5};
  const Model arc = uniform_arc_model(scene, c.curvature_per_m, c.cant_m);
  EXPECT_THROW(solve_equilibrium(arc, 57.5, lowered_nominal_state(arc, 57.5), newton_only()),
               EquilibriumError);
  const SteadyCurvingState s = solve_steady_curving(scene, c);
  EXPECT_NE(s.method.find("continuation"), std::string::npos) << s.method;
  EXPECT_LE(s.equilibrium.max_acceleration, 1e-7);
  // Newton from the continuation's result at the same point, 10x tighter
  // (1e-8 m/s^2: the rounding floor of the residual is ~5e-9 here).
  const EquilibriumResult polished = solve_equilibrium(arc, 57.5, s.equilibrium.state, newton_only(1e-8));
  EXPECT_LE((polished.state - s.equilibrium.state).cwiseAbs().maxCoeff(), 1e-9);
  const CurvingPoint p = curving_point(scene, s, 1.0);
  expect_force_balance(p);
  // The steady state there lies on the branch between the two folds that
  // bound the tread branch (~183 mm) and the flange branch (~280 mm): it is
  // unstable (divergent), and said so (the eigenvalues: tests/eigen).
  EXPECT_FALSE(p.stability.stable()) << p.stability.describe();
  EXPECT_GE(p.stability.divergent, 1);
}

// `equilibrium` on the scene's own track (prepare_scene) finds the same
// steady state at 57.5 m/s as the uniform arc: the vehicle is 700 m inside
// the arc. Both are Newton solutions to 1e-7 m/s^2 of the same equations
// (up to the rounding of the track frames): equal to 1e-8 m, rad, rad/s.
// About 2 s.
TEST(SteadyCurvingCoach, EquilibriumCommandReachesTheIssuePoint) {
  SceneOverrides o;
  o.speed_m_per_s = 57.5;
  const PreparedScene p = prepare_scene(kCoach, o);
  const SteadyCurvingState s =
      solve_steady_curving(p.model, condition_at_reference(p.model, 57.5));
  EXPECT_LE((p.equilibrium.state - s.equilibrium.state).cwiseAbs().maxCoeff(), 1e-8);
}

// From cant excess (-100 mm) to 300 mm cant deficiency in 50 mm steps, each
// point continued from the previous one: every point is found, balances
// its lateral forces and stays within Nadal's limit (R 1500 m is a wide
// curve: Y/Q stays below 0.4). About 2 s.
TEST(SteadyCurvingCoach, SweepFromCantExcessToThreeHundredMillimetres) {
  const Model scene = model_of(kCoach);
  std::vector<double> h_d;
  for (int i = -2; i <= 6; ++i) h_d.push_back(0.05 * i);
  const CurvingSweep sweep =
      sweep_steady_curving(scene, CurvingSweepKind::cant_deficiency, h_d, 1500.0, 1.0);
  ASSERT_EQ(sweep.points.size(), h_d.size()) << sweep.physical_limit;
  EXPECT_TRUE(sweep.physical_limit.empty());
  for (size_t i = 0; i < h_d.size(); ++i) {
    const CurvingPoint& p = sweep.points[i];
    EXPECT_NEAR(p.state.cant_deficiency_m, h_d[i], 1e-12);
    EXPECT_LE(p.state.equilibrium.max_acceleration, 1e-7);
    expect_force_balance(p);
    EXPECT_TRUE(p.nadal_warning.empty()) << p.nadal_warning;
  }
  // Below the tread branch's fold (~183 mm) every state is stable; at
  // 300 mm the stable state is the one with the trailing wheelsets on
  // their flanges (found from the nominal position: the continued one is
  // unstable there).
  for (size_t i = 0; i < h_d.size(); ++i)
    if (h_d[i] < 0.18) {
      EXPECT_TRUE(sweep.points[i].stability.stable()) << h_d[i];
    }
  const CurvingPoint& last = sweep.points.back();
  EXPECT_TRUE(last.stability.stable()) << last.stability.describe();
  EXPECT_TRUE(last.wheelsets[1].right_flange || last.wheelsets[3].right_flange);
  // At 300 mm the vehicle needs 1.95 m/s^2 in the track plane.
  EXPECT_NEAR(sweep.points.back().lateral_acceleration_m_per_s2,
              std::pow(speed_for_cant_deficiency(1.0 / 1500.0, 0.15, 0.3, 1.5, 9.81), 2) / 1500.0 *
                      std::sqrt(1.0 - 0.01) - 9.81 * 0.1,
              1e-12);
}

// Where Newton from the previous point converges, the sweep does not use the
// continuation; the continuation to the same point (forced here, in speed
// from 45 m/s) ends on the same steady state. Both solved to 1e-8 m/s^2:
// equal to 1e-9. About 1 s.
TEST(SteadyCurvingCoach, SameStateWithAndWithoutContinuation) {
  const Model scene = model_of(kCoach);
  SteadyCurvingOptions tight;
  tight.acceleration_tolerance = 1e-8;
  const SteadyCurvingState newton =
      solve_steady_curving(scene, {1.0 / 1500.0, 0.15, 50.0}, std::nullopt, tight);
  EXPECT_EQ(newton.method, "Newton");
  const Model arc = uniform_arc_model(scene, 1.0 / 1500.0, 0.15);
  const EquilibriumResult start =
      solve_equilibrium(arc, 45.0, lowered_nominal_state(arc, 45.0), newton_only(1e-8));
  SpeedPath path(arc, 45.0, 50.0);
  ArclengthOptions ao;
  ao.acceleration_tolerance = 1e-8;
  const ArclengthResult r = continue_by_arclength(path, start.state, ao);
  ASSERT_TRUE(r.reached) << r.failure;
  EXPECT_GT(r.steps, 1);
  EXPECT_LE((r.end.state - newton.equilibrium.state).cwiseAbs().maxCoeff(), 1e-9);
}

// R 250 m (150 mm cant) at 150 mm cant deficiency, without a known state:
// Newton from the nominal position, or the continuation from 5 m/s. The
// leading wheelset runs on its outer flange. About 1 s.
TEST(SteadyCurvingCoach, TightCurveOfTwoHundredFiftyMetres) {
  const Model scene = model_of(kCoach);
  const double V = speed_for_cant_deficiency(1.0 / 250.0, 0.15, 0.15, 1.5, 9.81);
  const SteadyCurvingState s = solve_steady_curving(scene, {1.0 / 250.0, 0.15, V});
  const CurvingPoint p = curving_point(scene, s, 1.0);
  expect_force_balance(p);
  EXPECT_TRUE(p.wheelsets.front().right_flange);  // the outer wheel of a left-hand curve
  EXPECT_GE(p.wheelsets.front().right.max_contact_angle_rad, kFlangeContactAngle_rad);
}

// The thesis vehicle on S1002 (R 1000 m, 50 mm cant at arc length 2000 m):
// 300 mm cant deficiency, and R 250 m at 150 mm. About 2 s.
TEST(SteadyCurvingThesisVehicle, ThreeHundredMillimetresAndTwoHundredFiftyMetres) {
  const Model scene = model_of(kThesis, {}, 2000.0);
  const double V300 = speed_for_cant_deficiency(1.0 / 1000.0, 0.05, 0.30, 1.5, 9.81);
  const SteadyCurvingState s300 = solve_steady_curving(scene, {1.0 / 1000.0, 0.05, V300});
  EXPECT_NEAR(s300.cant_deficiency_m, 0.30, 1e-12);
  expect_force_balance(curving_point(scene, s300, 1.0));
  const double V250 = speed_for_cant_deficiency(1.0 / 250.0, 0.05, 0.15, 1.5, 9.81);
  const SteadyCurvingState s250 = solve_steady_curving(scene, {1.0 / 250.0, 0.05, V250});
  const CurvingPoint p250 = curving_point(scene, s250, 1.0);
  expect_force_balance(p250);
  EXPECT_TRUE(p250.wheelsets.front().right_flange);
}

// With a friction coefficient of 1.0 Nadal's limit falls to
// (tan 70 deg - 1) / (1 + tan 70 deg) = 0.467, below the leading wheel's
// Y/Q in R 250 m: no steady state physically. The statement names the
// wheel and its forces, and it is true of the state it comes with.
// About 1 s.
TEST(SteadyCurvingLimit, BeyondNadalTheStatementNamesTheWheelAndIsTrue) {
  const Model scene = model_of(kCoach, {{"contacts.s1002_uic60.friction_coefficient", 1.0}});
  const double V = speed_for_cant_deficiency(1.0 / 250.0, 0.15, 0.0, 1.5, 9.81);
  try {
    solve_steady_curving(scene, {1.0 / 250.0, 0.15, V});
    FAIL() << "a steady state beyond Nadal's limit was accepted";
  } catch (const CurvingError& e) {
    const std::string what = e.what();
    EXPECT_TRUE(e.physical) << what;
    EXPECT_NE(what.find("no steady state physically"), std::string::npos) << what;
    EXPECT_NE(what.find("Nadal's limit"), std::string::npos) << what;
    EXPECT_NE(what.find("flange climbing"), std::string::npos) << what;
    EXPECT_NE(what.find(" kN"), std::string::npos) << what;
    ASSERT_TRUE(e.last_converged.has_value());
    const CurvingCondition& c = e.last_converged->condition;
    const Model arc = uniform_arc_model(scene, c.curvature_per_m, c.cant_m);
    bool climbing = false;
    for (const WheelForces& w :
         wheel_forces(arc, c.speed_m_per_s, 0.0, e.last_converged->equilibrium.state)) {
      const double limit = (std::tan(w.flange_angle_rad) - 1.0) / (1.0 + std::tan(w.flange_angle_rad));
      if (w.y_over_q && w.nadal_limit) {
        EXPECT_NEAR(*w.nadal_limit, limit, 1e-12);
      }
      climbing = climbing || (w.y_over_q && *w.y_over_q >= limit &&
                              w.max_contact_angle_rad >= kFlangeContactAngle_rad);
    }
    EXPECT_TRUE(climbing);
  }
}

// A continuation that is stopped short (3 steps allowed) fails with the
// last converged point in the message, and carries it. About 1 s.
TEST(SteadyCurvingLimit, SolverFailureNamesTheLastConvergedPoint) {
  const Model scene = model_of(kCoach);
  SteadyCurvingOptions options;
  options.continuation.max_steps = 3;
  try {
    solve_steady_curving(scene, {1.0 / 1500.0, 0.15, 57.5}, std::nullopt, options);
    FAIL() << "3 steps reached 57.5 m/s from 5 m/s";
  } catch (const CurvingError& e) {
    const std::string what = e.what();
    EXPECT_FALSE(e.physical) << what;
    EXPECT_NE(what.find("the last converged point towards the target: V = "), std::string::npos)
        << what;
    EXPECT_NE(what.find("cant deficiency"), std::string::npos) << what;
    EXPECT_NE(what.find("R = "), std::string::npos) << what;
    ASSERT_TRUE(e.last_converged.has_value());
    EXPECT_LT(e.last_converged->condition.speed_m_per_s, 57.5);
    EXPECT_GT(e.last_converged->condition.speed_m_per_s, 5.0);
  }
}
