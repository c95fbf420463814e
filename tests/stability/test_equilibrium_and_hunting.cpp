// Equilibria (steady rolling, steady curving) and the kinematic limit of the
// linearised knife-edge wheelset.
#include <railstab/setup/prepare_scene.hpp>
#include <railstab/equilibrium/equilibrium.hpp>
#include <railstab/model/equations_of_motion.hpp>
#include "model/scene_builders.hpp"
#include <railstab/stability/speed_analysis.hpp>

#include <gtest/gtest.h>

#include <cmath>

using namespace railstab;

namespace {

TrackSpec arc_track(double radius_m) {
  TrackSpec t;
  t.start_curvature_per_m = 1.0 / radius_m;
  t.segments.push_back({TrackSegmentKind::arc, 2000.0, 0.0, 0.0});
  return t;
}

}  // namespace

// Symmetric vehicle on tangent track: no lateral shift or yaw, equal wheel
// loads left and right, vertical contact forces summing to the weight.
TEST(Equilibrium, SymmetricVehicleOnTangent) {
  const PreparedScene s = prepare_scene(std::string(RAILSTAB_CASES_DIR) + "/thesis_vehicle_tangent.toml",
                                        SceneOverrides::at_speed(30.0));
  const Model& m = s.model;
  Eigen::MatrixXd q6, qd6;
  m.full_coordinates(0.0, s.speed_m_per_s, s.equilibrium.state, q6, qd6);
  double weight = 0.0;
  for (size_t b = 0; b < m.bodies.size(); ++b) {
    weight += m.bodies[b].mass_kg * m.gravity_m_per_s2;
    EXPECT_NEAR(q6(1, b), 0.0, 1e-12) << m.bodies[b].name;  // lateral, m
    EXPECT_NEAR(q6(5, b), 0.0, 1e-12) << m.bodies[b].name;  // yaw, rad
  }
  EvaluationDetails d;
  rhs(m, s.speed_m_per_s, 0.0, s.equilibrium.state, &d);
  double vertical = 0.0;
  for (size_t i = 0; i + 1 < d.contacts.size(); i += 2) {
    const auto& left = d.contacts[i].wheel;
    const auto& right = d.contacts[i + 1].wheel;
    ASSERT_EQ(left.side, 1);
    EXPECT_NEAR(left.normal_force_N, right.normal_force_N, 1e-9 * left.normal_force_N);
    vertical += left.force_I.z() + right.force_I.z();  // I = T here (no roll/yaw)
  }
  // Newton stops at accelerations below 1e-7 m/s^2: force balance to ~1e-8.
  EXPECT_NEAR(vertical, weight, 1e-8 * weight);
}

// The knife-edge cone's effective conicity. The wheelset rolls with its
// lateral shift so both wheels stay on their wires (equal approach):
// roll = tan(g) y / (e0 - r0 tan(g)), which moves the contact points along the
// cones, so the rolling-radius difference is 2 lambda_eff y with
//   lambda_eff = tan(g) e0 / (e0 - r0 tan(g))   (= 0.1068 for the thesis wheel).
double knife_edge_effective_conicity() {
  const double t = std::tan(0.1);
  return t * 0.75 / (0.75 - 0.45 * t);
}

// A free wheelset in an unbanked arc settles near the pure-rolling shift
// y0 = r0 e0 / (lambda_eff R), where the rolling-radius difference matches
// the curve. Not exact: the spin creepage from the yaw rate V/R and the
// small yaw angle that balances the centrifugal force through lateral creep
// shift it; at 5 m/s and R = 1000 m they stay well within 1 %.
TEST(Equilibrium, FreeWheelsetInArcNearPureRollingShift) {
  const double R = 1000.0;
  const double V = 5.0;
  const Model m = build_model(test::lone_knife_edge_wheelset(V, arc_track(R)));
  const EquilibriumResult eq = solve_equilibrium(m, V, lowered_nominal_state(m, V));
  const double y0 = 0.45 * 0.75 / (knife_edge_effective_conicity() * R);
  const double y = eq.state(m.bodies[0].state_index[1]);
  std::printf("free wheelset in R = %.0f m arc: y = %.4f mm, pure rolling %.4f mm\n", R, y * 1e3,
              y0 * 1e3);
  // The curve turns left: the outer rail is the right one (-y).
  EXPECT_NEAR(y, -y0, 0.01 * y0);
}

// A scene with no equilibrium fails with a clear message: 150 m/s in an
// unbanked 150 m curve (15 g lateral) lifts the wheelset off the rails.
TEST(Equilibrium, NoEquilibriumGivesClearError) {
  const double V = 150.0;
  const Model m = build_model(test::lone_knife_edge_wheelset(V, arc_track(150.0)));
  try {
    solve_equilibrium(m, V, lowered_nominal_state(m, V));
    FAIL() << "expected no equilibrium";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no equilibrium"), std::string::npos) << e.what();
  }
}

// Low-speed limit of the free knife-edge wheelset: its hunting (kinematic)
// wavelength approaches Klingel's 2 pi sqrt(r0 e0 / lambda). Not exact: the
// knife edge's roll (see above) raises the rolling-radius difference by
// k = e0/(e0 - r0 tan g) but also turns the contact point laterally with the
// roll rate, so zero lateral creep needs y' (cos g (1 + r0 roll') + sin g e0
// roll') = V psi cos g, roll' = tan(g)/(e0 - r0 tan g). The kinematic
// wavelength is then
//   L = 2 pi sqrt(r0 e0 / tan g * (1 + r0 roll' + tan g e0 roll') / (1 + r0 roll')),
// 0.50 % above Klingel's with lambda = tan g. Inertia adds O(V^2) terms:
// at 2 m/s the model must match L to 1e-4 and Klingel to 1 %.
TEST(Hunting, KnifeEdgeWheelsetApproachesKlingel) {
  TrackSpec straight;
  straight.segments.push_back({TrackSegmentKind::tangent, 2000.0, 0.0, 0.0});
  const double V = 2.0;
  const Model m = build_model(test::lone_knife_edge_wheelset(V, straight));
  const EquilibriumResult eq = solve_equilibrium(m, V, lowered_nominal_state(m, V));
  SpeedStability stability(m, eq.state, V);
  const StabilityPoint p = stability.at(V);
  // the kinematic mode: the oscillatory mode below 1 Hz
  double f = 0.0;
  for (const ModeReport& mode : p.modes)
    if (!mode.neutral && mode.eigenvalue.imag() > 0.0 && mode.frequency_hz < 1.0) f = mode.frequency_hz;
  ASSERT_GT(f, 0.0);
  const double klingel = 2.0 * M_PI * std::sqrt(0.45 * 0.75 / std::tan(0.1));
  const double t = std::tan(0.1), r0 = 0.45, e0 = 0.75;
  const double roll_per_y = t / (e0 - r0 * t);
  const double kinematic = 2.0 * M_PI *
                           std::sqrt(r0 * e0 / t * (1.0 + r0 * roll_per_y + t * e0 * roll_per_y) /
                                     (1.0 + r0 * roll_per_y));
  std::printf("knife-edge wheelset at 2 m/s: wavelength %.5f m, kinematic %.5f m, Klingel %.5f m\n",
              2.0 / f, kinematic, klingel);
  EXPECT_NEAR(2.0 / f, kinematic, 1e-4 * kinematic);
  EXPECT_NEAR(2.0 / f, klingel, 0.01 * klingel);
}
