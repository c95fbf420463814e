// traction_rod with preload = "balance_gravity_at_nominal" (issue 24, item
// 4): the rod takes part in the static sag linearised about its nominal line
// (elements/traction_rod.hpp), so a rod on the load path gets its share of
// the weight as its preload and the nominal configuration is the static
// equilibrium. Before, rods were left out of the sag: a body hung on rods
// had no support in the sag and no preload could be solved.
//
// The load: a rigid body of mass m (y and z free) hung from the track frame
// by two rods mirrored in y, each inclined at theta = 45 deg to the
// horizontal in the y-z plane, optionally on a vertical spring k_s as well.
// Linear statics (the linearised rods and the spring along the track's z are
// exact linear springs in the sag):
//   rods alone (statically determinate):  2 T sin(theta) = m g
//   with the spring:  T = m g k_r sin(theta) / (k_s + 2 k_r sin^2(theta)),
//                     F_s = m g k_s / (k_s + 2 k_r sin^2(theta)).
#include <gtest/gtest.h>

#include <railstab/model/equations_of_motion.hpp>
#include <railstab/scene_reading/load_scene.hpp>
#include <railstab/setup/build_model.hpp>
#include <railstab/setup/prepare_scene.hpp>

#include <cmath>
#include <string>

using namespace railstab;

namespace {

constexpr double kMass_kg = 800.0, kG = 9.81, kRod_N_per_m = 2.0e7;
const double kSinTheta = std::sqrt(0.5);

// The textbook wheelset (prescribed wheel load) and the hung load.
std::string scene_text(double spring_N_per_m) {
  std::string text = R"(
[scene]
name = "hung_load"
speed_m_per_s = 20.0
reference_arc_length_m = 100.0
preload = "balance_gravity_at_nominal"

[track]
[[track.segments]]
type = "tangent"
length_m = 1000.0

[contacts.linear]
geometry = "linear_conicity"
conicity = 0.1
half_contact_distance_m = 0.75
nominal_rolling_radius_m = 0.45
normal = "prescribed"
prescribed_wheel_load_N = 73575.0
tangential = "constant"
spin_creepage = false
f11_N = 1.0e7
f22_N = 1.0e7
f23_N_m = 0.0
f33_N_m2 = 0.0

[[bodies]]
name = "wheelset1"
type = "wheelset"
mass_kg = 1500.0
inertia_kg_m2 = [799.35, 93.75, 799.35]
track_offset_m = 0.0
position_m = [0.0, 0.0, 0.45]
free = ["y", "yaw"]
contact = "linear"

[[bodies]]
name = "load"
type = "rigid_body"
mass_kg = 800.0
inertia_kg_m2 = [50.0, 50.0, 50.0]
track_offset_m = 5.0
position_m = [0.0, 0.0, 1.0]
free = ["y", "z"]

[[elements]]
name = "track_holder"
type = "spring_damper_3d"
body1 = "track"
body2 = "wheelset1"
point1_m = [0.0, 1.0, 0.0]
point2_m = [0.0, 1.0, 0.0]
stiffness_N_per_m = [1.0e6, 0.5e6, 0.0]
damping_N_s_per_m = [0.0, 0.0, 0.0]
mirror_lateral = true

# Up and out at 45 deg: from (0, 0.1, 1.0) on the load to (0, 0.6, 1.5) in T.
[[elements]]
name = "hanger"
type = "traction_rod"
body1 = "track"
body2 = "load"
point1_m = [0.0, 0.6, 1.5]
point2_m = [0.0, 0.1, 0.0]
stiffness_N_per_m = 2.0e7
damping_N_s_per_m = 1.0e3
mirror_lateral = true
)";
  if (spring_N_per_m > 0.0)
    text += R"(
[[elements]]
name = "support"
type = "spring_damper_3d"
body1 = "track"
body2 = "load"
point1_m = [0.0, 0.0, 0.5]
point2_m = [0.0, 0.0, -0.5]
stiffness_N_per_m = [0.0, 0.0, )" + std::to_string(spring_N_per_m) + R"(]
damping_N_s_per_m = [0.0, 0.0, 0.0]
)";
  return text;
}

const TractionRod<double>& rod(const Model& model, const std::string& name) {
  for (const auto& e : model.elements)
    if (const auto* r = std::get_if<TractionRod<double>>(&e); r && r->ends.name == name) return *r;
  throw std::runtime_error("no rod " + name);
}

// The load's y and z in the equilibrium state, and its accelerations at the
// nominal state (the forces' balance there).
struct LoadAtNominal {
  double y_m, z_m, ydd, zdd;
};
LoadAtNominal load_at_nominal(const PreparedScene& s) {
  const int b = s.model.find_body("load");
  Eigen::MatrixXd q6, qd6;
  s.model.full_coordinates(0.0, s.speed_m_per_s, s.equilibrium.state, q6, qd6);
  // The equilibrium state with the load put exactly at its nominal y, z.
  const int iy = s.model.bodies[size_t(b)].state_index[1], iz = s.model.bodies[size_t(b)].state_index[2];
  Eigen::VectorXd x0 = s.equilibrium.state;
  x0(iy) = s.model.bodies[size_t(b)].nominal_q(1);
  x0(iz) = s.model.bodies[size_t(b)].nominal_q(2);
  const Eigen::VectorXd f = rhs(s.model, s.speed_m_per_s, 0.0, x0);
  const int n = s.model.n_coordinates;
  return {q6(1, b) - s.model.bodies[size_t(b)].nominal_q(1), q6(2, b) - s.model.bodies[size_t(b)].nominal_q(2),
          f(n + iy), f(n + iz)};
}

}  // namespace

TEST(TractionRodPreload, HangersCarryTheWeightAndNominalIsTheStaticEquilibrium) {
  const PreparedScene s = prepare_scene(load_scene_text(scene_text(0.0), "hung_load.toml"));
  // Statically determinate: T = m g / (2 sin theta) = 5549.3 N in each rod.
  const double T = kMass_kg * kG / (2.0 * kSinTheta);
  EXPECT_NEAR(rod(s.model, "hanger_left").preload_N, T, 1e-9 * T);
  EXPECT_NEAR(rod(s.model, "hanger_right").preload_N, T, 1e-9 * T);
  // The forces balance at nominal (accelerations of the load zero) and the
  // equilibrium found is the nominal configuration.
  const LoadAtNominal l = load_at_nominal(s);
  EXPECT_NEAR(l.zdd, 0.0, 1e-9);
  EXPECT_NEAR(l.ydd, 0.0, 1e-9);
  EXPECT_NEAR(l.z_m, 0.0, 1e-9);
  EXPECT_NEAR(l.y_m, 0.0, 1e-9);
}

TEST(TractionRodPreload, RodsAndASpringShareTheWeightByTheirStiffness) {
  const double k_s = 3.0e6;
  const PreparedScene s = prepare_scene(load_scene_text(scene_text(k_s), "hung_load.toml"));
  const double rods_vertical = 2.0 * kRod_N_per_m * kSinTheta * kSinTheta;
  const double T = kMass_kg * kG * kRod_N_per_m * kSinTheta / (k_s + rods_vertical);
  const double F_s = kMass_kg * kG * k_s / (k_s + rods_vertical);
  EXPECT_NEAR(rod(s.model, "hanger_left").preload_N, T, 1e-9 * T);
  EXPECT_NEAR(rod(s.model, "hanger_right").preload_N, T, 1e-9 * T);
  int springs = 0;
  for (const auto& e : s.model.elements)
    if (const auto* spring = std::get_if<SpringDamper3d<double>>(&e); spring && spring->ends.name == "support") {
      EXPECT_NEAR(std::abs(spring->preload_N.z()), F_s, 1e-9 * F_s);
      ++springs;
    }
  EXPECT_EQ(springs, 1);
  // 2 T sin(theta) + F_s = m g: the shares add up to the weight.
  EXPECT_NEAR(2.0 * T * kSinTheta + F_s, kMass_kg * kG, 1e-9 * kMass_kg * kG);
  const LoadAtNominal l = load_at_nominal(s);
  EXPECT_NEAR(l.zdd, 0.0, 1e-9);
  EXPECT_NEAR(l.z_m, 0.0, 1e-9);
}
