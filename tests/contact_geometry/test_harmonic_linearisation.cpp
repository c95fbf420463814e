// The harmonic (describing-function) linearisation against closed forms
// (contact_geometry/harmonic_linearisation.hpp): a straight line (gain =
// slope at every amplitude), a cubic about 0 and off 0, the textbook
// saturation and dead zone (e.g. Gelb and Vander Velde, "Multiple-input
// describing functions", 1968, table of describing functions), with their
// kinks given as breakpoints (the rule's stated error: exponential
// convergence on each smooth piece, < 1e-13 here) and without (an O(h^2)
// piece error, bounded here). And the rigid-contact functions of S1002 on
// UIC60: the equivalent conicity N_dr(A)/2 against an independent midpoint
// integration of the contact-geometry's own delta r function.
#include <gtest/gtest.h>

#include "support/test_files.hpp"

#include <railstab/contact_geometry/characteristic_functions.hpp>
#include <railstab/contact_geometry/equivalent_conicity.hpp>
#include <railstab/contact_geometry/harmonic_linearisation.hpp>
#include <railstab/contact_geometry/profile_contact_geometry.hpp>
#include <railstab/contact_geometry/quasi_linear_contact.hpp>
#include <railstab/setup/contact_tables.hpp>

#include <cmath>
#include <numbers>

using namespace railstab;

namespace {

// Saturation k y for |y| <= a, k a sign(y) beyond: for A > a
//   N = (2k/pi) (asin(a/A) + (a/A) sqrt(1 - (a/A)^2)), N = k for A <= a.
double saturation_gain(double k, double a, double A) {
  if (A <= a) return k;
  const double r = a / A;
  return 2.0 * k / std::numbers::pi * (std::asin(r) + r * std::sqrt(1 - r * r));
}

}  // namespace

TEST(HarmonicLinearisation, StraightLineGainIsItsSlopeAtEveryAmplitude) {
  const double r0 = 0.46, lambda = 0.15;
  auto f = [&](double y) { return r0 + lambda * y; };
  for (double centre : {0.0, 2e-3, -4e-3})
    for (double A : {1e-6, 1e-4, 1e-3, 5e-3, 1e-2}) {
      const HarmonicLinearisation h = harmonic_linearisation(f, centre, A);
      // 1e-12 relative, plus what floating point cannot resolve: f itself
      // is rounded to eps |f| (a radius of 0.46 m) and the argument
      // y_c + A sin(th) to eps |y_c|, both against the motion's lambda A
      // (the bound is below 1e-12 relative for A >= 1 mm, 7e-9 at 1 um).
      const double rounding = 10 * 2.2e-16 * (std::abs(f(centre)) + lambda * std::abs(centre)) / A;
      EXPECT_NEAR(h.gain, lambda, 1e-12 * lambda + rounding) << "A = " << A << ", centre " << centre;
      EXPECT_NEAR(h.bias, f(centre), 1e-12 * r0);
    }
}

TEST(HarmonicLinearisation, CubicGainAndBiasInClosedForm) {
  // f = k y + c y^3 about y_c: f(y_c + A s) has the first harmonic
  // (k + 3 c y_c^2 + 3/4 c A^2) A s and the mean k y_c + c (y_c^3 + 3/2 y_c A^2).
  const double k = 0.2, c = 4.0e3;
  auto f = [&](double y) { return k * y + c * y * y * y; };
  for (double yc : {0.0, 1.5e-3})
    for (double A : {1e-4, 1e-3, 3e-3, 8e-3}) {
      const HarmonicLinearisation h = harmonic_linearisation(f, yc, A);
      const double gain = k + 3 * c * yc * yc + 0.75 * c * A * A;
      const double bias = k * yc + c * (yc * yc * yc + 1.5 * yc * A * A);
      EXPECT_NEAR(h.gain, gain, 1e-13 * gain) << "A = " << A << ", y_c = " << yc;
      EXPECT_NEAR(h.bias, bias, 1e-13 * (std::abs(bias) + k * A));
    }
}

TEST(HarmonicLinearisation, SaturationAndDeadZoneAsTheTextbookDescribingFunctions) {
  const double k = 0.3, a = 1e-3;
  auto sat = [&](double y) { return k * std::clamp(y, -a, a); };
  // Dead zone of half-width a: y - sat(y) (times k): N = k - N_sat.
  auto dead = [&](double y) { return k * y - sat(y); };
  for (double A : {0.5e-3, 1e-3, 1.2e-3, 3e-3, 10e-3}) {
    const double n_sat = saturation_gain(k, a, A);
    const HarmonicLinearisation s = harmonic_linearisation(sat, 0.0, A, {-a, a});
    const HarmonicLinearisation d = harmonic_linearisation(dead, 0.0, A, {-a, a});
    EXPECT_NEAR(s.gain, n_sat, 1e-13 * k) << "A = " << A;
    EXPECT_NEAR(d.gain, k - n_sat, 1e-13 * k) << "A = " << A;
    EXPECT_NEAR(s.bias, 0.0, 1e-15);
    // Without the kinks as breakpoints: one piece with two kinks, O(h^2)
    // per the header; bounded at 5e-3 of k here (measured up to 1.8e-3).
    const HarmonicLinearisation blind = harmonic_linearisation(sat, 0.0, A);
    EXPECT_NEAR(blind.gain, n_sat, 5e-3 * k) << "A = " << A;
  }
}

TEST(HarmonicLinearisation, RejectsAnAmplitudeThatIsNotPositiveAndFinite) {
  auto f = [](double y) { return y; };
  for (double A : {0.0, -1e-3, std::nan(""), double(INFINITY)})
    EXPECT_THROW(harmonic_linearisation(f, 0.0, A), std::invalid_argument) << A;
}

// S1002 on UIC60 1:40 (the Manchester benchmark pair): the quasi-linear
// contact's equivalent conicity N_dr(A)/2 against the harmonic integral of
// the delta r function that contact-geometry samples itself
// (characteristic_functions, 0.01 mm, a different sampling than the
// quasi-linear contact's 0.02 mm), integrated here by a plain midpoint rule
// in theta with 20000 points: both are the same definition, so they agree
// to the sampling (1 %, the jumps of delta r fall between samples
// differently). Against EN 15302's Klingel-wavelength conicity (a different
// definition: the wavelength of the nonlinear kinematic motion) they are
// close, not equal: within 25 % at 1 .. 5 mm (measured, docs/quasi_linear.md).
TEST(QuasiLinearContact, S1002EquivalentConicityIsTheHarmonicIntegralOfDeltaR) {
  const std::vector<ContactSpec> contacts = load_scene_contacts(test::case_path("s1002_uic60_contact"));
  ASSERT_EQ(contacts.size(), 1u);
  const auto geometry = contacts[0].profile_geometry;
  const QuasiLinearContact ql(geometry);
  const std::vector<CharacteristicRow> rows =
      characteristic_functions(geometry->pair, -0.011, 0.011, 1e-5);
  DeltaRFunction dr;
  for (const CharacteristicRow& r : rows) {
    dr.y_m.push_back(r.solution.lateral_m);
    dr.delta_r_m.push_back(r.delta_r_m());
  }
  const double e0 = geometry->pair.wheel_offset_y_m, r0 = geometry->pair.parameters.nominal_rolling_radius_m;
  for (double A : {0.5e-3, 1e-3, 2e-3, 3e-3, 4e-3, 5e-3}) {
    const int n = 20000;
    double sum = 0;
    for (int i = 0; i < n; ++i) {
      const double th = 2 * std::numbers::pi * (i + 0.5) / n;
      sum += dr(A * std::sin(th)) * std::sin(th);
    }
    const double harmonic = 0.5 * sum * (2 * std::numbers::pi / n) / (std::numbers::pi * A);
    const QuasiLinearGains g = ql.gains(0.0, A);
    EXPECT_NEAR(g.equivalent_conicity, harmonic, 0.01 * harmonic) << "A = " << A;
    EXPECT_TRUE(std::isfinite(g.equivalent_conicity));
    if (A >= 1e-3) {
      const double klingel = equivalent_conicity(dr, A, e0, r0).equivalent_conicity;
      EXPECT_NEAR(g.equivalent_conicity, klingel, 0.25 * klingel) << "A = " << A;
    }
  }
  // The centre of the symmetric pair: the left wheel's rolling radius gain
  // is half the delta r gain at y_c = 0.
  const QuasiLinearGains g3 = ql.gains(0.0, 3e-3);
  EXPECT_NEAR(g3.gain[size_t(int(RigidFunction::rolling_radius_m))], g3.equivalent_conicity, 1e-12);
  EXPECT_GT(ql.flange_contact_shift_m(), 4e-3);
  EXPECT_LT(ql.flange_contact_shift_m(), 9e-3);
  EXPECT_THROW(ql.gains(0.0, ql.half_range_m() + 1e-4), std::invalid_argument);
}

// The equivalent table is the planes it is built from: at the rigid pose
// of the centre it returns F(y_c), and along the rigid motion
// (dq, dtheta) = (N_q, N_theta) dy its slope is N_F (the construction's
// defining property, through the table's Hermite interpolation).
TEST(QuasiLinearContact, EquivalentTableCarriesTheGainsAlongTheMotion) {
  const std::vector<ContactSpec> contacts = load_scene_contacts(test::case_path("s1002_uic60_contact"));
  const auto geometry = contacts[0].profile_geometry;
  const QuasiLinearContact ql(geometry);
  for (double yc : {0.0, 2e-3}) {
    const double A = 1.5e-3;
    const QuasiLinearGains g = ql.gains(yc, A);
    const ContactTable t = ql.equivalent_table(yc, A);
    ASSERT_EQ(t.slots(), 1);
    const double q = g.at_centre[size_t(int(RigidFunction::lateral_q_m))];
    const double th = g.at_centre[size_t(int(RigidFunction::roll_theta_rad))];
    const double Nq = g.gain[size_t(int(RigidFunction::lateral_q_m))];
    const double Nth = g.gain[size_t(int(RigidFunction::roll_theta_rad))];
    const double dy = 1e-4;
    auto at = [&](double s) {
      return t.evaluate<double>(0, {t.nominal_lateral_m() + q + s * Nq * dy, 0.0, th + s * Nth * dy});
    };
    const TableContact<double> c0 = at(0), cp = at(1), cm = at(-1);
    const double r_gain = g.gain[size_t(int(RigidFunction::rolling_radius_m))];
    const double gamma_gain = g.gain[size_t(int(RigidFunction::contact_angle_rad))];
    EXPECT_NEAR(c0.rolling_radius_m, g.at_centre[size_t(int(RigidFunction::rolling_radius_m))], 1e-12);
    EXPECT_NEAR(c0.vertical_gap_m, g.at_centre[size_t(int(RigidFunction::gap0_m))], 1e-12);
    EXPECT_NEAR((cp.rolling_radius_m - cm.rolling_radius_m) / (2 * dy), r_gain, 1e-9 * std::abs(r_gain) + 1e-12);
    EXPECT_NEAR((cp.contact_angle_rad - cm.contact_angle_rad) / (2 * dy), gamma_gain,
                1e-9 * std::abs(gamma_gain) + 1e-10);
    EXPECT_EQ(c0.interior_weight, 1.0);
  }
}
