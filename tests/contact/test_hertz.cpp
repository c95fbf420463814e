// Hertz normal contact: closed-form circle, the curvature-ratio equation,
// consistency of the load-approach law, the seed wheel/rail case, and AD
// derivatives against central differences.
#include <railstab/contact/hertz.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

using namespace railstab;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kEps = std::numeric_limits<double>::epsilon();
const double kStepScale = std::cbrt(kEps);  // central-difference step / scale

// Seed data (ERRATA 8): steel on steel.
constexpr double kSteelYoung = 2.1e11;
constexpr double kSteelPoisson = 0.25;

double relative_error(double value, double reference) {
  return std::abs(value - reference) / std::abs(reference);
}

// An AD variable: value x, derivative 1 in direction `direction`.
AdScalar ad_variable(double x, int direction) {
  return AdScalar(x, AdDerivatives::Unit(direction));
}

// Curvature-ratio equation of the Hertz ellipse (Johnson 4.2), k = n/m <= 1:
//   rho(k) = [(1/k^2) E(e) - K(e)] / [K(e) - E(e)],  e = sqrt(1 - k^2).
double curvature_ratio_equation(double k) {
  const double e = std::sqrt(1.0 - k * k);
  const double K = std::comp_ellint_1(e), E = std::comp_ellint_2(e);
  return (E / (k * k) - K) / (K - E);
}

double minor_over_major(const HertzShape<double>& s) {
  return std::min(s.a_over_b, 1.0 / s.a_over_b);
}

std::vector<double> field_values(const HertzShape<double>& s) {
  return {s.a_over_b, s.stiffness, s.approach_per_force_23, s.semi_axis_a_per_force_13,
          s.semi_axis_b_per_force_13};
}

std::vector<AdScalar> field_values(const HertzShape<AdScalar>& s) {
  return {s.a_over_b, s.stiffness, s.approach_per_force_23, s.semi_axis_a_per_force_13,
          s.semi_axis_b_per_force_13};
}

const char* const kFieldNames[] = {"a_over_b", "stiffness", "approach_per_force_23",
                                   "semi_axis_a_per_force_13", "semi_axis_b_per_force_13"};

// Curvature pairs (A, B) with B/A = 1.2, 1.5, 3, 10, 100 and the mirrored A > B cases.
std::vector<std::pair<double, double>> curvature_pairs() {
  std::vector<std::pair<double, double>> pairs;
  for (double ratio : {1.2, 1.5, 3.0, 10.0, 100.0}) {
    pairs.emplace_back(0.8, 0.8 * ratio);
    pairs.emplace_back(2.5 * ratio, 2.5);
  }
  return pairs;
}

}  // namespace

// ---------------------------------------------------------------------------
// Materials

TEST(CombineMaterials, IdenticalMaterials) {
  const ElasticPair p = combine_materials(kSteelYoung, kSteelPoisson, kSteelYoung, kSteelPoisson);
  // E* = E / (2 (1 - nu^2)), G = E / (2 (1 + nu)), nu unchanged; 1e-14 relative
  // (a handful of floating-point operations).
  EXPECT_LT(relative_error(p.effective_modulus_Pa,
                           kSteelYoung / (2.0 * (1.0 - kSteelPoisson * kSteelPoisson))),
            1e-14);
  EXPECT_LT(relative_error(p.shear_modulus_Pa, kSteelYoung / (2.0 * (1.0 + kSteelPoisson))),
            1e-14);
  EXPECT_LT(relative_error(p.poisson_ratio, kSteelPoisson), 1e-14);
}

TEST(CombineMaterials, DifferentMaterialsAreSymmetricAndBetween) {
  // Steel on aluminium: the combination must not depend on the order, G is the
  // harmonic mean of G1, G2 and nu lies between nu1 and nu2. Tolerance 1e-14.
  const ElasticPair p12 = combine_materials(2.1e11, 0.3, 7.0e10, 0.33);
  const ElasticPair p21 = combine_materials(7.0e10, 0.33, 2.1e11, 0.3);
  EXPECT_LT(relative_error(p12.effective_modulus_Pa, p21.effective_modulus_Pa), 1e-14);
  EXPECT_LT(relative_error(p12.shear_modulus_Pa, p21.shear_modulus_Pa), 1e-14);
  EXPECT_LT(relative_error(p12.poisson_ratio, p21.poisson_ratio), 1e-14);
  const double G1 = 2.1e11 / 2.6, G2 = 7.0e10 / 2.66;
  EXPECT_LT(relative_error(p12.shear_modulus_Pa, 2.0 * G1 * G2 / (G1 + G2)), 1e-14);
  EXPECT_GT(p12.poisson_ratio, 0.3);
  EXPECT_LT(p12.poisson_ratio, 0.33);
  const double Estar = 1.0 / ((1 - 0.09) / 2.1e11 + (1 - 0.33 * 0.33) / 7.0e10);
  EXPECT_LT(relative_error(p12.effective_modulus_Pa, Estar), 1e-14);
}

TEST(CombineMaterials, RejectsInvalidMaterials) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(combine_materials(0.0, 0.25, kSteelYoung, 0.25), std::invalid_argument);
  EXPECT_THROW(combine_materials(kSteelYoung, 0.25, -1.0, 0.25), std::invalid_argument);
  EXPECT_THROW(combine_materials(nan, 0.25, kSteelYoung, 0.25), std::invalid_argument);
  EXPECT_THROW(combine_materials(kSteelYoung, 0.5, kSteelYoung, 0.25), std::invalid_argument);
  EXPECT_THROW(combine_materials(kSteelYoung, 0.25, kSteelYoung, -0.01), std::invalid_argument);
  EXPECT_NO_THROW(combine_materials(kSteelYoung, 0.0, kSteelYoung, 0.49));
}

// ---------------------------------------------------------------------------
// Elliptic integrals

TEST(EllipticIntegrals, KnownValues) {
  // K(0) = E(0) = pi/2; at k = 1/sqrt(2): K = Gamma(1/4)^2 / (4 sqrt(pi)),
  // E = K/2 + pi/(4K) (Legendre's relation). Tolerance 1e-14 relative.
  EXPECT_LT(relative_error(elliptic_K(0.0), kPi / 2), 1e-14);
  EXPECT_LT(relative_error(elliptic_E(0.0), kPi / 2), 1e-14);
  const double k = 1.0 / std::sqrt(2.0);
  const double K = std::pow(std::tgamma(0.25), 2) / (4.0 * std::sqrt(kPi));
  EXPECT_LT(relative_error(elliptic_K(k), K), 1e-14);
  EXPECT_LT(relative_error(elliptic_E(k), K / 2 + kPi / (4 * K)), 1e-14);
  EXPECT_THROW(elliptic_K(1.0), std::domain_error);
}

TEST(EllipticIntegrals, AdDerivativesMatchCentralDifferences) {
  // Step h = cbrt(eps) * min(|k|, 1 - |k|): truncation O(h^2 K''') and rounding
  // O(eps K / h) are both ~1e-10 relative, far below the 1e-7 asserted.
  for (double k : {0.05, 0.1, 0.3, 0.5, -0.4, 0.7, 0.9, 0.99}) {
    const double h = kStepScale * std::min(std::abs(k), 1.0 - std::abs(k));
    const double dK_fd = (elliptic_K(k + h) - elliptic_K(k - h)) / (2 * h);
    const double dE_fd = (elliptic_E(k + h) - elliptic_E(k - h)) / (2 * h);
    const AdScalar K = elliptic_K(ad_variable(k, 0));
    const AdScalar E = elliptic_E(ad_variable(k, 0));
    EXPECT_LT(relative_error(K.derivatives()(0), dK_fd), 1e-7) << "k = " << k;
    EXPECT_LT(relative_error(E.derivatives()(0), dE_fd), 1e-7) << "k = " << k;
    // The header's formulas dK/dk = E/(k(1-k^2)) - K/k, dE/dk = (E-K)/k; at these
    // k their cancellation costs at most ~1e-13.
    const double Kv = K.value(), Ev = E.value();
    EXPECT_LT(relative_error(K.derivatives()(0), Ev / (k * (1 - k * k)) - Kv / k), 1e-12);
    EXPECT_LT(relative_error(E.derivatives()(0), (Ev - Kv) / k), 1e-12);
    // The other directions stay zero.
    EXPECT_EQ(K.derivatives().tail(kAdChunk - 1).norm(), 0.0);
  }
}

TEST(EllipticIntegrals, DerivativesApproachTheirSmallModulusLimits) {
  // dK/dk = pi k/4 + 9 pi k^3/32 + O(k^5), dE/dk = -pi k/4 - 3 pi k^3/32 + O(k^5):
  // for k <= 1e-4 the omitted terms are < 1e-15 relative; asserted to 1e-13.
  EXPECT_EQ(elliptic_K(ad_variable(0.0, 0)).derivatives()(0), 0.0);
  EXPECT_EQ(elliptic_E(ad_variable(0.0, 0)).derivatives()(0), 0.0);
  for (double k : {1e-12, 1e-8, 1e-6, 1e-4, -1e-5}) {
    const double dK = elliptic_K(ad_variable(k, 0)).derivatives()(0);
    const double dE = elliptic_E(ad_variable(k, 0)).derivatives()(0);
    EXPECT_LT(relative_error(dK, kPi * k / 4 + 9 * kPi * k * k * k / 32), 1e-13) << k;
    EXPECT_LT(relative_error(dE, -kPi * k / 4 - 3 * kPi * k * k * k / 32), 1e-13) << k;
  }
}

// ---------------------------------------------------------------------------
// Hertz shape

TEST(HertzContact, CircularContactMatchesClosedForm) {
  // Sphere of radius R on a plane (A = B = 1/(2R)):
  //   K_H = (4/3) E* sqrt(R),  a = b = sqrt(R delta) = (3 F R / (4 E*))^(1/3).
  // Tolerance 1e-12 relative.
  const double Estar = 1.12e11;
  for (double R : {0.05, 0.3, 0.45, 2.0}) {
    const double curvature = 1.0 / (2.0 * R);
    const HertzShape<double> s = hertz_shape(curvature, curvature, Estar);
    EXPECT_LT(relative_error(s.stiffness, 4.0 / 3.0 * Estar * std::sqrt(R)), 1e-12) << R;
    EXPECT_LT(relative_error(s.a_over_b, 1.0), 1e-15) << R;
    for (double F : {1e3, 6.8e4, 2e5}) {
      const double delta = s.approach_per_force_23 * std::pow(F, 2.0 / 3.0);
      const double a = s.semi_axis_a_per_force_13 * std::cbrt(F);
      const double b = s.semi_axis_b_per_force_13 * std::cbrt(F);
      EXPECT_LT(relative_error(a, std::sqrt(R * delta)), 1e-12) << R << " " << F;
      EXPECT_LT(relative_error(b, std::sqrt(R * delta)), 1e-12) << R << " " << F;
      EXPECT_LT(relative_error(a, std::cbrt(3 * F * R / (4 * Estar))), 1e-12) << R << " " << F;
    }
  }
}

TEST(HertzContact, SolvedShapeSatisfiesCurvatureRatioEquation) {
  // The k of the returned ellipse, put back into the equation, gives back
  // max(A,B)/min(A,B) to 1e-12 relative.
  for (const auto& [A, B] : curvature_pairs()) {
    const HertzShape<double> s = hertz_shape(A, B, 1.12e11);
    const double ratio = std::max(A, B) / std::min(A, B);
    EXPECT_LT(relative_error(curvature_ratio_equation(minor_over_major(s)), ratio), 1e-12)
        << "A = " << A << ", B = " << B;
  }
}

TEST(HertzContact, SemiAxesAndApproachSatisfyJohnsonEquations) {
  // Independent check of the absolute scale (Johnson eq. 4.39), with
  // p0 = 3F / (2 pi m n) (m major, n minor semi-axis, e^2 = 1 - n^2/m^2):
  //   A_small = p0 n (K - E) / (E* e^2 m^2),
  //   A_large = p0 n ((m/n)^2 E - K) / (E* e^2 m^2),
  //   delta = p0 n K / E*.
  // Tolerance 1e-11 (the K - E difference costs up to ~1e-14 at B/A = 1.2).
  const double Estar = 1.12e11, F = 5e4;
  for (const auto& [A, B] : curvature_pairs()) {
    const HertzShape<double> s = hertz_shape(A, B, Estar);
    const double a = s.semi_axis_a_per_force_13 * std::cbrt(F);
    const double b = s.semi_axis_b_per_force_13 * std::cbrt(F);
    const double m = std::max(a, b), n = std::min(a, b);
    const double e2 = 1.0 - (n * n) / (m * m);
    const double K = std::comp_ellint_1(std::sqrt(e2)), E = std::comp_ellint_2(std::sqrt(e2));
    const double p0 = 3.0 * F / (2.0 * kPi * m * n);
    const double scale = p0 * n / (Estar * e2 * m * m);
    EXPECT_LT(relative_error(scale * (K - E), std::min(A, B)), 1e-11) << A << " " << B;
    EXPECT_LT(relative_error(scale * ((m * m) / (n * n) * E - K), std::max(A, B)), 1e-11)
        << A << " " << B;
    const double delta = s.approach_per_force_23 * std::pow(F, 2.0 / 3.0);
    EXPECT_LT(relative_error(p0 * n * K / Estar, delta), 1e-11) << A << " " << B;
  }
}

TEST(HertzContact, ForceApproachRoundTrip) {
  // delta = approach_per_force_23 F^(2/3) must invert F = K_H delta^(3/2):
  // approach_per_force_23 = K_H^(-2/3). Tolerance 1e-12 relative.
  for (const auto& [A, B] : curvature_pairs()) {
    const HertzShape<double> s = hertz_shape(A, B, 1.12e11);
    EXPECT_LT(relative_error(s.approach_per_force_23, std::pow(s.stiffness, -2.0 / 3.0)), 1e-12);
    for (double F : {10.0, 6.8e4, 1e6}) {
      const double delta = s.approach_per_force_23 * std::pow(F, 2.0 / 3.0);
      EXPECT_LT(relative_error(s.stiffness * std::pow(delta, 1.5), F), 1e-12)
          << A << " " << B << " " << F;
    }
  }
}

TEST(HertzContact, MajorAxisLiesAlongTheSmallerCurvature) {
  // A < B: a (along x) is the major semi-axis; A > B: b is. Swapping A and B
  // swaps the semi-axes and keeps K_H (tolerance 1e-14 relative).
  for (double ratio : {1.2, 1.5, 3.0, 10.0}) {
    const HertzShape<double> x_major = hertz_shape(1.0, ratio, 1e11);
    const HertzShape<double> y_major = hertz_shape(ratio, 1.0, 1e11);
    EXPECT_GT(x_major.a_over_b, 1.0);
    EXPECT_GT(x_major.semi_axis_a_per_force_13, x_major.semi_axis_b_per_force_13);
    EXPECT_LT(y_major.a_over_b, 1.0);
    EXPECT_LT(y_major.semi_axis_a_per_force_13, y_major.semi_axis_b_per_force_13);
    EXPECT_LT(relative_error(x_major.a_over_b, x_major.semi_axis_a_per_force_13 /
                                                   x_major.semi_axis_b_per_force_13),
              1e-14);
    EXPECT_LT(relative_error(y_major.a_over_b, 1.0 / x_major.a_over_b), 1e-14);
    EXPECT_LT(relative_error(y_major.semi_axis_a_per_force_13, x_major.semi_axis_b_per_force_13),
              1e-14);
    EXPECT_LT(relative_error(y_major.stiffness, x_major.stiffness), 1e-14);
  }
}

TEST(HertzContact, ClassicTwoThirdsPowerApproximation) {
  // Sanity check only: n/m ~ (min/max curvature)^(2/3). The approximation is
  // within 0.4% up to a ratio of 3 and 3.2% at 10; asserted loosely at 10%.
  for (double ratio : {1.2, 1.5, 3.0, 10.0}) {
    const HertzShape<double> s = hertz_shape(1.0, ratio, 1e11);
    EXPECT_LT(relative_error(1.0 / s.a_over_b, std::pow(ratio, -2.0 / 3.0)), 0.10) << ratio;
  }
}

TEST(HertzContact, NearlyCircularContactIsAccurate) {
  // For rho = 1 + d: k = 1 - (2/3) d + O(d^2) (from rho = 1 + (3/4) e^2 + ...).
  // With d <= 1e-6 the O(d^2) term is < 1e-12; asserted to 1e-12 absolute,
  // which requires the cancellation-free evaluation of K - E near the circle.
  for (double d : {1e-15, 1e-12, 1e-9, 1e-6}) {
    const double ratio = 1.0 + d;
    const double d_exact = ratio - 1.0;  // d as represented
    const HertzShape<double> s = hertz_shape(1.0, ratio, 1e11);
    EXPECT_NEAR(1.0 / s.a_over_b, 1.0 - 2.0 / 3.0 * d_exact, 1e-12) << d;
  }
}

TEST(HertzContact, VerySlenderEllipsesConverge) {
  // Far outside the wheel/rail range the solver must still converge and k
  // must fall monotonically with the curvature ratio.
  double previous_k = 1.0;
  for (double ratio : {1e2, 1e3, 1e4, 1e6, 1e8}) {
    const HertzShape<double> s = hertz_shape(1.0, ratio, 1e11);
    const double k = 1.0 / s.a_over_b;
    EXPECT_GT(k, 0.0);
    EXPECT_LT(k, previous_k) << ratio;
    EXPECT_TRUE(std::isfinite(s.stiffness));
    EXPECT_LT(relative_error(s.approach_per_force_23, std::pow(s.stiffness, -2.0 / 3.0)), 1e-12);
    previous_k = k;
  }
}

TEST(HertzContact, SeedWheelOnRail) {
  // Seed (ERRATA 8): wheel rolling radius 0.45 m, rail head transverse radius
  // 0.30 m, steel E = 2.1e11 Pa, nu = 0.25, wheel load 68 kN.
  const ElasticPair steel =
      combine_materials(kSteelYoung, kSteelPoisson, kSteelYoung, kSteelPoisson);
  const double A = 1.0 / (2.0 * 0.45), B = 1.0 / (2.0 * 0.30), F = 68e3;
  const HertzShape<double> s = hertz_shape(A, B, steel.effective_modulus_Pa);
  const double a = s.semi_axis_a_per_force_13 * std::cbrt(F);
  const double b = s.semi_axis_b_per_force_13 * std::cbrt(F);
  const double delta = s.approach_per_force_23 * std::pow(F, 2.0 / 3.0);
  std::printf("seed Hertz: a = %.4f mm, b = %.4f mm, a/b = %.5f, delta = %.3f um, "
              "K_H = %.5e N/m^1.5\n",
              a * 1e3, b * 1e3, s.a_over_b, delta * 1e6, s.stiffness);
  EXPECT_GT(a, 3e-3);
  EXPECT_LT(a, 10e-3);
  EXPECT_GT(b, 3e-3);
  EXPECT_LT(b, 10e-3);
  EXPECT_GT(a, b);  // A < B: the longer axis runs along the rail
  EXPECT_GT(delta, 30e-6);
  EXPECT_LT(delta, 300e-6);
  EXPECT_LT(relative_error(s.a_over_b, a / b), 1e-14);
}

TEST(HertzContact, AdDerivativesMatchCentralDifferences) {
  // d(field)/dA and d(field)/dB by AD (implicit function theorem through the
  // curvature-ratio root) against central differences with step
  // h = cbrt(eps) * A (resp. B): truncation and rounding both ~1e-10 relative;
  // asserted to 1e-7 relative.
  const double Estar = 1.12e11;
  const std::vector<std::pair<double, double>> points = {
      {1.0 / 0.9, 1.0 / 0.6}, {1.0, 1.2}, {1.0, 10.0}, {3.0, 1.0}, {40.0, 1.0}};
  for (const auto& [A, B] : points) {
    const auto ad = field_values(hertz_shape(ad_variable(A, 0), ad_variable(B, 1), Estar));
    const double hA = kStepScale * A, hB = kStepScale * B;
    const auto plus_A = field_values(hertz_shape(A + hA, B, Estar));
    const auto minus_A = field_values(hertz_shape(A - hA, B, Estar));
    const auto plus_B = field_values(hertz_shape(A, B + hB, Estar));
    const auto minus_B = field_values(hertz_shape(A, B - hB, Estar));
    for (std::size_t f = 0; f < ad.size(); ++f) {
      const double dA_fd = (plus_A[f] - minus_A[f]) / (2 * hA);
      const double dB_fd = (plus_B[f] - minus_B[f]) / (2 * hB);
      EXPECT_LT(relative_error(ad[f].derivatives()(0), dA_fd), 1e-7)
          << kFieldNames[f] << " A = " << A << " B = " << B;
      EXPECT_LT(relative_error(ad[f].derivatives()(1), dB_fd), 1e-7)
          << kFieldNames[f] << " A = " << A << " B = " << B;
    }
  }
}

TEST(HertzContact, AdDerivativesAtTheCircle) {
  // At A = B the solver switches which axis is the major one (rho = B/A or
  // A/B), yet the shape is smooth there: a/b passes through 1 with slope
  // -2/(3B) in A, from k = 1 - (2/3)(rho - 1) + ..., and K_H depends on A + B
  // only, to first order in rho - 1. Closed-form slopes to 1e-12:
  //   d(a/b)/dA = -2/(3B), d(a/b)/dB = 2/(3B), dK_H/dA = dK_H/dB = -(1/2) K_H/(A+B);
  // all fields against central differences straddling A = B to 1e-7, as above.
  const double Estar = 1.12e11, A = 1.25, B = 1.25;
  const auto ad = field_values(hertz_shape(ad_variable(A, 0), ad_variable(B, 1), Estar));
  const HertzShape<double> s = hertz_shape(A, B, Estar);
  EXPECT_LT(relative_error(ad[0].derivatives()(0), -2.0 / (3.0 * B)), 1e-12);
  EXPECT_LT(relative_error(ad[0].derivatives()(1), 2.0 / (3.0 * B)), 1e-12);
  EXPECT_LT(relative_error(ad[1].derivatives()(0), -0.5 * s.stiffness / (A + B)), 1e-12);
  EXPECT_LT(relative_error(ad[1].derivatives()(1), -0.5 * s.stiffness / (A + B)), 1e-12);
  const double h = kStepScale * A;
  const auto plus_A = field_values(hertz_shape(A + h, B, Estar));
  const auto minus_A = field_values(hertz_shape(A - h, B, Estar));
  for (std::size_t f = 0; f < ad.size(); ++f) {
    const double dA_fd = (plus_A[f] - minus_A[f]) / (2 * h);
    EXPECT_LT(relative_error(ad[f].derivatives()(0), dA_fd), 1e-7) << kFieldNames[f];
  }
}

TEST(HertzContact, RejectsInvalidCurvatures) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_THROW(hertz_shape(0.0, 1.0, 1e11), std::domain_error);
  EXPECT_THROW(hertz_shape(1.0, 0.0, 1e11), std::domain_error);
  EXPECT_THROW(hertz_shape(-1.0, 1.0, 1e11), std::domain_error);
  EXPECT_THROW(hertz_shape(nan, 1.0, 1e11), std::domain_error);
  EXPECT_THROW(hertz_shape(1.0, inf, 1e11), std::domain_error);
  EXPECT_THROW(hertz_shape(AdScalar(0.0), AdScalar(1.0), 1e11), std::domain_error);
  EXPECT_THROW(hertz_shape(1.0, 1.0, 0.0), std::invalid_argument);
}
