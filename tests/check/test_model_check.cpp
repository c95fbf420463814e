// Model checks (check/model_check.hpp): the quantities against closed forms
// of the thesis vehicle (Table 5.1 masses, statically determinate preloads),
// each warning raised by a scene with that one mistake and none raised by
// the thesis cases.
#include <railstab/check/model_check.hpp>
#include <railstab/scene_reading/load_scene.hpp>
#include <railstab/setup/prepare_scene.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>
#include "support/test_files.hpp"

namespace railstab {
namespace {

namespace fs = std::filesystem;

using railstab::test::case_path;

using railstab::test::read_text;

std::string warning_list(const ModelCheckReport& r) {
  std::string s;
  for (const ModelWarning& w : r.warnings) s += w.kind + ": " + w.message + "\n";
  for (const std::string& e : r.errors) s += "error: " + e + "\n";
  return s;
}

// The case `name` with each `from` replaced by its `to` (each must occur),
// written to a temporary file and checked as `railstab check` does.
ModelCheckReport check_mutated(const std::string& name,
                               const std::vector<std::pair<std::string, std::string>>& edits,
                               bool natural_frequencies = false) {
  std::string text = read_text(case_path(name));
  for (const auto& [from, to] : edits) {
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << "not in " << name << ": " << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
  }
  const fs::path path = fs::temp_directory_path() /
                        ("railstab_check_" + std::to_string(::getpid()) + "_" + name + ".toml");
  std::ofstream(path) << text;
  ModelCheckOptions options;
  options.natural_frequencies = natural_frequencies;
  ModelCheckReport r = check_scene(load_scene_with_overrides(path.string(), {}), options);
  fs::remove(path);
  return r;
}

// --- no false alarm on the thesis cases ------------------------------------------------
class ThesisCase : public ::testing::TestWithParam<std::string> {};

TEST_P(ThesisCase, RaisesNoWarning) {
  ModelCheckOptions options;
  const ModelCheckReport r = check_scene(load_scene_with_overrides(case_path(GetParam()), {}), options);
  EXPECT_TRUE(r.warnings.empty()) << warning_list(r);
  EXPECT_TRUE(r.errors.empty()) << warning_list(r);
  EXPECT_FALSE(r.natural_frequencies.empty()) << r.natural_frequency_note;
}

INSTANTIATE_TEST_SUITE_P(ModelCheck, ThesisCase,
                         ::testing::Values("thesis_bogie_tangent", "thesis_bogie_curve",
                                           "thesis_vehicle_tangent", "thesis_vehicle_curve"));

// --- quantities ---------------------------------------------------------------------------
// Table 5.1: 4 wheelsets of 1500 kg, 2 bogie frames of 3020 kg, a car body of 43200 kg.
constexpr double kThesisVehicleMassKg = 4 * 1500.0 + 2 * 3020.0 + 43200.0;

TEST(ModelCheck, ThesisVehicleMassesAxleLoadsAndDeflections) {
  const PreparedScene s = prepare_scene(case_path("thesis_vehicle_tangent"), {});
  ModelCheckOptions options;
  options.natural_frequencies = false;
  const ModelCheckReport r =
      check_model(s.spec, s.model, s.speed_m_per_s, s.equilibrium, options);
  EXPECT_NEAR(r.total_mass_kg, kThesisVehicleMassKg, 1e-9);
  ASSERT_EQ(r.bodies.size(), 7u);
  EXPECT_EQ(r.bodies[0].role, "wheelset");
  EXPECT_EQ(r.bodies[4].role, "bogie frame");
  EXPECT_EQ(r.bodies[6].role, "car body");

  // The axle loads carry the whole weight (tangent, no element to the track).
  const double weight = kThesisVehicleMassKg * 9.81;
  ASSERT_EQ(r.axle_loads.size(), 4u);
  EXPECT_NEAR(r.axle_load_sum_N, weight, 1e-6 * weight);
  // The car body's CM lies midway between the bogies, each bogie's midway
  // between its wheelsets: every axle carries a quarter, each wheel an
  // eighth, to 1e-4 (the suspension's longitudinal preloads, a few N at
  // lever arms of ~1 m, move a few N between the axles of a bogie).
  for (const AxleLoad& a : r.axle_loads) {
    EXPECT_NEAR(a.total_N, weight / 4.0, 1e-4 * weight / 4.0) << a.wheelset;
    EXPECT_NEAR(a.left_N, a.right_N, 1e-6 * weight) << a.wheelset;
  }

  // The vertical preloads carry the weights: the secondary springs the car
  // body's, the primary springs the car body's and the bogie frames'.
  double secondary_z = 0.0, primary_z = 0.0;
  int secondary = 0, primary = 0;
  for (const SpringDeflection& d : r.static_deflections) {
    if (d.axis != "z") {
      EXPECT_LT(std::abs(d.deflection), 1e-4) << d.element << " " << d.axis;  // < 0.1 mm
      continue;
    }
    const bool is_secondary = d.element.rfind("secondary", 0) == 0;
    (is_secondary ? secondary_z : primary_z) += std::abs(d.preload);
    (is_secondary ? secondary : primary)++;
    EXPECT_EQ(d.stiffness, is_secondary ? 5.3e5 : 9.75e5) << d.element;  // Tables 5.4, 5.6
    EXPECT_NEAR(d.deflection, d.preload / d.stiffness, 1e-15) << d.element;
  }
  EXPECT_EQ(secondary, 4);
  EXPECT_EQ(primary, 8);
  EXPECT_NEAR(secondary_z, 43200.0 * 9.81, 1e-6 * 43200.0 * 9.81);
  EXPECT_NEAR(primary_z, (43200.0 + 2 * 3020.0) * 9.81, 1e-6 * 49240.0 * 9.81);
}

// A known spring: one body of m = 800 kg hanging on a vertical spring of
// k = 2e5 N/m from the track sags by m g / k = 39.24 mm.
TEST(ModelCheck, StaticDeflectionOfOneSpringIsWeightOverStiffness) {
  const std::string toml = R"(
[scene]
name = "one_spring"
speed_m_per_s = 1.0
reference_arc_length_m = 0.0
preload = "balance_gravity_at_nominal"
[track]
[[track.segments]]
type = "tangent"
length_m = 1000.0
[[bodies]]
name = "mass"
type = "rigid_body"
mass_kg = 800.0
inertia_kg_m2 = [100.0, 100.0, 100.0]
position_m = [0.0, 0.0, 1.0]
free = ["z"]
[[elements]]
name = "spring"
type = "spring_damper_3d"
body1 = "track"
body2 = "mass"
point1_m = [0.0, 0.0, 1.0]
point2_m = [0.0, 0.0, 0.0]
stiffness_N_per_m = [0.0, 0.0, 2.0e5]
damping_N_s_per_m = [0.0, 0.0, 1.0e3]
)";
  ModelCheckOptions options;
  const ModelCheckReport r = check_scene(load_scene_text(toml, "one_spring.toml"), options);
  ASSERT_EQ(r.static_deflections.size(), 1u) << warning_list(r);
  const SpringDeflection& d = r.static_deflections[0];
  EXPECT_EQ(d.axis, "z");
  EXPECT_NEAR(std::abs(d.preload), 800.0 * 9.81, 1e-9 * 800.0 * 9.81);
  EXPECT_NEAR(std::abs(d.deflection), 800.0 * 9.81 / 2e5, 1e-12);
  EXPECT_NEAR(r.total_mass_kg, 800.0, 0.0);
  // Its one mode: sqrt(k/m) / 2 pi = 2.516 Hz, damped by zeta = c / (2 sqrt(k m)).
  ASSERT_EQ(r.natural_frequencies.size(), 1u) << r.natural_frequency_note;
  const double zeta = 1e3 / (2.0 * std::sqrt(2e5 * 800.0));
  EXPECT_NEAR(r.natural_frequencies[0].frequency_hz,
              std::sqrt(2e5 / 800.0) * std::sqrt(1.0 - zeta * zeta) / (2.0 * M_PI), 1e-9);
  EXPECT_NEAR(r.natural_frequencies[0].damping_ratio, zeta, 1e-9);
  EXPECT_TRUE(r.warnings.empty()) << warning_list(r);
}

// Natural frequencies at rest: the car body's bounce is the lower mode of
// car body (43200 kg) on the secondary springs (4 x 5.3e5 N/m) over the
// bogie frames (2 x 3020 kg) on the primary springs (8 x 9.75e5 N/m),
// 0.9854 Hz undamped; damped by its reported ratio zeta, f sqrt(1 - zeta^2).
// Within 1 % (the damping is not proportional, the wheelsets sit on Hertz springs).
TEST(ModelCheck, ThesisVehicleBounceFrequency) {
  const ModelCheckReport r =
      check_scene(load_scene_with_overrides(case_path("thesis_vehicle_tangent"), {}));
  const double ks = 4 * 5.3e5, kp = 8 * 9.75e5, m1 = 43200.0, m2 = 2 * 3020.0;
  // det(K - w^2 M) = 0 for M = diag(m1, m2), K = [ks, -ks; -ks, ks + kp].
  const double a = m1 * m2, b = -(ks * m2 + (ks + kp) * m1), c = ks * kp;
  const double w2 = (-b - std::sqrt(b * b - 4 * a * c)) / (2 * a);
  const double f_undamped = std::sqrt(w2) / (2.0 * M_PI);
  int found = 0;
  for (const NaturalFrequency& f : r.natural_frequencies)
    if (f.name == "car body bounce") {  // named from the shape (stability/mode_names.hpp)
      ++found;
      const double f_damped = f_undamped * std::sqrt(1.0 - f.damping_ratio * f.damping_ratio);
      EXPECT_NEAR(f.frequency_hz, f_damped, 0.01 * f_damped);
    }
  EXPECT_EQ(found, 1);
  EXPECT_EQ(r.natural_frequency_speed_m_per_s, 0.5);
  // No kinematic mode (frequency ~ V) below the band.
  for (const NaturalFrequency& f : r.natural_frequencies) EXPECT_GE(f.frequency_hz, 0.1) << f.name;
}

// --- each warning from a scene with that mistake -----------------------------------------------
TEST(ModelCheckWarning, WheelsetPlacedByPosition) {
  const ModelCheckReport r = check_mutated(
      "thesis_bogie_tangent", {{"track_offset_m = -3.0\nposition_m = [0.0, 0.0, 0.45]",
                                "track_offset_m = 0.0\nposition_m = [-3.0, 0.0, 0.45]"}});
  EXPECT_TRUE(r.has_warning("wheelset_placed_by_position")) << warning_list(r);
}

TEST(ModelCheckWarning, SpringEndsApart) {
  // The bogie-frame point given as if in the wheelset's frame (x = 0, not 1.5).
  const ModelCheckReport r = check_mutated(
      "thesis_bogie_tangent", {{"point2_m = [1.5, 1.0, -0.6075]", "point2_m = [0.0, 1.0, -0.6075]"}});
  EXPECT_TRUE(r.has_warning("spring_ends_apart")) << warning_list(r);
}

TEST(ModelCheckWarning, BodyMassOutOfRange) {
  const ModelCheckReport r =
      check_mutated("thesis_bogie_tangent", {{"mass_kg = 3020.0", "mass_kg = 30200.0"}});
  EXPECT_TRUE(r.has_warning("body_mass_out_of_range")) << warning_list(r);
}

TEST(ModelCheckWarning, CarBodyMassInTonnes) {
  const ModelCheckReport r =
      check_mutated("thesis_vehicle_tangent", {{"mass_kg = 43200.0", "mass_kg = 43.2"}});
  EXPECT_TRUE(r.has_warning("unit_looks_wrong")) << warning_list(r);
  EXPECT_NE(warning_list(r).find("looks like tonnes"), std::string::npos) << warning_list(r);
}

TEST(ModelCheckWarning, InertiaInTonneSquareMetres) {
  const ModelCheckReport r = check_mutated(
      "thesis_bogie_tangent",
      {{"inertia_kg_m2 = [2130.912, 4063.712, 4063.712]", "inertia_kg_m2 = [2.130912, 4.063712, 4.063712]"}});
  EXPECT_TRUE(r.has_warning("inertia_out_of_range")) << warning_list(r);
}

TEST(ModelCheckWarning, AxleLoadOutOfRange) {
  // Every mass within its body range, the axle load (1200/2 + 600) g = 11.8 kN is not.
  std::vector<std::pair<std::string, std::string>> edits = {
      {"mass_kg = 1500.0", "mass_kg = 600.0"},
      {"mass_kg = 1500.0", "mass_kg = 600.0"},
      {"mass_kg = 3020.0", "mass_kg = 1200.0"}};
  const ModelCheckReport r = check_mutated("thesis_bogie_tangent", edits);
  EXPECT_TRUE(r.has_warning("axle_load_out_of_range")) << warning_list(r);
  EXPECT_FALSE(r.has_warning("body_mass_out_of_range")) << warning_list(r);
}

TEST(ModelCheckWarning, LongitudinalCoordinateUnheld) {
  // The bogie frame's x freed: nothing holds the bogie and its wheelsets
  // along the track (creep forces resist the rate only).
  const ModelCheckReport r = check_mutated(
      "thesis_bogie_tangent", {{"free = [\"y\", \"z\", \"roll\", \"pitch\", \"yaw\"]",
                                "free = [\"x\", \"y\", \"z\", \"roll\", \"pitch\", \"yaw\"]"}});
  EXPECT_TRUE(r.has_warning("longitudinal_unheld")) << warning_list(r);
}

TEST(ModelCheckWarning, ContactDistanceMismatch) {
  // Half the track gauge (1.435 m) instead of half the contact distance.
  const ModelCheckReport r = check_mutated(
      "thesis_bogie_tangent", {{"half_contact_distance_m = 0.75", "half_contact_distance_m = 0.7175"}});
  EXPECT_TRUE(r.has_warning("contact_distance_mismatch")) << warning_list(r);
}

// A height given in millimetres (1057.5 for 1.0575 m) is refused by the
// scene reader's range ([-100, 100] m); between the check's 50 m and that
// range, the check warns that the unit looks wrong.
TEST(ModelCheckWarning, PositionInMillimetres) {
  EXPECT_THROW(check_mutated("thesis_bogie_tangent",
                             {{"position_m = [0.0, 0.0, 1.0575]", "position_m = [0.0, 0.0, 1057.5]"}}),
               SceneError);
  const ModelCheckReport r = check_mutated(
      "thesis_bogie_tangent",
      {{"position_m = [0.0, 0.0, 1.0575]", "position_m = [0.0, 0.0, 60.0]"}});
  EXPECT_TRUE(r.has_warning("unit_looks_wrong")) << warning_list(r);
}

TEST(ModelCheckWarning, StaticDeflectionLarge) {
  // Primary vertical stiffness 100x too soft: 7.4 kN / 9750 N/m = 0.76 m.
  std::vector<std::pair<std::string, std::string>> edits = {
      {"stiffness_N_per_m = [3.9e7, 7.85e6, 9.75e5]", "stiffness_N_per_m = [3.9e7, 7.85e6, 9.75e3]"},
      {"stiffness_N_per_m = [3.9e7, 7.85e6, 9.75e5]", "stiffness_N_per_m = [3.9e7, 7.85e6, 9.75e3]"}};
  const ModelCheckReport r = check_mutated("thesis_bogie_tangent", edits);
  EXPECT_TRUE(r.has_warning("static_deflection_large")) << warning_list(r);
}

}  // namespace
}  // namespace railstab
