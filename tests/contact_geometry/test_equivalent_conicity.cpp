// EN 15302 equivalent conicity by Klingel integration.
#include <railstab/contact_geometry/characteristic_functions.hpp>
#include <railstab/contact_geometry/contact_geometry_summary.hpp>
#include <railstab/contact_geometry/equivalent_conicity.hpp>
#include "contact_geometry/synthetic_profiles.hpp"
#include <railstab/profiles/profile_readers.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include "support/benchmark_profiles.hpp"

using namespace railstab;
using namespace railstab::testing;

// Linear delta_r = 2 lambda y: the Klingel wavelength 2 pi sqrt(r0 e0 / lambda)
// and conicity lambda at every amplitude (the integrator's error).
TEST(EquivalentConicity, LinearDeltaRGivesItsConicityAtEveryAmplitude) {
  DeltaRFunction dr;
  for (int i = -300; i <= 300; ++i) {
    dr.y_m.push_back(i * 5e-5);
    dr.delta_r_m.push_back(2 * 0.12 * i * 5e-5);
  }
  for (double a : {0.0005, 0.003, 0.01}) {
    const ConicityPoint c = equivalent_conicity(dr, a, 0.75, 0.46);
    EXPECT_NEAR(c.equivalent_conicity, 0.12, 1e-9);
    EXPECT_NEAR(c.wavelength_m, 2 * std::numbers::pi * std::sqrt(0.46 * 0.75 / 0.12), 1e-7);
  }
}

// Cubic delta_r = 2 lambda y + c y^3: harmonic balance (first harmonic) gives
// lambda_e = lambda + 3 c A^2 / 8 to first order in c A^2 / lambda.
TEST(EquivalentConicity, CubicDeltaRMatchesHarmonicBalance) {
  DeltaRFunction dr;
  const double lambda = 0.1, c = 400.0;  // c A^2 = 0.0036 at 3 mm
  for (int i = -2000; i <= 2000; ++i) {
    const double y = i * 1e-5;
    dr.y_m.push_back(y);
    dr.delta_r_m.push_back(2 * lambda * y + c * y * y * y);
  }
  const double A = 0.003;
  const ConicityPoint p = equivalent_conicity(dr, A, 0.75, 0.46);
  EXPECT_NEAR(p.equivalent_conicity, lambda + 3 * c * A * A / 8, 5e-5);
}

// A cone on a circular rail: delta_r = 2 c sin(phi) exactly (c: the
// crown centre's lateral position, test_en15302.cpp), nearly linear in the
// standard's lateral displacement y = y_c + r0 sin(phi), so the equivalent
// conicity equals its secant delta_r(A)/(2A) to 1e-3 and the closed-form
// slope c / (c (1/t + t) - R sqrt(1 + t^2) - D t) to 1e-3 (tan(gamma)
// times about 1/(1 - t R / e0): the roll coupling through the crown radius).
// Until issue 23 this test asserted t / (1 - t h / e0), h = r0 + R the
// axle's height above the crown centre: the same closed form in the
// wheelset centre's shift y_c, which EN 15302 does not use (its y excludes
// the roll's r0 sin(phi); docs/en15302.md).
TEST(EquivalentConicity, ConicalPairGivesTanGammaWithTheRollCoupling) {
  const double t = 0.05, R = 0.3;
  ProfilePairParameters p;
  p.gauge_measuring_height_m = 0.002;
  const double y_g = -std::sqrt(R * R - (R - 0.002) * (R - 0.002));
  p.track_gauge_m = 2.0 * (0.5 * p.flange_back_distance_m + p.tape_circle_from_flange_back_m + y_g);
  const ProfilePair pair = make_profile_pair(cone_wheel(t), circular_rail(R, 0.040), p);
  ContactGeometrySummaryOptions o;
  const ContactGeometrySummary s = summarise_contact_geometry(pair, o);
  const RigidContactSolution at3 = solve_rigid_contact(WheelsetProfilePairs{pair, pair}, 0.003,
                                                       0.0, LateralShiftReference::en15302);
  const double secant =
      (at3.left.front().rolling_radius_m - at3.right.front().rolling_radius_m) / (2 * 0.003);
  EXPECT_NEAR(s.equivalent_conicity_at_3mm, secant, 1e-3 * secant);
  const double c = pair.rail_offset_y_m, D = pair.wheel_offset_y_m;
  EXPECT_NEAR(s.equivalent_conicity_at_3mm,
              c / (c * (1 / t + t) - R * std::sqrt(1 + t * t) - D * t), 1e-3 * t);
  EXPECT_FALSE(s.flange.found);
}

// The benchmark pair: reported, not tuned. Published values for new
// S1002/UIC60 1:40 at 1435 mm are around 0.15-0.2 at 3 mm; this code gives
// 0.1810 (yaw neglected, rigid contact) in EN 15302's lateral displacement
// y = y_c + r0 sin(roll). Until issue 23 it gave 0.1836 over the wheelset
// centre's shift y_c. The change is checked independently here: the
// characteristic functions solved over y_c (the other solver path), each
// sample moved to y_c + r0 sin(roll), give the same conicity (to the
// sampling, 2e-5; measured 1e-6).
TEST(EquivalentConicity, BenchmarkPairAt3mm) {
  const ProfilePair pair = railstab::test::benchmark_profile_pair();
  const ContactGeometrySummary s = summarise_contact_geometry(pair);
  EXPECT_NEAR(s.equivalent_conicity_at_3mm, 0.1810, 0.0005);
  EXPECT_GT(s.equivalent_conicity_at_3mm, 0.15);
  EXPECT_LT(s.equivalent_conicity_at_3mm, 0.20);
  ASSERT_EQ(s.conicity.size(), 20u);
  EXPECT_NEAR(s.conicity.front().amplitude_m, 0.0005, 1e-12);
  EXPECT_NEAR(s.conicity.back().amplitude_m, 0.010, 1e-12);

  DeltaRFunction remapped;
  for (const CharacteristicRow& r : characteristic_functions(pair, -0.015, 0.015, 5e-5)) {
    remapped.y_m.push_back(r.solution.lateral_m + 0.46 * std::sin(r.solution.roll_rad));
    remapped.delta_r_m.push_back(r.delta_r_m());
  }
  const double via_centre =
      equivalent_conicity(remapped, 0.003, s.half_contact_distance_m, 0.46).equivalent_conicity;
  EXPECT_NEAR(s.equivalent_conicity_at_3mm, via_centre, 2e-5);
}
