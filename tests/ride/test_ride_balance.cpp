// The ride quantities (ride/) against invariants no one tuned them to:
// Newton's second law for the whole vehicle (the contact forces equal the
// bodies' mass times the point accelerations, minus gravity) in steady
// curving, the track shift forces Sum Y against the vehicle's uncompensated
// lateral acceleration, and Prud'homme's limit from the weight.
#include <gtest/gtest.h>

#include "support/test_files.hpp"

#include <railstab/model/equations_of_motion.hpp>
#include <railstab/model/workspace.hpp>
#include <railstab/ride/point_acceleration.hpp>
#include <railstab/ride/wheelset_forces.hpp>
#include <railstab/setup/prepare_scene.hpp>

#include <cmath>

namespace railstab {
namespace {

// The thesis vehicle in the arc (R = 1000 m left, cant 50 mm) at 20 m/s:
// every body's track frame at its own arc length.
PreparedScene vehicle_in_arc() {
  SceneOverrides o;
  o.reference_arc_length_m = 2000.0;
  return prepare_scene(test::case_path("thesis_vehicle_curve"), o);
}

// Sum over the bodies of m (a - g) in W, and the contact forces on the
// wheelsets in W, at the steady curving state.
struct Balance {
  Eigen::Vector3d inertial_minus_gravity_W = Eigen::Vector3d::Zero();
  Eigen::Vector3d contact_W = Eigen::Vector3d::Zero();
  double weight_N = 0.0;
};

Balance balance_at(const PreparedScene& s) {
  const Model& model = s.model;
  const double V = s.speed_m_per_s;
  const Eigen::VectorXd& x = s.equilibrium.state;
  Balance b;
  // CMs of every body, wheelsets included (point_accelerations takes any body).
  std::vector<AccelerationPoint> cms;
  for (size_t i = 0; i < model.bodies.size(); ++i) cms.push_back({model.bodies[i].name, int(i), {0, 0, 0}});
  const std::vector<Eigen::Vector3d> a_T = point_accelerations(model, V, 0.0, x, cms);
  Workspace<double> ws(model);
  EvaluationDetails details;
  Eigen::VectorXd xdot;
  evaluate_rhs<double>(model, ws, 0.0, V, x, xdot, &details);
  const Eigen::Vector3d g_W(0.0, 0.0, -model.gravity_m_per_s2);
  for (size_t i = 0; i < model.bodies.size(); ++i) {
    const double m = model.bodies[i].mass_kg;
    b.inertial_minus_gravity_W += m * (ws.frames[i].R_WT * a_T[i] - g_W);
    b.weight_N += m * model.gravity_m_per_s2;
  }
  for (const ContactSnapshot& c : details.contacts)
    b.contact_W += ws.motions[size_t(c.body)].R_WI * c.wheel.force_I;
  return b;
}

TEST(RideBalance, ContactForcesEqualTheVehiclesMassTimesItsAccelerationsInTheArc) {
  const PreparedScene s = vehicle_in_arc();
  const Balance b = balance_at(s);
  // The car body's x is held (it imposes V): its constraint force acts along
  // its own x_T, so compare across that direction only. Nothing else holds
  // a body to the ground: every other force is internal and cancels.
  const int carbody = s.model.find_body("carbody");
  ASSERT_GE(carbody, 0);
  Workspace<double> ws(s.model);
  ws.update_frames(s.model, 0.0, s.speed_m_per_s);
  const Eigen::Matrix3d R_WT = ws.frames[size_t(carbody)].R_WT;
  const Eigen::Vector3d residual_T = R_WT.transpose() * (b.contact_W - b.inertial_minus_gravity_W);
  // The equilibrium's acceleration residual (~1e-9 m/s2) times the masses.
  EXPECT_LT(std::abs(residual_T.y()), 1e-7 * b.weight_N) << residual_T.transpose();
  EXPECT_LT(std::abs(residual_T.z()), 1e-7 * b.weight_N) << residual_T.transpose();
  // Not trivially zero: the centripetal part is V^2/R ~ 0.4 m/s2 of the weight.
  const Eigen::Vector3d inertial_T = R_WT.transpose() * b.inertial_minus_gravity_W;
  EXPECT_GT(std::abs(inertial_T.y()), 1e-3 * b.weight_N);
}

TEST(RideBalance, SumOfTrackShiftForcesIsTheUncompensatedLateralForce) {
  const PreparedScene s = vehicle_in_arc();
  const Model& model = s.model;
  const double V = s.speed_m_per_s;
  const std::vector<WheelsetForces> forces =
      wheelset_forces(model, V, 0.0, s.equilibrium.state, static_wheel_loads(model, V), 1.0);
  ASSERT_EQ(forces.size(), 4u);
  double sum_y = 0.0;
  for (const WheelsetForces& f : forces) sum_y += f.sum_y_N;
  // Closed form: the track must supply m (V^2/R cos phi - g sin phi) to the
  // left (the arc turns left; cant raises the right rail by phi =
  // asin(cant / D)). The wheelsets push the track the opposite way.
  const double R = 1000.0, phi = std::asin(0.05 / model.track.spec().rail_contact_distance_m);
  double mass = 0.0;
  for (const Body& b : model.bodies) mass += b.mass_kg;
  const double expected =
      -mass * (V * V / R * std::cos(phi) - model.gravity_m_per_s2 * std::sin(phi));
  // Bodies sit at different arc lengths (+-11 m: their frames differ by up to
  // 0.011 rad in heading) and their CMs are above the centreline, off the
  // radius R: the closed form holds to ~1e-4 of m V^2/R, i.e. ~0.1 % of the
  // net force (V^2/R 0.400 m/s2 against the cant's 0.327 m/s2): 2 % allowed.
  EXPECT_NEAR(sum_y, expected, 0.02 * std::abs(expected) + 5.0) << "expected " << expected;
  for (const WheelsetForces& f : forces) {
    // Prud'homme: 10 kN + P0/3 with P0 the static axle load.
    EXPECT_NEAR(f.prudhomme_limit_N, 10e3 + f.static_axle_load_N / 3.0, 1e-9 * f.prudhomme_limit_N);
    // On straight, level track the vehicle is symmetric: equal wheel loads,
    // a quarter of the weight each plus the wheelset's own.
    EXPECT_NEAR(f.left_static_load_N, f.right_static_load_N, 1e-6 * f.left_static_load_N);
  }
  double static_total = 0.0;
  for (const WheelsetForces& f : forces) static_total += f.static_axle_load_N;
  EXPECT_NEAR(static_total, mass * model.gravity_m_per_s2, 1e-6 * static_total);
}

TEST(RideBalance, WheelUnloadingIsRelativeToTheStaticLoad) {
  const PreparedScene s = vehicle_in_arc();
  const double V = s.speed_m_per_s;
  const std::vector<WheelsetForces> forces = wheelset_forces(
      s.model, V, 0.0, s.equilibrium.state, static_wheel_loads(s.model, V), 0.85);
  for (const WheelsetForces& f : forces) {
    EXPECT_NEAR(f.left_delta_q_over_q0, (f.left_static_load_N - f.left.Q_N) / f.left_static_load_N, 1e-14);
    EXPECT_NEAR(f.right_delta_q_over_q0, (f.right_static_load_N - f.right.Q_N) / f.right_static_load_N,
                1e-14);
    EXPECT_NEAR(f.prudhomme_limit_N, 0.85 * (10e3 + f.static_axle_load_N / 3.0), 1e-6);
    // Not zero: the curve loads one wheel and unloads the other (which one
    // depends on the wheelset's place in the bogie: the knife-edge contact's
    // lateral creep forces act at the contact angle).
    EXPECT_GT(std::abs(f.left_delta_q_over_q0), 0.01);
    EXPECT_LT(f.left_delta_q_over_q0 * f.right_delta_q_over_q0, 0.0);
    EXPECT_NEAR(f.sum_y_N, f.left.Y_N - f.right.Y_N, 1e-9);
  }
}

}  // namespace
}  // namespace railstab
