// Kalker's linear creep coefficients: thesis table B.1 (ERRATA 9), smoothly
// interpolated so that AD differentiates through it.
//
// Ratio coordinate: u = a/b for a/b <= 1 and u = 2 - b/a for a/b > 1, so the
// 19 table rows (a/b = 0.1..0.9, 1, b/a = 0.9..0.1) sit at u = 0.1, 0.2, ..., 1.9.
// du/d(a/b) = 1 on the left of a/b = 1 and (b/a)^2 = 1 on the right: the
// mapping is C1 there (its second derivative jumps from 0 to -2).
// In u each table column is a not-a-knot cubic spline (C2, exact at the nodes);
// in the Poisson ratio the three columns nu = 0, 0.25, 0.5 are joined by the
// quadratic through them (exact at the nodes).
#include <railstab/contact/kalker.hpp>

#include <railstab/core/nested_dual.hpp>

#include <Eigen/LU>

#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace railstab {
namespace {

constexpr int kRows = 19;
constexpr int kPoissonNodes = 3;      // nu = 0, 0.25, 0.5
constexpr int kCoefficients = 4;      // c11, c22, c23, c33
constexpr int kColumns = kPoissonNodes * kCoefficients;
constexpr double kFirstNode = 0.1;    // u of row 0
constexpr double kNodeSpacing = 0.1;  // uniform spacing in u

// Table B.1 (Kalker). Columns: c11 (nu = 0, 0.25, 0.5), c22 (...), c23 (...), c33 (...).
// Rows: a/b = 0.1..0.9, a/b = b/a = 1.0, then b/a = 0.9..0.1.
constexpr double kTableB1[kRows][kColumns] = {
    // a/b = 0.1 .. 0.9
    {2.51, 3.31, 4.85, 2.51, 2.52, 2.53, 0.334, 0.473, 0.731, 6.42, 8.28, 11.7},
    {2.59, 3.37, 4.81, 2.59, 2.63, 2.66, 0.483, 0.603, 0.809, 3.46, 4.27, 5.66},
    {2.68, 3.44, 4.80, 2.68, 2.75, 2.81, 0.607, 0.715, 0.889, 2.49, 2.96, 3.72},
    {2.78, 3.53, 4.82, 2.78, 2.88, 2.98, 0.720, 0.823, 0.977, 2.02, 2.32, 2.77},
    {2.88, 3.62, 4.83, 2.88, 3.01, 3.14, 0.827, 0.929, 1.07, 1.74, 1.93, 2.22},
    {2.98, 3.72, 4.91, 2.98, 3.14, 3.31, 0.930, 1.03, 1.18, 1.56, 1.68, 1.86},
    {3.09, 3.81, 4.97, 3.09, 3.28, 3.48, 1.03, 1.14, 1.29, 1.43, 1.50, 1.60},
    {3.19, 3.91, 5.05, 3.19, 3.41, 3.65, 1.13, 1.25, 1.40, 1.34, 1.37, 1.42},
    {3.29, 4.01, 5.12, 3.29, 3.54, 3.82, 1.23, 1.36, 1.51, 1.27, 1.27, 1.27},
    // a/b = 1
    {3.40, 4.12, 5.20, 3.40, 3.67, 3.98, 1.33, 1.47, 1.63, 1.21, 1.19, 1.16},
    // b/a = 0.9 .. 0.1
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

using TableMatrix = Eigen::Matrix<double, kRows, kColumns>;

// Node values y_i and spline second derivatives M_i (per column).
struct SplineTable {
  TableMatrix values;
  TableMatrix second_derivatives;
};

// Not-a-knot cubic spline on the uniform grid, spacing h:
//   interior:  M_{i-1} + 4 M_i + M_{i+1} = 6 (y_{i-1} - 2 y_i + y_{i+1}) / h^2
//   ends:      M_0 - 2 M_1 + M_2 = 0,  M_{n-3} - 2 M_{n-2} + M_{n-1} = 0
//              (third derivative continuous across the second and the
//              second-to-last node)
SplineTable build_spline_table() {
  SplineTable table;
  for (int i = 0; i < kRows; ++i)
    for (int j = 0; j < kColumns; ++j) table.values(i, j) = kTableB1[i][j];

  Eigen::Matrix<double, kRows, kRows> system = Eigen::Matrix<double, kRows, kRows>::Zero();
  TableMatrix rhs = TableMatrix::Zero();
  system(0, 0) = 1.0, system(0, 1) = -2.0, system(0, 2) = 1.0;
  for (int i = 1; i < kRows - 1; ++i) {
    system(i, i - 1) = 1.0, system(i, i) = 4.0, system(i, i + 1) = 1.0;
    rhs.row(i) = 6.0 / (kNodeSpacing * kNodeSpacing) *
                 (table.values.row(i - 1) - 2.0 * table.values.row(i) + table.values.row(i + 1));
  }
  system(kRows - 1, kRows - 3) = 1.0, system(kRows - 1, kRows - 2) = -2.0,
                          system(kRows - 1, kRows - 1) = 1.0;
  table.second_derivatives = system.fullPivLu().solve(rhs);
  return table;
}

const SplineTable& spline_table() {
  static const SplineTable table = build_spline_table();
  return table;
}

// u(a/b): u = a/b if a/b <= 1, else 2 - b/a.
template <class T> T ratio_coordinate(const T& a_over_b) {
  if (value_of(a_over_b) <= 1.0) return a_over_b;
  return T(2.0 - 1.0 / a_over_b);
}

// Position of u on the grid: interval i (between nodes i and i+1) and the
// local coordinate t = (u - u_i)/h in [0, 1].
template <class T> struct GridPosition {
  int interval;
  T t;
};

template <class T> GridPosition<T> locate(const T& u) {
  const double s = (value_of(u) - kFirstNode) / kNodeSpacing;  // node index units
  int i = static_cast<int>(std::floor(s));
  if (i < 0) i = 0;
  if (i > kRows - 2) i = kRows - 2;
  const double u_i = kFirstNode + kNodeSpacing * i;
  return GridPosition<T>{i, T((u - u_i) / kNodeSpacing)};
}

// Cubic spline of one column on interval i:
//   S = (1-t) y_i + t y_{i+1} + h^2/6 [((1-t)^3 - (1-t)) M_i + (t^3 - t) M_{i+1}]
template <class T> T spline_value(int column, const GridPosition<T>& at) {
  const SplineTable& table = spline_table();
  const int i = at.interval;
  const T& t = at.t;
  const T s = 1.0 - t;
  const double h2_6 = kNodeSpacing * kNodeSpacing / 6.0;
  return s * table.values(i, column) + t * table.values(i + 1, column) +
         h2_6 * ((s * s * s - s) * table.second_derivatives(i, column) +
                 (t * t * t - t) * table.second_derivatives(i + 1, column));
}

// Lagrange weights of the quadratic through nu = 0, 0.25, 0.5.
std::array<double, kPoissonNodes> poisson_weights(double nu) {
  return {(nu - 0.25) * (nu - 0.5) / ((0.0 - 0.25) * (0.0 - 0.5)),
          (nu - 0.0) * (nu - 0.5) / ((0.25 - 0.0) * (0.25 - 0.5)),
          (nu - 0.0) * (nu - 0.25) / ((0.5 - 0.0) * (0.5 - 0.25))};
}

// Coefficient c (0: c11, 1: c22, 2: c23, 3: c33) at the grid position and nu.
template <class T> T interpolate_coefficient(int coefficient, const GridPosition<T>& at,
                                             const std::array<double, kPoissonNodes>& w) {
  T sum = T(0.0);
  for (int j = 0; j < kPoissonNodes; ++j)
    sum += w[j] * spline_value(kPoissonNodes * coefficient + j, at);
  return sum;
}

void require_ratio_in_table(double a_over_b) {
  if (!(a_over_b >= 0.1 && a_over_b <= 10.0)) {
    std::ostringstream msg;
    msg << "kalker_table: semi-axis ratio a/b = " << a_over_b
        << " lies outside table B.1, which covers [0.1, 10]";
    throw std::domain_error(msg.str());
  }
}

void require_poisson_in_table(double nu) {
  if (!(nu >= 0.0 && nu <= 0.5)) {
    std::ostringstream msg;
    msg << "kalker_table: Poisson ratio " << nu << " lies outside [0, 0.5]";
    throw std::domain_error(msg.str());
  }
}

void require_positive_semi_axes(double a, double b) {
  if (!(a > 0.0) || !(b > 0.0) || !std::isfinite(a) || !std::isfinite(b)) {
    std::ostringstream msg;
    msg << "kalker_coefficients: semi-axes must be positive and finite, got a = " << a
        << " m, b = " << b << " m";
    throw std::domain_error(msg.str());
  }
}

void require_positive_shear_modulus(double G) {
  if (!(G > 0.0) || !std::isfinite(G)) {
    std::ostringstream msg;
    msg << "kalker_coefficients: shear modulus must be positive and finite, got " << G
        << " Pa";
    throw std::invalid_argument(msg.str());
  }
}

}  // namespace

template <class T> KalkerTableValues<T> kalker_table(const T& a_over_b, double poisson_ratio) {
  require_ratio_in_table(value_of(a_over_b));
  require_poisson_in_table(poisson_ratio);
  const GridPosition<T> at = locate(ratio_coordinate(a_over_b));
  const std::array<double, kPoissonNodes> w = poisson_weights(poisson_ratio);
  return KalkerTableValues<T>{interpolate_coefficient(0, at, w), interpolate_coefficient(1, at, w),
                              interpolate_coefficient(2, at, w), interpolate_coefficient(3, at, w)};
}

template <class T> CreepCoefficients<T> kalker_coefficients(const T& a_m, const T& b_m,
                                                           double shear_modulus_Pa,
                                                           double poisson_ratio) {
  using std::sqrt;
  require_positive_semi_axes(value_of(a_m), value_of(b_m));
  require_positive_shear_modulus(shear_modulus_Pa);
  const KalkerTableValues<T> c = kalker_table(T(a_m / b_m), poisson_ratio);
  const double G = shear_modulus_Pa;
  const T ab = a_m * b_m;
  // f11 = G ab c11, f22 = G ab c22, f23 = G (ab)^(3/2) c23, f33 = G (ab)^2 c33
  return CreepCoefficients<T>{G * ab * c.c11, G * ab * c.c22, G * ab * sqrt(ab) * c.c23,
                              G * ab * ab * c.c33};
}

template KalkerTableValues<double> kalker_table(const double&, double);
template KalkerTableValues<AdScalar> kalker_table(const AdScalar&, double);
template KalkerTableValues<ParamDual> kalker_table(const ParamDual&, double);
template KalkerTableValues<ParamAdScalar> kalker_table(const ParamAdScalar&, double);
template KalkerTableValues<Dual3> kalker_table(const Dual3&, double);
template CreepCoefficients<Dual3> kalker_coefficients(const Dual3&, const Dual3&, double, double);
template CreepCoefficients<ParamDual> kalker_coefficients(const ParamDual&, const ParamDual&,
                                                          double, double);
template CreepCoefficients<ParamAdScalar> kalker_coefficients(const ParamAdScalar&,
                                                              const ParamAdScalar&, double,
                                                              double);
template CreepCoefficients<double> kalker_coefficients(const double&, const double&, double,
                                                       double);
template CreepCoefficients<AdScalar> kalker_coefficients(const AdScalar&, const AdScalar&,
                                                         double, double);

}  // namespace railstab
