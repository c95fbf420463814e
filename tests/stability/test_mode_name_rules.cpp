// Mode names say what the shape is (issue 24 item 2): "in phase" and
// "anti-phase" only within kPhaseToleranceDeg, otherwise the phase in
// degrees with who is behind; "hunting" only where the wheelsets yaw and
// translate as a rolling wheelset does (psi / y = i omega / V); equal names
// told apart by words (the dominant body, the frequency), not by counters.
// The shapes are written by hand on the thesis vehicle's bodies, so the
// expected names follow from the rules in stability/mode_names.hpp alone.
#include <gtest/gtest.h>

#include <railstab/setup/prepare_scene.hpp>
#include <railstab/stability/mode_names.hpp>

#include <cmath>
#include <complex>

#include "support/test_files.hpp"

using namespace railstab;
using cd = std::complex<double>;

namespace {

const PreparedScene& vehicle() {
  static const PreparedScene s = prepare_scene(test::case_path("thesis_vehicle_tangent"), {});
  return s;
}

int body(const char* name) { return vehicle().model.find_body(name); }

// Both bogies and their wheelsets in lateral + yaw: the frames' lateral
// displacements 1 and exp(i theta), each wheelset with its frame's lateral
// and a yaw of psi_per_y times it. Equal kinetic shares on the two units.
ModeShape two_bogie_shape(double theta_deg, cd psi_per_y) {
  ModeShape shape;
  const cd b2 = std::polar(1.0, theta_deg * M_PI / 180.0);
  const std::pair<const char*, cd> units[] = {{"bogie1", 1.0}, {"bogie2", b2}};
  const std::pair<const char*, int> wheelsets[] = {
      {"wheelset1", 0}, {"wheelset2", 0}, {"wheelset3", 1}, {"wheelset4", 1}};
  for (const auto& [frame, q] : units) shape.coordinates.push_back({body(frame), 1, q, 0.1, 0.0});
  for (const auto& [w, unit] : wheelsets) {
    const cd q = units[unit].second;
    shape.coordinates.push_back({body(w), 1, q, 0.15, 0.0});
    shape.coordinates.push_back({body(w), 5, q * psi_per_y, 0.05, 0.0});
  }
  return shape;
}

std::string name_of(const ModeShape& shape, cd lambda, double speed) {
  return mode_name_from_shape(vehicle().model, body_roles(vehicle().model), shape, lambda, speed);
}

}  // namespace

TEST(ModeNameRules, PhaseWordsOnlyWithinTheTolerance) {
  const double V = 100.0, omega = 2.0 * M_PI * 4.0;
  const cd lambda(-0.1, omega), kinematic(0.0, omega / V);  // psi / y = i omega / V
  EXPECT_EQ(name_of(two_bogie_shape(0.0, kinematic), lambda, V), "bogie hunting, bogies in phase");
  EXPECT_EQ(name_of(two_bogie_shape(-29.0, kinematic), lambda, V), "bogie hunting, bogies in phase");
  // The "in phase" with the rear bogie 34 deg behind.
  EXPECT_EQ(name_of(two_bogie_shape(-34.0, kinematic), lambda, V),
            "bogie hunting, bogie2 30 deg behind bogie1");
  EXPECT_EQ(name_of(two_bogie_shape(68.0, kinematic), lambda, V),
            "bogie hunting, bogie2 70 deg ahead of bogie1");
  EXPECT_EQ(name_of(two_bogie_shape(-100.0, kinematic), lambda, V),
            "bogie hunting, bogie2 100 deg behind bogie1");
  EXPECT_EQ(name_of(two_bogie_shape(151.0, kinematic), lambda, V), "bogie hunting, bogies anti-phase");
  EXPECT_EQ(name_of(two_bogie_shape(-180.0, kinematic), lambda, V), "bogie hunting, bogies anti-phase");
  // The conjugate shape (Im lambda < 0) is the same motion: the same name.
  ModeShape conjugate = two_bogie_shape(-34.0, kinematic);
  for (CoordinateMotion& c : conjugate.coordinates) c.displacement = std::conj(c.displacement);
  EXPECT_EQ(name_of(conjugate, std::conj(lambda), V), "bogie hunting, bogie2 30 deg behind bogie1");
}

TEST(ModeNameRules, HuntingOnlyInTheKinematicRelation) {
  const double V = 100.0, omega = 2.0 * M_PI * 4.0;
  const cd lambda(-0.1, omega), kinematic(0.0, omega / V);
  // Within the tolerances: phase 90 +- 45 deg, ratio within a factor 2.
  EXPECT_EQ(name_of(two_bogie_shape(0.0, kinematic * std::polar(1.9, 0.7)), lambda, V),
            "bogie hunting, bogies in phase");
  // Yaw lagging the lateral motion (phase -90 deg): not a rolling wheelset.
  EXPECT_EQ(name_of(two_bogie_shape(0.0, -kinematic), lambda, V), "bogie lateral/yaw, bogies in phase");
  // In phase with the lateral motion (0 deg), or the ratio 3x too large.
  EXPECT_EQ(name_of(two_bogie_shape(0.0, cd(omega / V, 0.0)), lambda, V),
            "bogie lateral/yaw, bogies in phase");
  EXPECT_EQ(name_of(two_bogie_shape(0.0, 3.0 * kinematic), lambda, V),
            "bogie lateral/yaw, bogies in phase");
  // At standstill nothing hunts (check's 12.5 Hz "hunting" at 0 m/s).
  EXPECT_EQ(name_of(two_bogie_shape(0.0, kinematic), cd(-5.0, 2.0 * M_PI * 12.5), 0.0),
            "bogie lateral/yaw, bogies in phase");
  // A real mode is never hunting.
  EXPECT_EQ(name_of(two_bogie_shape(0.0, kinematic), cd(-3.0, 0.0), V),
            "bogie lateral/yaw, bogies in phase, aperiodic");
}

TEST(ModeNameRules, EqualNamesToldApartInWords) {
  // Three modes of one name: the dominant body separates two of them, the
  // frequency the third pair; a conjugate partner copies its mate.
  std::vector<std::string> names(4, "bogie lateral/yaw, bogies in phase");
  const std::vector<std::vector<std::string>> q = {
      mode_qualifiers("wheelset1", cd(-1.0, 2.0 * M_PI * 3.14)),
      mode_qualifiers("bogie1", cd(-1.0, 2.0 * M_PI * 12.5)),
      mode_qualifiers("bogie1", cd(-1.0, 2.0 * M_PI * 16.0)),
      mode_qualifiers("wheelset1", cd(-1.0, -2.0 * M_PI * 3.14))};
  make_names_unique(names, {-1, -1, -1, 0}, {0.1, 0.2, 0.3, 0.1}, q);
  EXPECT_EQ(names[0], "bogie lateral/yaw, bogies in phase, mostly wheelset1, 3.14 Hz");
  EXPECT_EQ(names[1], "bogie lateral/yaw, bogies in phase, mostly bogie1, 12.5 Hz");
  EXPECT_EQ(names[2], "bogie lateral/yaw, bogies in phase, mostly bogie1, 16 Hz");
  EXPECT_EQ(names[3], names[0]);
  // One level suffices: it is the only one added.
  std::vector<std::string> two(2, "car body yaw");
  make_names_unique(two, {}, {}, {mode_qualifiers("carbody", cd(-1, 6.0)),
                                  mode_qualifiers("bogie2", cd(-1, 6.0))});
  EXPECT_EQ(two[0], "car body yaw, mostly carbody");
  EXPECT_EQ(two[1], "car body yaw, mostly bogie2");
  // Real modes: the rate. Words that still collide get counters.
  EXPECT_EQ(mode_qualifiers("wheelset2", cd(-12.5, 0.0))[1], "rate -12.5 1/s");
  std::vector<std::string> same(2, "x");
  make_names_unique(same, {}, {0.2, 0.1}, {mode_qualifiers("a", cd(-1, 1)), mode_qualifiers("a", cd(-1, 1))});
  EXPECT_EQ(same[1], "x, mostly a, 0.159 Hz");
  EXPECT_EQ(same[0], "x, mostly a, 0.159 Hz (2)");
}
