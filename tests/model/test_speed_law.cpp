// The speed law of a ramp (model/model.hpp speed_rate_m_per_s2,
// track/track.hpp frame_at with dV/dt) against its closed forms: on an arc
// of radius R the frame moving at V with dV/dt = a has the origin
// acceleration (a, V^2/R, 0) in T (tangential and centripetal) and the yaw
// acceleration a / R; at a = 0 everything is the constant-speed frame, bit
// for bit.
#include <railstab/model/model.hpp>
#include <railstab/track/track.hpp>

#include "model/scene_builders.hpp"

#include <gtest/gtest.h>

using namespace railstab;
using namespace railstab::test;

TEST(SpeedLaw, ArcFrameGainsTheTangentialAccelerationAndTheYawAcceleration) {
  const double R = 1000.0, V = 30.0, a = -0.8;
  const Track track(curved_track(R, 0.0));
  const TrackFrameKinematics k = track.frame_at(500.0, V, a);  // inside the arc
  EXPECT_NEAR(k.a_WT_T.x(), a, 1e-12);
  EXPECT_NEAR(k.a_WT_T.y(), V * V / R, 1e-12);
  EXPECT_NEAR(k.a_WT_T.z(), 0.0, 1e-12);
  EXPECT_NEAR(k.w_WT_T.z(), V / R, 1e-15);
  EXPECT_NEAR(k.alpha_WT_T.z(), a / R, 1e-15);
  // At a = 0: the constant-speed frame exactly.
  const TrackFrameKinematics c = track.frame_at(500.0, V);
  const TrackFrameKinematics z = track.frame_at(500.0, V, 0.0);
  EXPECT_EQ(z.a_WT_T, c.a_WT_T);
  EXPECT_EQ(z.alpha_WT_T, c.alpha_WT_T);
  EXPECT_EQ(c.alpha_WT_T.z(), 0.0);
}

TEST(SpeedLaw, ArcLengthAndFrozenSpinFollowTheIntegralOfTheSpeed) {
  // A wheelset with its spin frozen: pitch = (V0 t + a t^2 / 2) / r0, its rate V(t) / r0.
  Model model(straight_track());
  model.reference_arc_length_m = 100.0;
  Body w;
  w.name = "w";
  WheelsetKind kind;
  kind.nominal_rolling_radius_m = 0.45;
  w.kind = kind;
  w.nominal_q.setZero();
  w.initial_offset.setZero();
  w.initial_rate.setZero();
  w.state_index.fill(-1);
  model.bodies.push_back(w);
  model.speed_rate_m_per_s2 = -0.5;
  const double V0 = 40.0, t = 6.0;
  EXPECT_DOUBLE_EQ(model.speed_at(t, V0), 37.0);
  EXPECT_DOUBLE_EQ(model.arc_length_of(0, t, V0), 100.0 + 40.0 * 6.0 - 0.25 * 36.0);
  Eigen::MatrixXd q6, qd6;
  model.full_coordinates(t, V0, Eigen::VectorXd(), q6, qd6);
  EXPECT_NEAR(q6(4, 0), (V0 * t - 0.25 * t * t) / 0.45, 1e-12);
  EXPECT_NEAR(qd6(4, 0), 37.0 / 0.45, 1e-12);
  model.speed_rate_m_per_s2 = 0.0;
  model.full_coordinates(t, V0, Eigen::VectorXd(), q6, qd6);
  EXPECT_EQ(q6(4, 0), V0 / 0.45 * t);
  EXPECT_EQ(model.arc_length_of(0, t, V0), 100.0 + 0.0 + V0 * t);
}
