// Mode names on shipped cases against their shapes (issue 24, item 2: "a
// mode named 'bogies in phase' has the rear bogie 34 degrees behind", "check
// calls a 12.5 Hz mode hunting at standstill", "ten modes ... all 'bogie
// hunting, bogies in phase (N)'"). Each name's claim is recomputed here from
// the mode's shape (stability/point_mode_shapes.hpp) with the rule written
// in docs/model.md section 10, not with the naming code:
// - "hunting" only where, on the wheelset with the most lateral + yaw
//   kinetic energy, z = (psi / y) / (i omega / V) has |arg z| <= 45 deg and
//   1/2 <= |z| <= 2; "lateral/yaw" only where that fails;
// - "bogies in phase" / "anti-phase" only where the two bogie frames' lateral
//   displacements are within 30 deg of 0 / 180 deg; otherwise
//   "bogie2 N deg ahead of/behind bogie1" with N that phase rounded to 10 deg
//   (checked where the frames' lateral motion is not negligible);
// - no " (N)" counter among the modes in the hunting band.
// Cases: the coach (cases/coach_tangent.toml) at 150 m/s and at 1 m/s
// (nearly at rest: hunting only at the kinematic 0.06 Hz), the thesis
// vehicle on S1002 at its critical speed 118.53 m/s. Under 1 s.
#include <railstab/setup/prepare_scene.hpp>
#include <railstab/stability/point_mode_shapes.hpp>
#include <railstab/stability/speed_analysis.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "support/test_files.hpp"

using namespace railstab;

namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

struct Checked {
  int hunting = 0, lateral_yaw = 0, phase_words = 0;
  double highest_hunting_hz = 0.0;
};

std::complex<double> displacement(const Model& model, const ModeShape& s, const std::string& body,
                                  CoordinateIndex c) {
  for (const CoordinateMotion& m : s.coordinates)
    if (model.bodies[size_t(m.body)].name == body && m.coordinate == int(c)) return m.displacement;
  return 0.0;
}

Checked check_names(const std::string& scene, double speed_m_per_s) {
  SceneOverrides at_speed;
  at_speed.speed_m_per_s = speed_m_per_s;
  const PreparedScene s = prepare_scene(test::case_path(scene), at_speed);
  const Model& model = s.model;
  SpeedStability st(model, s.equilibrium.state, s.speed_m_per_s);
  const StabilityPoint p = st.at(speed_m_per_s);
  const std::vector<ModeShape> shapes = full_mode_shapes(model, p);
  Checked out;
  for (size_t k = 0; k < p.modes.size(); ++k) {
    const ModeReport& m = p.modes[k];
    if (m.neutral || m.eigenvalue.imag() <= 0.0 || m.frequency_hz > 20.0) continue;
    const std::string where = scene + " at " + std::to_string(speed_m_per_s) + " m/s, '" + m.name + "'";
    EXPECT_EQ(m.name.find(" ("), std::string::npos) << where;
    const ModeShape& shape = shapes[k];
    // The wheelset with the most lateral + yaw kinetic energy.
    std::string wheelset;
    double most = -1.0;
    for (const Body& b : model.bodies) {
      if (!b.wheelset()) continue;
      double e = 0.0;
      for (const CoordinateMotion& c : shape.coordinates)
        if (model.bodies[size_t(c.body)].name == b.name &&
            (c.coordinate == int(CoordinateIndex::y) || c.coordinate == int(CoordinateIndex::yaw)))
          e += c.kinetic_share;
      if (e > most) {
        most = e;
        wheelset = b.name;
      }
    }
    const std::complex<double> y = displacement(model, shape, wheelset, CoordinateIndex::y);
    const std::complex<double> psi = displacement(model, shape, wheelset, CoordinateIndex::yaw);
    const double omega = m.eigenvalue.imag();
    const std::complex<double> z =
        std::abs(y) > 0.0 ? (psi / y) / std::complex<double>(0.0, omega / speed_m_per_s) : 0.0;
    const bool kinematic = std::abs(std::arg(z)) * kDeg <= 45.0 && std::abs(z) >= 0.5 &&
                           std::abs(z) <= 2.0;
    if (m.name.find("hunting") != std::string::npos) {
      EXPECT_TRUE(kinematic) << where << ": z = " << z;
      ++out.hunting;
      out.highest_hunting_hz = std::max(out.highest_hunting_hz, m.frequency_hz);
    }
    if (m.name.find("lateral/yaw") != std::string::npos) {
      EXPECT_FALSE(kinematic) << where << ": z = " << z;
      ++out.lateral_yaw;
    }
    // Phase words of the two bogie frames, where both move laterally.
    const std::complex<double> b1 = displacement(model, shape, "bogie1", CoordinateIndex::y);
    const std::complex<double> b2 = displacement(model, shape, "bogie2", CoordinateIndex::y);
    const bool two_units = m.name.rfind("bogie ", 0) == 0 &&
                           (m.name.find("bogies ") != std::string::npos ||
                            m.name.find(" deg ") != std::string::npos);
    if (std::abs(b1) < 0.05 || std::abs(b2) < 0.05 || !two_units) continue;
    if (m.name.find("lateral/yaw") == std::string::npos && m.name.find("hunting") == std::string::npos)
      continue;  // the phase of another coordinate (roll, pitch, bounce) names those
    const double theta = std::arg(b2 / b1) * kDeg;  // > 0: bogie2 ahead
    if (m.name.find("bogies in phase") != std::string::npos) {
      EXPECT_LE(std::abs(theta), 30.0) << where;
    } else if (m.name.find("bogies anti-phase") != std::string::npos) {
      EXPECT_GE(std::abs(theta), 150.0) << where;
    } else {
      const size_t at = m.name.find(" deg ");
      EXPECT_NE(at, std::string::npos) << where;
      if (at == std::string::npos) continue;
      const size_t start = m.name.rfind(' ', at - 1) + 1;
      const double stated = std::stod(m.name.substr(start, at - start));
      const bool ahead = m.name.find("ahead", at) != std::string::npos;
      EXPECT_NEAR(ahead ? theta : -theta, stated, 5.0 + 1e-9) << where << ": phase " << theta;
    }
    ++out.phase_words;
  }
  return out;
}

}  // namespace

TEST(ModeNamesOnShippedCases, CoachAt150MetresPerSecondNamesAgreeWithTheShapes) {
  const Checked c = check_names("coach_tangent", 150.0);
  EXPECT_GE(c.hunting, 2);      // the 16 Hz pair
  EXPECT_GE(c.lateral_yaw, 2);  // the 5.6-5.7 Hz pair, not hunting
  EXPECT_GE(c.phase_words, 4);
}

// At 1 m/s the kinematic (hunting) modes are at 0.06 Hz (wavelength 17 m):
// those alone are hunting; the 12.5 Hz bogie lateral/yaw pair that `check`
// once called hunting at rest is not.
TEST(ModeNamesOnShippedCases, CoachNearlyAtRestHuntsOnlyAtTheKinematicFrequency) {
  const Checked c = check_names("coach_tangent", 1.0);
  EXPECT_GE(c.hunting, 1);
  EXPECT_LT(c.highest_hunting_hz, 0.1);
  EXPECT_GE(c.lateral_yaw, 2);
}

TEST(ModeNamesOnShippedCases, S1002VehicleAtItsCriticalSpeedNamesAgreeWithTheShapes) {
  const Checked c = check_names("thesis_vehicle_s1002_tangent", 118.53);
  EXPECT_GE(c.hunting, 1);  // the crossing mode
}
