#pragma once
// Interpolating natural cubic spline f(x) through (x_i, f_i), x strictly
// increasing: C2, the second derivative piecewise linear, zero at both ends.
// Outside [x_0, x_n] the spline continues as the straight line of its end
// slope (C1 there); callers keep to the data range.
#include <cstddef>
#include <vector>

namespace railstab {

class CubicSpline {
 public:
  CubicSpline() = default;
  CubicSpline(std::vector<double> x, std::vector<double> f);

  struct Value {
    double f, df, d2f;
  };
  Value evaluate(double x) const;
  // The value alone, as evaluate(x).f to the last bit (the same expression),
  // for the contact search's samples, which need no derivatives.
  double operator()(double x) const;

  double x_min() const { return x_.front(); }
  double x_max() const { return x_.back(); }
  const std::vector<double>& knots() const { return x_; }
  const std::vector<double>& values() const { return f_; }
  // Index i of the interval [x_i, x_{i+1}] holding x (clamped to the ends):
  // the largest i with x_i <= x. Found from a uniform bucket grid over the
  // knots' range (the interval at each bucket's left end) and a walk to the
  // exact interval, in place of a binary search: the contact tables evaluate
  // the profiles ~10^6 times per scene (docs/performance.md).
  std::size_t interval(double x) const;

 private:
  std::vector<double> x_, f_, m_;  // m: second derivatives at the knots
  double bucket_width_ = 1.0;      // (x_n - x_0) / buckets
  std::vector<std::size_t> bucket_interval_;  // interval(x_0 + b * width)
};

}  // namespace railstab
