// Steady curving on real profiles (S1002 / UIC60 1:40): the thesis vehicle in
// the thesis track's R = 1000 m arc (cant 50 mm), where Newton's method from
// the centred nominal state fails (the contact jumps near-conformally at
// y ~ 0.25 mm and the leading wheelset ends in two-point flange-root contact)
// and the pseudo-transient continuation (equilibrium/pseudo_transient.hpp)
// finds the steady state. References no one tuned to:
// - the forces balance: the wheel-rail forces carry the weight (vertical sum
//   = M g) and give the centripetal force M V^2 / R towards the curve centre;
// - the steady state is the one the vehicle reaches when it runs into the
//   curve: a time simulation from the end of the transition settles on it.
#include <railstab/model/wheel_forces.hpp>
#include <railstab/equilibrium/equilibrium.hpp>
#include <railstab/integrate/integrator.hpp>
#include <railstab/scene_reading/load_scene.hpp>
#include <railstab/model/equations_of_motion.hpp>
#include <railstab/model/workspace.hpp>
#include <railstab/setup/build_model.hpp>
#include <railstab/setup/prepare_scene.hpp>

#include "support/state_index.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

using namespace railstab;

namespace {

const std::string kScene = std::string(RAILSTAB_CASES_DIR) + "/thesis_vehicle_s1002_tangent.toml";

}  // namespace

// At 20 m/s in the arc (reference point at s = 2000 m; R = 1000 m, cant
// 50 mm): V^2/R = 0.4 m/s^2, cant deficiency 0.4 * 1.5 / 9.81 - 0.05 = 11 mm.
TEST(SteadyCurvingProfiles, ForcesBalanceWeightAndCentripetalForce) {
  SceneOverrides o;
  o.reference_arc_length_m = 2000.0;
  const SceneSpec spec = load_scene_with_overrides(kScene, o);
  const Model model = build_model(spec);
  const double V = 20.0, R = 1000.0;
  const Eigen::VectorXd guess = lowered_nominal_state(model, V);
  // Newton alone finds it: with the tread slots sharing their overlap the
  // contact force is continuous in the lateral shift (docs/model.md 6.1);
  // when both counted it, Newton failed here and the pseudo-transient
  // fallback was needed.
  EquilibriumOptions newton_only;
  newton_only.pseudo_transient_fallback = false;
  // Default tolerance, 1e-7 m/s^2: with ~1e5 kg that leaves < 0.1 N of
  // imbalance against ~1e6 N of weight.
  const EquilibriumResult eq = solve_equilibrium(model, V, guess, newton_only);
  EXPECT_EQ(eq.pseudo_transient_steps, 0);
  EXPECT_LE(eq.max_acceleration, 1e-7);

  EvaluationDetails details;
  rhs(model, V, 0.0, eq.state, &details);
  // Each contact force is in its wheelset's non-spinning frame I; R_WI
  // turns it into the world frame W (z vertical).
  Workspace<double> ws(model);
  compute_all_body_motions<double>(model, ws, 0.0, V, eq.state);
  double mass = 0.0;
  for (const Body& b : model.bodies) mass += b.mass_kg;
  Eigen::Vector3d total = Eigen::Vector3d::Zero();
  double flange_load_N = 0.0, flange_lateral_N = 0.0;
  for (const ContactSnapshot& c : details.contacts) {
    total += ws.motions[size_t(c.body)].R_WI * c.wheel.force_I;
    // The leading wheelset's outer (right, -y) wheel on its flange root.
    if (c.body == 0 && c.wheel.side < 0 && c.wheel.contact_angle_rad > 0.3 &&
        c.wheel.normal_force_N > 0.0) {
      flange_load_N += c.wheel.normal_force_N;
      flange_lateral_N += c.wheel.force_I.y();
    }
  }
  // All steady accelerations are horizontal: the vertical sum is the weight.
  EXPECT_NEAR(total.z(), mass * model.gravity_m_per_s2, 1e-6 * mass * model.gravity_m_per_s2);
  // Horizontal: M V^2 / R towards the centre; the bodies' radii differ by
  // their lateral offsets (< 0.1 m in 1000 m) and their headings over the
  // 25 m long vehicle by < 1.5 degrees: 2e-3 of the force.
  const double horizontal = std::hypot(total.x(), total.y());
  EXPECT_NEAR(horizontal, mass * V * V / R, 2e-3 * mass * V * V / R);
  // Guided by the flange root: the outer leading wheel has a loaded contact
  // with a contact angle above 0.3 rad pushing the wheelset inwards (+y).
  EXPECT_GT(flange_load_N, 1e3);
  EXPECT_GT(flange_lateral_N, 0.0);
  // The leading wheelset runs out towards the outer rail by about 5.6 mm.
  const double y1 = eq.state(test::state_index(model, "wheelset1.y_m"));
  EXPECT_LT(y1, -4.5e-3);
  EXPECT_GT(y1, -7.0e-3);
}

// The vehicle runs at 5 m/s from the end of the transition (s = 1190 m, the
// scene's own equilibrium there as the start) 30 s into the arc; where it
// settles is the steady state at s = 1190 + 5 * 30 = 1340 m found from the
// centred guess. Tolerances: the run's own settling (the slowest mode's
// remainder after 30 s, and rtol 1e-5): 0.01 mm, 0.01 mrad.
TEST(SteadyCurvingProfiles, EquilibriumIsWhereTheSimulatedVehicleSettles) {
  SceneOverrides o;
  o.reference_arc_length_m = 1190.0;
  o.speed_m_per_s = 5.0;
  const PreparedScene s = prepare_scene(kScene, o);
  const double V = 5.0, t_end = 30.0;
  IntegrationOptions io;
  io.kind = IntegratorKind::arkode_dirk;
  io.t_end_s = t_end;
  io.output_interval_s = t_end;
  io.relative_tolerance = 1e-5;
  io.absolute_tolerance = 1e-8;
  const Trajectory run = integrate(s.model, V, s.equilibrium.state, io);
  ASSERT_TRUE(run.stopped_early.empty()) << run.stopped_early;
  const Eigen::VectorXd& settled = run.states.back();

  EquilibriumOptions eo;
  eo.time_s = t_end;
  const EquilibriumResult eq =
      solve_equilibrium(s.model, V, lowered_nominal_state(s.model, V), eo);
  for (const char* body : {"wheelset1", "wheelset2", "wheelset3", "wheelset4", "bogie1",
                           "bogie2", "carbody"}) {
    const std::string b(body);
    EXPECT_NEAR(eq.state(test::state_index(s.model, b + ".y_m")),
                settled(test::state_index(s.model, b + ".y_m")), 1e-5)
        << b;
    EXPECT_NEAR(eq.state(test::state_index(s.model, b + ".yaw_rad")),
                settled(test::state_index(s.model, b + ".yaw_rad")), 1e-5)
        << b;
  }
}

// A tight curve: R = 300 m, cant 150 mm, 22 m/s (V^2/R = 1.61 m/s^2, cant
// deficiency 1.61 * 1.5 / 9.81 - 0.15 = 97 mm). The leading wheelset is
// guided by two-point contact on the flange root of its outer wheel (38 and
// 51 deg): an equilibrium, not a failure. Checked: the weight on the wheels
// (1e-6), the centripetal force (2e-3), two loaded flange-root points,
// and Y/Q (model/wheel_forces.hpp) of the flanging wheel positive and
// below EN 14363's 0.8 and Nadal's limit for S1002 (beta ~ 70 deg, mu 0.4:
// 1.12), with no Nadal warning; Q summed over the wheels equals the sum of
// the contact forces' components normal to each wheelset's track plane.
TEST(SteadyCurvingProfiles, TightCurveFlangeContactIsAnEquilibriumWithinNadal) {
  std::ifstream in(kScene);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto replace_all = [&](const std::string& from, const std::string& to) {
    int count = 0;
    for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
      text.replace(at, from.size(), to);
      ++count;
    }
    return count;
  };
  ASSERT_EQ(replace_all("end_radius_m = 1000.0", "end_radius_m = 300.0"), 1);
  ASSERT_EQ(replace_all("end_cant_m = 0.05", "end_cant_m = 0.15"), 2);
  ASSERT_EQ(replace_all("reference_arc_length_m = 100.0", "reference_arc_length_m = 2000.0"), 1);
  const Model model = build_model(load_scene_text(text, kScene));  // profiles relative to kScene
  const double V = 22.0, R = 300.0;
  const EquilibriumResult eq = solve_equilibrium(model, V, lowered_nominal_state(model, V));

  Workspace<double> ws(model);
  compute_all_body_motions<double>(model, ws, 0.0, V, eq.state);
  EvaluationDetails details;
  rhs(model, V, 0.0, eq.state, &details);
  double mass = 0.0;
  for (const Body& b : model.bodies) mass += b.mass_kg;
  Eigen::Vector3d total = Eigen::Vector3d::Zero();
  double flange_N = 0.0, normal_sum_T = 0.0, steepest_rad = 0.0;
  int outer_points = 0;
  for (const ContactSnapshot& c : details.contacts) {
    total += ws.motions[size_t(c.body)].R_WI * c.wheel.force_I;
    normal_sum_T += (ws.motions[size_t(c.body)].R_TI * c.wheel.force_I).z();
    if (c.body != 0 || c.wheel.side > 0 || c.wheel.normal_force_N < 1e3) continue;
    ++outer_points;
    steepest_rad = std::max(steepest_rad, c.wheel.contact_angle_rad);
    if (c.wheel.contact_angle_rad > 0.5) flange_N += c.wheel.normal_force_N;
  }
  const double g = model.gravity_m_per_s2;
  EXPECT_NEAR(total.z(), mass * g, 1e-6 * mass * g);
  EXPECT_NEAR(std::hypot(total.x(), total.y()), mass * V * V / R, 2e-3 * mass * V * V / R);
  // The leading outer wheel on its flange root: two loaded points (> 1 kN),
  // the steeper above 0.6 rad (34 deg; the tread is below 0.05 rad).
  EXPECT_GE(outer_points, 2);
  EXPECT_GT(steepest_rad, 0.6);
  EXPECT_GT(flange_N, 1e4) << "no loaded flange contact on the leading outer wheel";

  const std::vector<WheelForces> wheels = wheel_forces(model, V, 0.0, eq.state);
  ASSERT_EQ(wheels.size(), 8u);
  double q_sum = 0.0;
  for (const WheelForces& w : wheels) q_sum += w.Q_N;
  EXPECT_NEAR(q_sum, normal_sum_T, 1e-9 * mass * g);
  const WheelForces* flanging = nullptr;
  for (const WheelForces& w : wheels)
    if (w.body == 0 && w.side < 0) flanging = &w;
  ASSERT_NE(flanging, nullptr);
  ASSERT_TRUE(flanging->y_over_q && flanging->nadal_limit);
  EXPECT_GT(*flanging->y_over_q, 0.1);
  EXPECT_LT(*flanging->y_over_q, 0.8);
  EXPECT_NEAR(*flanging->nadal_limit, 1.12, 0.03);
  EXPECT_FALSE(wheel_beyond_nadal_limit(wheels).has_value());
}
