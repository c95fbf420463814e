// Kalker creep coefficients: table B.1 reproduced at its nodes, smoothness of
// the interpolation (value and slope) across every node and across a/b = 1,
// AD derivatives, range checks, and the f_ij scaling.
#include <railstab/contact/hertz.hpp>
#include <railstab/contact/kalker.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>

using namespace railstab;

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr int kRows = 19;
constexpr std::array<double, 3> kPoissonNodes = {0.0, 0.25, 0.5};

// Table B.1 of the thesis, typed in independently of src/railstab/contact/kalker.cpp.
// Columns: c11, c22, c23, c33, each for nu = 0, 0.25, 0.5.
// Rows: a/b = 0.1..0.9, 1.0, then b/a = 0.9..0.1.
constexpr double kTable[kRows][12] = {
    {2.51, 3.31, 4.85, 2.51, 2.52, 2.53, 0.334, 0.473, 0.731, 6.42, 8.28, 11.7},
    {2.59, 3.37, 4.81, 2.59, 2.63, 2.66, 0.483, 0.603, 0.809, 3.46, 4.27, 5.66},
    {2.68, 3.44, 4.80, 2.68, 2.75, 2.81, 0.607, 0.715, 0.889, 2.49, 2.96, 3.72},
    {2.78, 3.53, 4.82, 2.78, 2.88, 2.98, 0.720, 0.823, 0.977, 2.02, 2.32, 2.77},
    {2.88, 3.62, 4.83, 2.88, 3.01, 3.14, 0.827, 0.929, 1.07, 1.74, 1.93, 2.22},
    {2.98, 3.72, 4.91, 2.98, 3.14, 3.31, 0.930, 1.03, 1.18, 1.56, 1.68, 1.86},
    {3.09, 3.81, 4.97, 3.09, 3.28, 3.48, 1.03, 1.14, 1.29, 1.43, 1.50, 1.60},
    {3.19, 3.91, 5.05, 3.19, 3.41, 3.65, 1.13, 1.25, 1.40, 1.34, 1.37, 1.42},
    {3.29, 4.01, 5.12, 3.29, 3.54, 3.82, 1.23, 1.36, 1.51, 1.27, 1.27, 1.27},
    {3.40, 4.12, 5.20, 3.40, 3.67, 3.98, 1.33, 1.47, 1.63, 1.21, 1.19, 1.16},
    {3.51, 4.22, 5.30, 3.51, 3.81, 4.16, 1.44, 1.59, 1.77, 1.16, 1.11, 1.06},
    {3.65, 4.36, 5.42, 3.65, 3.99, 4.39, 1.58, 1.75, 1.94, 1.10, 1.04, 0.954},
    {3.82, 4.54, 5.58, 3.82, 4.21, 4.67, 1.76, 1.95, 2.18, 1.05, 0.965, 0.852},
    {4.06, 4.78, 5.80, 4.06, 4.50, 5.04, 2.01, 2.23, 2.50, 1.01, 0.892, 0.751},
    {4.37, 5.10, 6.11, 4.37, 4.90, 5.56, 2.35, 2.62, 2.96, 0.958, 0.819, 0.650},
    {4.84, 5.57, 6.57, 4.84, 5.48, 6.31, 2.88, 3.24, 3.70, 0.912, 0.747, 0.549},
    {5.57, 6.34, 7.34, 5.57, 6.40, 7.51, 3.79, 4.32, 5.01, 0.868, 0.674, 0.446},
    {6.96, 7.78, 8.82, 6.96, 8.14, 9.79, 5.72, 6.63, 7.89, 0.828, 0.601, 0.341},
    {10.7, 11.7, 12.9, 10.7, 12.8, 16.0, 12.2, 14.6, 18.0, 0.795, 0.526, 0.228},
};

// a/b of table row i: a/b = 0.1 (i+1) for i <= 9, then b/a = 0.1 (19 - i).
double row_ratio(int row) {
  return row <= 9 ? 0.1 * (row + 1) : 1.0 / (0.1 * (kRows - row));
}

std::array<double, 4> as_array(const KalkerTableValues<double>& c) {
  return {c.c11, c.c22, c.c23, c.c33};
}

std::array<AdScalar, 4> as_array(const KalkerTableValues<AdScalar>& c) {
  return {c.c11, c.c22, c.c23, c.c33};
}

std::array<double, 4> table_at(double a_over_b, double nu) {
  return as_array(kalker_table(a_over_b, nu));
}

// Derivatives d c_ij / d(a/b) by AD.
std::array<double, 4> slopes_at(double a_over_b, double nu) {
  const auto c = as_array(kalker_table(AdScalar(a_over_b, AdDerivatives::Unit(0)), nu));
  return {c[0].derivatives()(0), c[1].derivatives()(0), c[2].derivatives()(0),
          c[3].derivatives()(0)};
}

const char* const kNames[] = {"c11", "c22", "c23", "c33"};

// Bounds for the smoothness tolerances, derived from the table itself.
// In u the spline's slope stays within twice the largest secant slope and
// its curvature within three times the largest second difference / h^2 (the
// not-a-knot end curvature is extrapolated linearly from the first two
// interior ones). In a/b = r: dc/dr = c'(u) u'(r), d2c/dr2 = c'' u'^2 + c' u'',
// with |u'| <= 1 and |u''| <= 2 on [0.1, 10]. The quadratic in nu has Lagrange
// weights with sum of moduli <= 1.25 on [0, 0.5].
struct SmoothnessBounds {
  double value, slope, curvature;
};

SmoothnessBounds smoothness_bounds() {
  double max_value = 0, max_secant = 0, max_second_difference = 0;
  for (int i = 0; i < kRows; ++i)
    for (int j = 0; j < 12; ++j) {
      max_value = std::max(max_value, kTable[i][j]);
      if (i + 1 < kRows)
        max_secant = std::max(max_secant, std::abs(kTable[i + 1][j] - kTable[i][j]) / 0.1);
      if (i > 0 && i + 1 < kRows)
        max_second_difference = std::max(
            max_second_difference,
            std::abs(kTable[i - 1][j] - 2 * kTable[i][j] + kTable[i + 1][j]) / 0.01);
    }
  const double slope = 1.25 * 2.0 * max_secant;
  const double curvature = 1.25 * 3.0 * max_second_difference + 2.0 * slope;
  return {1.25 * max_value, slope, curvature};
}

}  // namespace

TEST(KalkerTable, ReproducesEveryTableEntry) {
  // All 19 rows x 3 Poisson ratios x 4 coefficients, 1e-12 relative.
  for (int row = 0; row < kRows; ++row)
    for (int p = 0; p < 3; ++p) {
      const auto c = table_at(row_ratio(row), kPoissonNodes[p]);
      for (int coefficient = 0; coefficient < 4; ++coefficient) {
        const double expected = kTable[row][3 * coefficient + p];
        EXPECT_NEAR(c[coefficient], expected, 1e-12 * expected)
            << kNames[coefficient] << " row " << row << " nu " << kPoissonNodes[p];
      }
    }
}

TEST(KalkerTable, LongitudinalEqualsLateralForZeroPoisson) {
  // Table B.1 has c11 = c22 at nu = 0 in every row; the interpolation keeps
  // it between the rows (same data, same spline): exact equality.
  for (double r : {0.1, 0.137, 0.5, 0.93, 1.0, 1.07, 3.3, 10.0})
    EXPECT_EQ(table_at(r, 0.0)[0], table_at(r, 0.0)[1]) << r;
}

TEST(KalkerTable, ValueAndSlopeAreContinuousAcrossNodes) {
  // At every interior node (a/b = 1 included) with one-sided differences of
  // step d = 1e-6 in a/b:
  //   |c(r+d) - c(r-d)| <= 2 d max|c'| + 4 eps max|c|,
  //   |right slope - left slope| <= d max|c''| + 4 eps max|c| / d,
  // since each one-sided difference differs from c'(r) by at most
  // d max|c''|/2 + 2 eps max|c|/d. A jump of the slope (a C0 interpolant)
  // would be O(1), about three orders of magnitude above these tolerances.
  const SmoothnessBounds bound = smoothness_bounds();
  const double d = 1e-6;
  const double value_tol = 2 * d * bound.slope + 4 * kEps * bound.value;
  const double slope_tol = d * bound.curvature + 4 * kEps * bound.value / d;
  for (int row = 1; row + 1 < kRows; ++row)
    for (double nu : {0.0, 0.1, 0.25, 0.4, 0.5}) {
      const double r = row_ratio(row);
      const auto left = table_at(r - d, nu), centre = table_at(r, nu), right = table_at(r + d, nu);
      for (int c = 0; c < 4; ++c) {
        EXPECT_LT(std::abs(right[c] - left[c]), value_tol) << kNames[c] << " a/b = " << r;
        const double left_slope = (centre[c] - left[c]) / d;
        const double right_slope = (right[c] - centre[c]) / d;
        EXPECT_LT(std::abs(right_slope - left_slope), slope_tol)
            << kNames[c] << " a/b = " << r << " nu = " << nu;
      }
    }
}

TEST(KalkerTable, AdSlopeIsContinuousAcrossNodes) {
  // Sharper: the AD slope of the two cubic pieces just left and right of each
  // node (d = 1e-9) differs by at most 2 d max|c''| (~3e-6 with the bound above).
  const SmoothnessBounds bound = smoothness_bounds();
  const double d = 1e-9;
  for (int row = 1; row + 1 < kRows; ++row)
    for (double nu : {0.0, 0.25, 0.5}) {
      const double r = row_ratio(row);
      const auto left = slopes_at(r - d, nu), right = slopes_at(r + d, nu);
      for (int c = 0; c < 4; ++c)
        EXPECT_LT(std::abs(right[c] - left[c]), 2 * d * bound.curvature)
            << kNames[c] << " a/b = " << r << " nu = " << nu;
    }
}

TEST(KalkerTable, RatioCoordinateIsC1AtUnity) {
  // u = a/b (a/b <= 1), u = 2 - b/a (a/b > 1): du/d(a/b) = 1 on both sides,
  // so the AD slopes in a/b at 1 -+ d (d = 1e-9) differ by at most
  // 2 d max|c''| (bound as in ValueAndSlopeAreContinuousAcrossNodes, ~5e-6).
  // A mapping with a slope factor other than 1 on one side would make them
  // differ by O(|slope|): c23 has a slope well away from zero there (> 0.5).
  const SmoothnessBounds bound = smoothness_bounds();
  const double d = 1e-9;
  for (double nu : {0.0, 0.25, 0.5}) {
    const auto below = slopes_at(1.0 - d, nu), above = slopes_at(1.0 + d, nu);
    for (int c = 0; c < 4; ++c)
      EXPECT_NEAR(above[c], below[c], 2 * d * bound.curvature) << kNames[c] << " nu " << nu;
    EXPECT_GT(std::abs(below[2]), 0.5);
  }
}

TEST(KalkerTable, AdDerivativeMatchesCentralDifferences) {
  // Points away from the nodes (the mapping u(a/b) is only C1 at a/b = 1);
  // step h = cbrt(eps) a/b: truncation O(h^2 c''') and rounding O(eps c / h)
  // stay below ~1e-9 of the coefficient's scale. Asserted to 1e-6 relative to
  // max(|dc/d(a/b)|, |c|) (a few slopes are near zero, e.g. c33 for nu = 0.25
  // around a/b = 0.9, where a purely relative error is meaningless).
  for (double r : {0.137, 0.55, 0.93, 1.07, 2.3, 7.7})
    for (double nu : {0.0, 0.13, 0.25, 0.37, 0.5}) {
      const double h = std::cbrt(kEps) * r;
      const auto plus = table_at(r + h, nu), minus = table_at(r - h, nu);
      const auto value = table_at(r, nu);
      const auto ad = slopes_at(r, nu);
      for (int c = 0; c < 4; ++c) {
        const double fd = (plus[c] - minus[c]) / (2 * h);
        EXPECT_NEAR(ad[c], fd, 1e-6 * std::max(std::abs(fd), std::abs(value[c])))
            << kNames[c] << " a/b = " << r << " nu = " << nu;
      }
    }
}

TEST(KalkerTable, RejectsOutOfRangeArguments) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (double r : {0.0999, 10.001, 0.0, -1.0, nan})
    EXPECT_THROW(kalker_table(r, 0.25), std::domain_error) << r;
  try {
    kalker_table(12.5, 0.25);
    ADD_FAILURE() << "no exception for a/b = 12.5";
  } catch (const std::domain_error& e) {
    EXPECT_NE(std::string(e.what()).find("12.5"), std::string::npos) << e.what();
  }
  EXPECT_THROW(kalker_table(AdScalar(0.05), 0.25), std::domain_error);
  EXPECT_THROW(kalker_table(1.0, -0.01), std::domain_error);
  EXPECT_THROW(kalker_table(1.0, 0.51), std::domain_error);
  EXPECT_NO_THROW(kalker_table(0.1, 0.0));
  EXPECT_NO_THROW(kalker_table(10.0, 0.5));
}

TEST(KalkerCreep, CoefficientsScaleWithContactSize) {
  // f11/(G a b) = c11, f22/(G a b) = c22, f23/(G (ab)^1.5) = c23,
  // f33/(G (ab)^2) = c33; 1e-14 relative.
  const double G = 8.4e10, nu = 0.25;
  for (const auto& [a, b] : {std::pair{6e-3, 4e-3}, std::pair{3e-3, 9e-3}, std::pair{5e-3, 5e-3}}) {
    const CreepCoefficients<double> f = kalker_coefficients(a, b, G, nu);
    const auto c = table_at(a / b, nu);
    const double ab = a * b;
    EXPECT_LT(std::abs(f.f11_N / (G * ab) / c[0] - 1), 1e-14);
    EXPECT_LT(std::abs(f.f22_N / (G * ab) / c[1] - 1), 1e-14);
    EXPECT_LT(std::abs(f.f23_N_m / (G * std::pow(ab, 1.5)) / c[2] - 1), 1e-14);
    EXPECT_LT(std::abs(f.f33_N_m2 / (G * ab * ab) / c[3] - 1), 1e-14);
  }
}

TEST(KalkerCreep, AdDerivativesMatchCentralDifferences) {
  // d f_ij / da and d f_ij / db, step cbrt(eps) times the semi-axis: 1e-6 relative.
  const double G = 8.4e10, nu = 0.25, a = 6.3e-3, b = 4.8e-3;
  const CreepCoefficients<AdScalar> ad = kalker_coefficients(
      AdScalar(a, AdDerivatives::Unit(0)), AdScalar(b, AdDerivatives::Unit(1)), G, nu);
  auto values = [&](double aa, double bb) {
    const CreepCoefficients<double> f = kalker_coefficients(aa, bb, G, nu);
    return std::array<double, 4>{f.f11_N, f.f22_N, f.f23_N_m, f.f33_N_m2};
  };
  const std::array<AdScalar, 4> f = {ad.f11_N, ad.f22_N, ad.f23_N_m, ad.f33_N_m2};
  const double ha = std::cbrt(kEps) * a, hb = std::cbrt(kEps) * b;
  const auto pa = values(a + ha, b), ma = values(a - ha, b);
  const auto pb = values(a, b + hb), mb = values(a, b - hb);
  for (int c = 0; c < 4; ++c) {
    const double dfa = (pa[c] - ma[c]) / (2 * ha), dfb = (pb[c] - mb[c]) / (2 * hb);
    EXPECT_NEAR(f[c].derivatives()(0), dfa, 1e-6 * std::abs(dfa)) << c;
    EXPECT_NEAR(f[c].derivatives()(1), dfb, 1e-6 * std::abs(dfb)) << c;
  }
}

TEST(KalkerCreep, RejectsInvalidInputs) {
  EXPECT_THROW(kalker_coefficients(0.0, 5e-3, 8e10, 0.25), std::domain_error);
  EXPECT_THROW(kalker_coefficients(5e-3, -1e-3, 8e10, 0.25), std::domain_error);
  EXPECT_THROW(kalker_coefficients(5e-3, 5e-3, 0.0, 0.25), std::invalid_argument);
  EXPECT_THROW(kalker_coefficients(1e-3, 20e-3, 8e10, 0.25), std::domain_error);  // a/b = 0.05
}

TEST(KalkerCreep, SeedContactEllipse) {
  // Seed wheel/rail ellipse (see HertzContact.SeedWheelOnRail) at 68 kN with
  // G, nu combined for steel on steel. Printed for the record; the c_ij must
  // lie between the neighbouring table rows (a/b = 1.31: b/a = 0.763, rows
  // b/a = 0.8 and 0.7 at nu = 0.25).
  const ElasticPair steel = combine_materials(2.1e11, 0.25, 2.1e11, 0.25);
  const HertzShape<double> s =
      hertz_shape(1.0 / (2 * 0.45), 1.0 / (2 * 0.30), steel.effective_modulus_Pa);
  const double a = s.semi_axis_a_per_force_13 * std::cbrt(68e3);
  const double b = s.semi_axis_b_per_force_13 * std::cbrt(68e3);
  const CreepCoefficients<double> f =
      kalker_coefficients(a, b, steel.shear_modulus_Pa, steel.poisson_ratio);
  const auto c = table_at(a / b, steel.poisson_ratio);
  std::printf("seed Kalker: G = %.4e Pa, c11 = %.4f, c22 = %.4f, c23 = %.4f, c33 = %.4f\n"
              "             f11 = %.5e N, f22 = %.5e N, f23 = %.5e N m, f33 = %.5e N m^2\n",
              steel.shear_modulus_Pa, c[0], c[1], c[2], c[3], f.f11_N, f.f22_N, f.f23_N_m,
              f.f33_N_m2);
  for (int k = 0; k < 4; ++k) {
    const double row_08 = kTable[11][3 * k + 1], row_07 = kTable[12][3 * k + 1];
    EXPECT_GE(c[k], std::min(row_08, row_07)) << kNames[k];
    EXPECT_LE(c[k], std::max(row_08, row_07)) << kNames[k];
  }
}
