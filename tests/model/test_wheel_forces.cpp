// Wheel forces Y, Q and Y/Q (model/wheel_forces.hpp) and Nadal's limit.
// - Nadal's formula against hand-computed values and its mu -> 0 limit
//   (tan beta);
// - the selection of the wheel beyond its limit;
// - on the tangent, the thesis vehicle on S1002/UIC60 at its steady state:
//   the wheels carry the weight (sum of Q = M g, 1e-6), left and right wheels
//   alike (mirror symmetry, 1e-6), both pushing their rails outwards (Y > 0:
//   the coned treads' gauge-spreading force); the knife-edge vehicle has no
//   flange and so no limit.
#include <railstab/model/wheel_forces.hpp>
#include <railstab/contact_geometry/profile_contact_geometry.hpp>
#include <railstab/equilibrium/equilibrium.hpp>
#include <railstab/scene_reading/load_scene.hpp>
#include <railstab/setup/build_model.hpp>

#include <gtest/gtest.h>

#include <cmath>

using namespace railstab;

TEST(WheelForces, NadalLimitClosedForm) {
  // tan(70 deg) = 2.7474774; (2.7474774 - 0.36) / (1 + 0.36 * 2.7474774) = 1.2002851
  EXPECT_NEAR(nadal_limit(70.0 * M_PI / 180.0, 0.36), 1.2002851, 1e-7);
  // (2.7474774 - 0.4) / (1 + 0.4 * 2.7474774) = 1.1183838
  EXPECT_NEAR(nadal_limit(70.0 * M_PI / 180.0, 0.4), 1.1183838, 1e-7);
  EXPECT_NEAR(nadal_limit(1.2, 0.0), std::tan(1.2), 1e-15);
}

TEST(WheelForces, TheWheelFurthestBeyondItsLimitIsNamed) {
  auto wheel = [](int body, int side, double yq, std::optional<double> limit) {
    WheelForces w;
    w.body = body;
    w.side = side;
    w.Q_N = 1e5;
    w.Y_N = yq * 1e5;
    w.y_over_q = yq;
    w.nadal_limit = limit;
    return w;
  };
  std::vector<WheelForces> within = {wheel(0, 1, 0.5, 1.12), wheel(0, -1, 1.11, 1.12),
                                     wheel(1, 1, 3.0, std::nullopt)};  // no flange: no limit
  EXPECT_FALSE(wheel_beyond_nadal_limit(within).has_value());
  std::vector<WheelForces> beyond = within;
  beyond.push_back(wheel(1, -1, 1.2, 1.12));
  beyond.push_back(wheel(2, -1, 1.5, 1.12));
  const auto worst = wheel_beyond_nadal_limit(beyond);
  ASSERT_TRUE(worst.has_value());
  EXPECT_EQ(worst->body, 2);
  EXPECT_EQ(worst->side, -1);
}

TEST(WheelForces, TangentWheelsCarryTheWeightSymmetrically) {
  const Model model = build_model(
      load_scene_file(std::string(RAILSTAB_CASES_DIR) + "/thesis_vehicle_s1002_tangent.toml"));
  const double V = 20.0;
  EquilibriumOptions o;
  o.acceleration_tolerance = 1e-9;
  const Eigen::VectorXd x = solve_equilibrium(model, V, lowered_nominal_state(model, V), o).state;
  const std::vector<WheelForces> wheels = wheel_forces(model, V, 0.0, x);
  ASSERT_EQ(wheels.size(), 8u);
  double mass = 0.0, q_sum = 0.0;
  for (const Body& b : model.bodies) mass += b.mass_kg;
  for (const WheelForces& w : wheels) q_sum += w.Q_N;
  EXPECT_NEAR(q_sum, mass * model.gravity_m_per_s2, 1e-6 * mass * model.gravity_m_per_s2);
  for (const WheelForces& left : wheels) {
    if (left.side < 0) continue;
    for (const WheelForces& right : wheels) {
      if (right.body != left.body || right.side > 0) continue;
      EXPECT_NEAR(left.Q_N, right.Q_N, 1e-6 * left.Q_N);
      EXPECT_NEAR(left.Y_N, right.Y_N, 1e-6 * left.Q_N);
      EXPECT_GT(left.Y_N, 0.0);
      ASSERT_TRUE(left.nadal_limit.has_value());
      // S1002's flange (~70 deg) with the scene's mu = 0.4.
      EXPECT_NEAR(*left.nadal_limit, 1.12, 0.03);
    }
  }
  EXPECT_FALSE(wheel_beyond_nadal_limit(wheels).has_value());

  const Model cone = build_model(
      load_scene_file(std::string(RAILSTAB_CASES_DIR) + "/thesis_vehicle_tangent.toml"));
  const std::vector<WheelForces> cone_wheels =
      wheel_forces(cone, V, 0.0, solve_equilibrium(cone, V, lowered_nominal_state(cone, V)).state);
  for (const WheelForces& w : cone_wheels) EXPECT_FALSE(w.nadal_limit.has_value());
}
