#include <railstab/profiles/cubic_spline.hpp>

#include <algorithm>
#include <stdexcept>

namespace railstab {

// Natural spline: for the interior knots (h_i = x_{i+1} - x_i)
//   h_{i-1} m_{i-1} + 2 (h_{i-1} + h_i) m_i + h_i m_{i+1}
//     = 6 [(f_{i+1} - f_i)/h_i - (f_i - f_{i-1})/h_{i-1}],  m_0 = m_n = 0,
// a diagonally dominant tridiagonal system (Thomas algorithm).
CubicSpline::CubicSpline(std::vector<double> x, std::vector<double> f)
    : x_(std::move(x)), f_(std::move(f)) {
  const size_t n = x_.size();
  if (n < 2 || f_.size() != n)
    throw std::invalid_argument("CubicSpline: need at least 2 knots and one value per knot");
  for (size_t i = 1; i < n; ++i)
    if (!(x_[i] > x_[i - 1]))
      throw std::invalid_argument("CubicSpline: knots must be strictly increasing");
  // One bucket per knot interval on average.
  const size_t buckets = n - 1;
  bucket_width_ = (x_.back() - x_.front()) / double(buckets);
  bucket_interval_.resize(buckets);
  for (size_t b = 0, i = 0; b < buckets; ++b) {
    const double left = x_.front() + double(b) * bucket_width_;
    while (i + 2 < n && x_[i + 1] <= left) ++i;
    bucket_interval_[b] = i;
  }
  m_.assign(n, 0.0);
  if (n < 3) return;
  std::vector<double> diag(n, 0.0), upper(n, 0.0), rhs(n, 0.0);
  for (size_t i = 1; i + 1 < n; ++i) {
    const double h0 = x_[i] - x_[i - 1], h1 = x_[i + 1] - x_[i];
    diag[i] = 2.0 * (h0 + h1);
    upper[i] = h1;
    rhs[i] = 6.0 * ((f_[i + 1] - f_[i]) / h1 - (f_[i] - f_[i - 1]) / h0);
  }
  // Forward elimination over rows 1..n-2 (lower coefficient of row i is h_{i-1}).
  for (size_t i = 2; i + 1 < n; ++i) {
    const double lower = x_[i] - x_[i - 1];
    const double w = lower / diag[i - 1];
    diag[i] -= w * upper[i - 1];
    rhs[i] -= w * rhs[i - 1];
  }
  for (size_t i = n - 2; i >= 1; --i) {
    m_[i] = (rhs[i] - upper[i] * m_[i + 1]) / diag[i];
    if (i == 1) break;
  }
}

size_t CubicSpline::interval(double x) const {
  const size_t n = x_.size();
  if (x <= x_.front()) return 0;
  if (x >= x_.back()) return n - 2;
  // The bucket's interval is near; walk to the largest i with x_i <= x (the
  // walk makes the answer exact whatever the bucket's rounding).
  const double b = (x - x_.front()) / bucket_width_;
  const size_t last = bucket_interval_.size() - 1;
  size_t i = bucket_interval_[b >= 0.0 && b < double(last) ? size_t(b) : last];
  while (i > 0 && x_[i] > x) --i;
  while (i + 2 < n && x_[i + 1] <= x) ++i;
  return i;
}

double CubicSpline::operator()(double x) const {
  if (x < x_.front() || x > x_.back()) return evaluate(x).f;
  const size_t i = std::min(interval(x), x_.size() - 2);
  const double h = x_[i + 1] - x_[i];
  const double a = (x_[i + 1] - x) / h, b = (x - x_[i]) / h;
  // As evaluate()'s f.
  return a * f_[i] + b * f_[i + 1] +
         ((a * a * a - a) * m_[i] + (b * b * b - b) * m_[i + 1]) * h * h / 6.0;
}

CubicSpline::Value CubicSpline::evaluate(double x) const {
  const size_t n = x_.size();
  if (x < x_.front() || x > x_.back()) {
    // Straight continuation with the end slope.
    const bool left = x < x_.front();
    const Value end = evaluate(left ? x_.front() : x_.back());
    const double dx = x - (left ? x_.front() : x_.back());
    return {end.f + end.df * dx, end.df, 0.0};
  }
  const size_t i = std::min(interval(x), n - 2);
  const double h = x_[i + 1] - x_[i];
  const double a = (x_[i + 1] - x) / h, b = (x - x_[i]) / h;
  // f = a f_i + b f_{i+1} + [(a^3 - a) m_i + (b^3 - b) m_{i+1}] h^2 / 6
  const double f = a * f_[i] + b * f_[i + 1] +
                   ((a * a * a - a) * m_[i] + (b * b * b - b) * m_[i + 1]) * h * h / 6.0;
  const double df = (f_[i + 1] - f_[i]) / h -
                    (3.0 * a * a - 1.0) / 6.0 * h * m_[i] + (3.0 * b * b - 1.0) / 6.0 * h * m_[i + 1];
  const double d2f = a * m_[i] + b * m_[i + 1];
  return {f, df, d2f};
}

}  // namespace railstab
