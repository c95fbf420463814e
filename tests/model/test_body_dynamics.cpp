// Invariants of the rigid-body equations in moving track frames.
#include <railstab/equilibrium/equilibrium.hpp>
#include <railstab/setup/build_model.hpp>
#include <railstab/integrate/integrator.hpp>
#include <railstab/kinematics/body_motion.hpp>
#include <railstab/model/energy.hpp>
#include <railstab/model/equations_of_motion.hpp>
#include "model/scene_builders.hpp"

#include <gtest/gtest.h>

#include <random>

using namespace railstab;

namespace {

IntegrationOptions tight(double t_end) {
  IntegrationOptions o;
  o.t_end_s = t_end;
  o.output_interval_s = t_end / 20;
  o.relative_tolerance = 1e-10;
  o.absolute_tolerance = 1e-12;
  return o;
}

}  // namespace

// A free body with no forces on tangent track moves with constant velocity
// in W and keeps its angular momentum: its coordinates relative to the track
// frame (moving at V) drift linearly.
TEST(BodyDynamics, FreeBodyOnTangentKeepsConstantVelocity) {
  SceneSpec s;
  s.name = "free";
  s.speed_m_per_s = 10.0;
  s.gravity_m_per_s2 = 0.0;
  s.reference_arc_length_m = 10.0;
  s.track = test::straight_track();
  s.bodies.push_back(test::rigid_body("body", 0.0, 1.0));
  s.bodies[0].initial_rate = {0.3, -0.2, 0.1, 0.0, 0.0, 0.0};
  const Model model = build_model(s);
  const Trajectory traj = integrate(model, s.speed_m_per_s, initial_state(model, s.speed_m_per_s), tight(2.0));
  const Eigen::VectorXd& x = traj.states.back();
  const double t = traj.times_s.back();
  // relative position = initial + rate t (tolerance: 1e-8 m, integrator rtol 1e-10)
  EXPECT_NEAR(x(0), 0.3 * t, 1e-8);
  EXPECT_NEAR(x(1), -0.2 * t, 1e-8);
  EXPECT_NEAR(x(2), 1.0 + 0.1 * t, 1e-8);
}

// Torque-free spinning asymmetric body: kinetic energy and |angular momentum|
// are conserved (Euler's equations through the Z-X-Y coordinates).
TEST(BodyDynamics, TorqueFreeRotationConservesEnergy) {
  SceneSpec s;
  s.name = "spinning";
  s.speed_m_per_s = 5.0;
  s.gravity_m_per_s2 = 0.0;
  s.reference_arc_length_m = 10.0;
  s.track = test::straight_track();
  s.bodies.push_back(test::rigid_body("body", 0.0, 1.0));
  s.bodies[0].initial_rate = {0.0, 0.0, 0.0, 0.05, 0.3, 0.08};
  const Model model = build_model(s);
  const Trajectory traj = integrate(model, s.speed_m_per_s, initial_state(model, s.speed_m_per_s), tight(3.0));
  const double e0 = mechanical_energy(model, s.speed_m_per_s, 0.0, traj.states.front()).total();
  for (size_t i = 0; i < traj.states.size(); ++i) {
    const double e = mechanical_energy(model, s.speed_m_per_s, traj.times_s[i], traj.states[i]).total();
    EXPECT_NEAR(e, e0, 1e-7 * std::abs(e0)) << "t = " << traj.times_s[i];
  }
}

// Springs, gravity, no dissipation, tangent track: the track frame moves at
// constant V (inertial), and the energy seen from it is conserved to
// integrator tolerance (in W the track anchors would do work).
TEST(BodyDynamics, UndampedSpringsConserveEnergyOnTangentTrack) {
  SceneSpec s = test::two_body_oscillator(test::straight_track(), 20.0);
  s.bodies[0].initial_offset = {0.01, -0.02, 0.015, 0.02, -0.01, 0.03};
  s.bodies[1].initial_rate = {0.1, 0.2, -0.1, 0.1, 0.05, -0.08};
  const Model model = build_model(s);
  IntegrationOptions opt = tight(2.0);
  opt.kind = IntegratorKind::cvode_adams;  // BDF damps oscillations numerically
  const Trajectory traj = integrate(model, s.speed_m_per_s, initial_state(model, s.speed_m_per_s), opt);
  const Eigen::Vector3d observer(20.0, 0.0, 0.0);  // track along W's x
  const EnergyParts e0 = mechanical_energy(model, s.speed_m_per_s, 0.0, traj.states.front(), observer);
  double max_exchange = 0.0;
  for (size_t i = 0; i < traj.states.size(); ++i) {
    const EnergyParts e = mechanical_energy(model, s.speed_m_per_s, traj.times_s[i], traj.states[i], observer);
    max_exchange = std::max(max_exchange, std::abs(e.elastic_J - e0.elastic_J));
    // BDF at rtol 1e-10 drifts ~1e-9 relative over these 2 s; a wrong force
    // or moment (as anchors' work in W) shows up at 1e-1 relative.
    EXPECT_NEAR(e.total(), e0.total(), 1e-8 * e0.total()) << "t = " << traj.times_s[i];
  }
  EXPECT_GT(max_exchange, 10.0);  // the test exercises real oscillation
}

// The result relative to the track does not depend on where the fixed frame
// is put: moving and turning the whole track leaves all coordinates equal.
TEST(BodyDynamics, CurveResultIndependentOfFixedFrame) {
  const double V = 25.0;
  const Model m1 = build_model(test::two_body_oscillator(test::curved_track(300.0, 0.1), V));
  const Model m2 = build_model(
      test::two_body_oscillator(test::curved_track(300.0, 0.1, 1.1, -350.0, 2200.0), V));
  Eigen::VectorXd x0 = initial_state(m1, V);
  x0(1) += 0.01;
  const Trajectory t1 = integrate(m1, V, x0, tight(8.0));
  const Trajectory t2 = integrate(m2, V, x0, tight(8.0));
  // 8 s covers tangent, clothoid and arc. 1e-7 against motions of ~1e-2.
  EXPECT_LT((t1.states.back() - t2.states.back()).cwiseAbs().maxCoeff(), 1e-7);
  EXPECT_GT((t1.states.back() - x0).cwiseAbs().maxCoeff(), 1e-3);
}

// The wheelset path (frame I, axisymmetric inertia) and the general-body
// path (body frame B) give the same accelerations when Jx = Jz.
TEST(BodyDynamics, WheelsetPathEqualsGeneralPathForAxisymmetricBody) {
  TrackSpec ts = test::curved_track(500.0, 0.08);
  const Track track(ts);
  const TrackFrameKinematics k = track.frame_at(150.0, 30.0);  // inside the clothoid
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.2, 0.2);
  for (int trial = 0; trial < 10; ++trial) {
    Body body;
    body.mass_kg = 1200.0;
    body.inertia_kg_m2 = Eigen::Vector3d(700.0, 90.0, 700.0);
    for (int i = 0; i < 6; ++i) body.state_index[i] = i;
    Eigen::Matrix<double, 6, 1> q, qd;
    for (int i = 0; i < 6; ++i) {
      q(i) = u(rng);
      qd(i) = u(rng);
    }
    qd(4) = 60.0;  // spinning
    const Eigen::Vector3d force(u(rng) * 1e4, u(rng) * 1e4, u(rng) * 1e4);
    const Eigen::Vector3d moment(u(rng) * 1e3, u(rng) * 1e3, u(rng) * 1e3);
    Eigen::Matrix<double, 6, 1> acc[2];
    for (int path = 0; path < 2; ++path) {
      if (path == 0) body.kind = WheelsetKind{};
      else body.kind = RigidBodyKind{};
      BodyMotion<double> m;
      compute_body_motion(body, k, q, qd, m);
      m.force_W = force;
      m.spinning_moment_W = moment;  // on the rotating body in both paths
      acc[path] = body_accelerations(body, m);
    }
    EXPECT_LT((acc[0] - acc[1]).cwiseAbs().maxCoeff(), 1e-9 * acc[1].cwiseAbs().maxCoeff());
  }
}
