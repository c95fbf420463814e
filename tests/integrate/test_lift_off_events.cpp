// Wheel lift-off and touch-down are events, not errors: every integrator
// records them at the time the penetration crosses zero, goes on through
// them, and stops at the first one only on request.
#include <railstab/equilibrium/equilibrium.hpp>
#include <railstab/setup/build_model.hpp>
#include <railstab/equilibrium/equilibrium.hpp>
#include "integrate/integration_scenes.hpp"
#include <railstab/integrate/integrator.hpp>
#include <railstab/model/equations_of_motion.hpp>

#include <gtest/gtest.h>

#include <cstdio>
#include <regex>

using namespace railstab;

namespace {

// The lone wheelset at its rolling equilibrium, thrown upwards (0.05 m/s)
// and rolled (0.1 rad/s, left side up): the left wheel leaves the rail
// after ~0.16 ms; the undamped wheelset then bounces, its wheels losing and
// regaining contact every few milliseconds.
struct ThrownWheelset {
  SceneSpec spec = test::lone_knife_edge_wheelset();
  double V = spec.speed_m_per_s;
  Model model = build_model(spec);
  Eigen::VectorXd x0;
  ThrownWheelset() {
    x0 = solve_equilibrium(model, V, lowered_nominal_state(model, V)).state;
    const int n = model.n_coordinates;
    x0(n + model.bodies[0].state_index[int(CoordinateIndex::z)]) += 0.05;
    x0(n + model.bodies[0].state_index[int(CoordinateIndex::roll)]) += 0.1;
  }
};

struct Crossing {
  double time_s;
  int side;
  bool lost;
};

// Zero crossings of each wheel's penetration (from rhs() details, not from
// the integrator's root functions) in a fine-output tight-tolerance run,
// located by linear interpolation between outputs 1 us apart.
std::vector<Crossing> fine_crossings(const Model& model, double V, const Eigen::VectorXd& x0, double t_end) {
  IntegrationOptions o;
  o.t_end_s = t_end;
  o.output_interval_s = 1e-6;
  o.relative_tolerance = 1e-11;
  o.absolute_tolerance = 1e-14;
  const Trajectory traj = integrate(model, V, x0, o);
  std::vector<Crossing> out;
  std::vector<double> previous;
  for (size_t i = 0; i < traj.times_s.size(); ++i) {
    EvaluationDetails d;
    rhs(model, V, traj.times_s[i], traj.states[i], &d);
    if (previous.empty()) previous.assign(d.contacts.size(), 0.0);
    for (size_t w = 0; w < d.contacts.size(); ++w) {
      const double p = d.contacts[w].wheel.penetration_m;
      if (i > 0 && (p > 0.0) != (previous[w] > 0.0)) {
        const double t0 = traj.times_s[i - 1], t1 = traj.times_s[i];
        out.push_back({t0 + (t1 - t0) * previous[w] / (previous[w] - p), d.contacts[w].wheel.side,
                       p <= 0.0});
      }
      previous[w] = p;
    }
  }
  return out;
}

}  // namespace

class LiftOff : public ::testing::TestWithParam<IntegratorKind> {};

// Event times against the fine run's crossings. Tolerance 1e-7 s: the
// linear interpolation between 1 us outputs is good to ~1e-11 s (curvature
// of the penetration ~100 m/s^2, slope ~0.1 m/s), the integrators at rtol
// 1e-8 place their roots to within 1e-9..1.2e-8 s (measured); 1e-7 s is 1e-5 of the
// ~10 ms between events, so a missed, extra or misplaced event fails.
TEST_P(LiftOff, EventsAtThePenetrationZeroCrossings) {
  const ThrownWheelset w;
  const double t_end = 0.03;
  const std::vector<Crossing> expected = fine_crossings(w.model, w.V, w.x0, t_end);
  ASSERT_GE(expected.size(), 6u) << "the scene no longer bounces";
  ASSERT_EQ(expected.front().side, 1);
  ASSERT_TRUE(expected.front().lost);

  IntegrationOptions o;
  o.kind = GetParam();
  o.t_end_s = t_end;
  o.output_interval_s = 0.01;
  o.relative_tolerance = 1e-8;
  o.absolute_tolerance = 1e-11;
  const Trajectory traj = integrate(w.model, w.V, w.x0, o);
  EXPECT_TRUE(traj.stopped_early.empty()) << traj.stopped_early;
  EXPECT_NEAR(traj.times_s.back(), t_end, 1e-12);  // lift-off does not end the run
  EXPECT_EQ(traj.times_s.size(), 4u);  // events add no output points
  ASSERT_EQ(traj.events.size(), expected.size());
  double worst = 0.0;
  for (size_t i = 0; i < expected.size(); ++i) {
    const ContactEvent& e = traj.events[i];
    EXPECT_EQ(e.side, expected[i].side) << "event " << i << ": " << e.description;
    EXPECT_EQ(e.kind, expected[i].lost ? ContactEvent::Kind::lost : ContactEvent::Kind::regained)
        << "event " << i << ": " << e.description;
    EXPECT_EQ(e.body, 0);
    EXPECT_NEAR(e.time_s, expected[i].time_s, 1e-7) << e.description;
    worst = std::max(worst, std::abs(e.time_s - expected[i].time_s));
  }
  std::printf("  %-12s %zu events, max |t_event - t_crossing| = %.2g s\n",
              integrator_name(GetParam()).c_str(), traj.events.size(), worst);
  EXPECT_EQ(traj.events.front().description.rfind("wheelset left wheel lost contact at t = ", 0),
            0u)
      << traj.events.front().description;
}

INSTANTIATE_TEST_SUITE_P(AllIntegrators, LiftOff,
                         ::testing::ValuesIn(all_integrator_kinds()),
                         [](const ::testing::TestParamInfo<IntegratorKind>& info) {
                           return integrator_name(info.param);
                         });

// On request the run ends at the first loss of contact, with the message
// "<wheelset> <left|right> wheel lost contact at t = X s" and the state there.
TEST(LiftOff, StopOnLiftOffEndsTheRunWithTheMessage) {
  const ThrownWheelset w;
  IntegrationOptions o;
  o.t_end_s = 0.03;
  o.output_interval_s = 0.01;
  o.relative_tolerance = 1e-8;
  o.absolute_tolerance = 1e-11;
  o.stop_on_lift_off = true;
  const Trajectory traj = integrate(w.model, w.V, w.x0, o);
  EXPECT_TRUE(std::regex_match(traj.stopped_early,
                               std::regex(R"(wheelset left wheel lost contact at t = [0-9.e+-]+ s)")))
      << traj.stopped_early;
  ASSERT_EQ(traj.events.size(), 1u);
  EXPECT_EQ(traj.stopped_early, traj.events.front().description);
  // The run ends at the event, with the state there: the left wheel's
  // penetration is zero to the root finder's resolution.
  EXPECT_DOUBLE_EQ(traj.times_s.back(), traj.events.front().time_s);
  EXPECT_NEAR(traj.times_s.back(), 1.566e-4, 1e-7);
  EvaluationDetails d;
  rhs(w.model, w.V, traj.times_s.back(), traj.states.back(), &d);
  EXPECT_NEAR(d.contacts[0].wheel.penetration_m, 0.0, 1e-12);
}

// A wheel already in the air at the start is reported (root finding only
// sees sign changes), and stops the run at once on request. The wheelset
// lifted 1 mm falls freely until both wheels touch down together: for the
// knife-edge cone at y = roll = yaw = 0 the penetration is (r0 - z) cos(g),
// so the fall height is -penetration / cos(g) and t = sqrt(2 h / g_grav).
TEST(LiftOff, WheelsOutOfContactAtTheStartAreReported) {
  ThrownWheelset w;
  const int n = w.model.n_coordinates;
  const int kz = w.model.bodies[0].state_index[int(CoordinateIndex::z)];
  w.x0(kz) += 0.001;
  w.x0.tail(n).setZero();
  w.x0(n + w.model.bodies[0].state_index[int(CoordinateIndex::pitch)]) =
      w.model.bodies[0].prescribed_rate(int(CoordinateIndex::pitch),
                                        w.V);  // rolling at V
  EvaluationDetails d;
  rhs(w.model, w.V, 0.0, w.x0, &d);
  const double fall_m = -d.contacts[0].wheel.penetration_m / std::cos(0.1);
  ASSERT_GT(fall_m, 9e-4);
  const double touch_down_s = std::sqrt(2.0 * fall_m / 9.81);

  IntegrationOptions o;
  o.t_end_s = 0.05;
  o.relative_tolerance = 1e-10;
  o.absolute_tolerance = 1e-13;
  const Trajectory free_fall = integrate(w.model, w.V, w.x0, o);
  ASSERT_GE(free_fall.events.size(), 4u);
  EXPECT_EQ(free_fall.events[0].kind, ContactEvent::Kind::out_of_contact_at_start);
  EXPECT_EQ(free_fall.events[1].kind, ContactEvent::Kind::out_of_contact_at_start);
  EXPECT_EQ(free_fall.events[0].side, 1);
  EXPECT_EQ(free_fall.events[1].side, -1);
  for (int i : {2, 3}) {
    EXPECT_EQ(free_fall.events[size_t(i)].kind, ContactEvent::Kind::regained);
    // Free fall is a parabola: the integrator is exact to its tolerance, the
    // root finder to ~1e-14 s; 1e-9 s leaves room for both.
    EXPECT_NEAR(free_fall.events[size_t(i)].time_s, touch_down_s, 1e-9);
  }

  o.stop_on_lift_off = true;
  const Trajectory stopped = integrate(w.model, w.V, w.x0, o);
  EXPECT_EQ(stopped.stopped_early,
            "wheelset left wheel lost contact at t = 0 s (out of contact in the initial state)");
  EXPECT_EQ(stopped.times_s.size(), 1u);
}
