#pragma once
// A force characteristic F(x): force against deflection (a spring) or
// against velocity (a damper), linear or from a table.
//
//   linear: F = c x                        (c: stiffness or damping)
//   table:  F = a P(x), P through the points (x_i, F_i), x strictly
//           increasing, at least 2 points; a the table's scale factor (the
//           scene's `spring_force_scale` / `damper_force_scale`, default 1),
//           the parameter that varies a table characteristic (sensitivity,
//           study, --set) as c varies a linear one.
//           Between the points a monotone C1 cubic (Fritsch-Carlson "PCHIP":
//           Hermite cubics whose node slopes are the harmonic mean of the
//           neighbouring secants, zero where they change sign), so the curve
//           passes through every point, is C1 (Newton and AD see continuous
//           derivatives) and stays monotone where the table is. Beyond the
//           ends it continues linearly with the end segment's secant slope
//           (the end node slopes are those secants, so the join is C1).
//           A piecewise-linear table is thus followed exactly at its points;
//           between them the cubic departs from the straight segment by at
//           most |s_left - s_right| h / 8 per segment of width h (s: the
//           secant slopes around it).
//
// The slope at x = 0 is what the linearisation sees: for a table whose
// segments on both sides of 0 have the same slope it is that slope.
// Potential (springs): the integral from 0 to x, exact per cubic.
#include <railstab/core/scalar.hpp>

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace railstab {

template <class S> struct ForceCharacteristic {
  bool is_table = false;
  S coefficient = S(0);      // linear: F = coefficient x
  S scale = S(1);            // table: F = scale P(x)
  std::vector<double> x, f;  // table points
  std::vector<double> slope; // PCHIP node slopes (computed by set_table)

  static ForceCharacteristic linear(const S& c) {
    ForceCharacteristic k;
    k.coefficient = c;
    return k;
  }
  // Throws std::invalid_argument (the caller adds file and key) unless x is
  // strictly increasing with at least two finite points.
  static ForceCharacteristic table(std::vector<double> xs, std::vector<double> fs) {
    ForceCharacteristic k;
    k.is_table = true;
    if (xs.size() < 2 || xs.size() != fs.size())
      throw std::invalid_argument("at least two [x, F] points");
    for (size_t i = 1; i < xs.size(); ++i)
      if (!(xs[i] > xs[i - 1])) throw std::invalid_argument("x strictly increasing");
    k.x = std::move(xs);
    k.f = std::move(fs);
    k.compute_slopes();
    return k;
  }

  // The inverse characteristic x(F) of a strictly increasing table (or a
  // non-zero linear coefficient), used where a damper's velocity must be
  // explicit in its force (series_spring_damper). For a table it is the
  // inverse of P, scale 1: x = P^-1(F / scale).
  ForceCharacteristic<S> inverse() const {
    if (!is_table) return linear(S(1) / coefficient);
    for (size_t i = 1; i < f.size(); ++i)
      if (!(f[i] > f[i - 1])) throw std::invalid_argument("F strictly increasing");
    return table(f, x);
  }

  bool strictly_increasing() const {
    if (!is_table) return value_of(coefficient) > 0.0;
    for (size_t i = 1; i < f.size(); ++i)
      if (!(f[i] > f[i - 1])) return false;
    return true;
  }

  double slope_at_zero() const {
    if (!is_table) return value_of(coefficient);
    const double h = 1e-7 * (x.back() - x.front());
    return (value(h) - value(-h)) / (2.0 * h);
  }

  template <class T> T force(const T& xv) const {
    if (!is_table) return lift<T>(coefficient) * xv;
    return lift<T>(scale) * table_force(xv);
  }
  double value(double xv) const { return force<double>(xv); }

  // Integral of F from 0 to x (the potential of a spring characteristic).
  double integral(double xv) const {
    if (!is_table) return 0.5 * value_of(coefficient) * xv * xv;
    return value_of(scale) * (antiderivative(xv) - antiderivative(0.0));
  }

  template <class S2> ForceCharacteristic<S2> cast() const {
    ForceCharacteristic<S2> k;
    k.is_table = is_table;
    k.coefficient = lift<S2>(coefficient);
    k.scale = lift<S2>(scale);
    k.x = x;
    k.f = f;
    k.slope = slope;
    return k;
  }

 private:
  // P(x): the table's interpolant, unscaled.
  template <class T> T table_force(const T& xv) const {
    const double xd = value_of(xv);
    if (xd <= x.front()) return T(f.front()) + T(slope.front()) * (xv - T(x.front()));
    if (xd >= x.back()) return T(f.back()) + T(slope.back()) * (xv - T(x.back()));
    const size_t i = segment(xd);
    const double h = x[i + 1] - x[i];
    const T t = (xv - T(x[i])) / T(h);
    const T t2 = t * t, t3 = t2 * t;
    // Cubic Hermite basis.
    return T(f[i]) * (T(2) * t3 - T(3) * t2 + T(1)) + T(h * slope[i]) * (t3 - T(2) * t2 + t) +
           T(f[i + 1]) * (T(-2) * t3 + T(3) * t2) + T(h * slope[i + 1]) * (t3 - t2);
  }

  size_t segment(double xd) const {
    const auto it = std::upper_bound(x.begin(), x.end(), xd);
    return std::min<size_t>(size_t(it - x.begin()) - 1, x.size() - 2);
  }

  void compute_slopes() {
    const size_t n = x.size();
    std::vector<double> secant(n - 1);
    for (size_t i = 0; i + 1 < n; ++i) secant[i] = (f[i + 1] - f[i]) / (x[i + 1] - x[i]);
    slope.assign(n, 0.0);
    slope.front() = secant.front();
    slope.back() = secant.back();
    for (size_t i = 1; i + 1 < n; ++i) {
      const double a = secant[i - 1], b = secant[i];
      if (a * b <= 0.0) {
        slope[i] = 0.0;
      } else {
        // Weighted harmonic mean (Fritsch-Butland / PCHIP), monotone.
        const double h0 = x[i] - x[i - 1], h1 = x[i + 1] - x[i];
        const double w1 = 2.0 * h1 + h0, w2 = h1 + 2.0 * h0;
        slope[i] = (w1 + w2) / (w1 / a + w2 / b);
      }
    }
  }

  // Antiderivative G with G(x0) = 0, continuous everywhere.
  double antiderivative(double xv) const {
    const size_t n = x.size();
    auto segment_integral = [&](size_t i, double t) {  // integral over [x_i, x_i + t h]
      const double h = x[i + 1] - x[i];
      const double t2 = t * t, t3 = t2 * t, t4 = t3 * t;
      // Integrals of the Hermite basis from 0 to t, times h.
      const double h00 = 0.5 * t4 - t3 + t, h10 = 0.25 * t4 - 2.0 / 3.0 * t3 + 0.5 * t2;
      const double h01 = -0.5 * t4 + t3, h11 = 0.25 * t4 - t3 / 3.0;
      return h * (f[i] * h00 + h * slope[i] * h10 + f[i + 1] * h01 + h * slope[i + 1] * h11);
    };
    if (xv <= x.front()) {
      const double u = xv - x.front();
      return f.front() * u + 0.5 * slope.front() * u * u;
    }
    double sum = 0.0;
    for (size_t i = 0; i + 1 < n; ++i) {
      if (xv <= x[i + 1]) return sum + segment_integral(i, (xv - x[i]) / (x[i + 1] - x[i]));
      sum += segment_integral(i, 1.0);
    }
    const double u = xv - x.back();
    return sum + f.back() * u + 0.5 * slope.back() * u * u;
  }
};

}  // namespace railstab
