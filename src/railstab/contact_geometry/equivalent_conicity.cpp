#include <railstab/contact_geometry/equivalent_conicity.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace railstab {

double DeltaRFunction::operator()(double y) const {
  if (y_m.size() < 2 || y < y_m.front() || y > y_m.back()) {
    std::ostringstream msg;
    msg << "equivalent conicity: the wheelset motion reaches y = " << y * 1e3
        << " mm, outside the delta_r function (" << (y_m.empty() ? 0.0 : y_m.front() * 1e3)
        << " .. " << (y_m.empty() ? 0.0 : y_m.back() * 1e3)
        << " mm); expected delta_r sampled beyond the amplitude";
    throw std::invalid_argument(msg.str());
  }
  const size_t i = std::min(size_t(std::upper_bound(y_m.begin(), y_m.end(), y) - y_m.begin()),
                            y_m.size() - 1);
  const double w = (y - y_m[i - 1]) / (y_m[i] - y_m[i - 1]);
  return delta_r_m[i - 1] + w * (delta_r_m[i] - delta_r_m[i - 1]);
}

namespace {

void require_samples(const DeltaRFunction& dr) {
  bool ok = dr.y_m.size() >= 2 && dr.y_m.size() == dr.delta_r_m.size();
  for (size_t i = 1; ok && i < dr.y_m.size(); ++i) ok = dr.y_m[i] > dr.y_m[i - 1];
  for (size_t i = 0; ok && i < dr.y_m.size(); ++i)
    ok = std::isfinite(dr.y_m[i]) && std::isfinite(dr.delta_r_m[i]);
  if (!ok)
    throw std::invalid_argument(
        "equivalent conicity: expected a delta_r function of at least two finite samples with "
        "strictly increasing y");
}

// The potential P(y) = integral of delta_r from the first sample: exact for
// the linear interpolant, on segment k with t = y - y_k, s the segment slope:
//   P = P_k + delta_r_k t + s t^2 / 2.
class Potential {
 public:
  explicit Potential(const DeltaRFunction& dr) : dr_(dr), P_(dr.y_m.size(), 0.0) {
    for (size_t k = 0; k + 1 < P_.size(); ++k)
      P_[k + 1] = P_[k] + 0.5 * (y(k + 1) - y(k)) * (d(k) + d(k + 1));
  }
  size_t segments() const { return P_.size() - 1; }
  size_t segment_of(double v) const {
    const size_t i = size_t(std::upper_bound(dr_.y_m.begin(), dr_.y_m.end(), v) - dr_.y_m.begin());
    return std::min(std::max<size_t>(i, 1), P_.size() - 1) - 1;
  }
  double at(double v) const {
    const size_t k = segment_of(v);
    const double t = v - y(k);
    return P_[k] + d(k) * t + 0.5 * slope(k) * t * t;
  }
  double sample(size_t k) const { return P_[k]; }

  // First v >= from where P(v) reaches L (P(from) < L), walking up; NaN if
  // P stays below L up to the last sample.
  double first_up(double from, double L) const {
    for (size_t k = segment_of(from); k < segments(); ++k) {
      const double t0 = std::max(0.0, from - y(k));
      const double t = first_root(k, L, t0, y(k + 1) - y(k), true);
      if (std::isfinite(t)) return y(k) + t;
    }
    return std::numeric_limits<double>::quiet_NaN();
  }
  // First v <= from where P(v) reaches L, walking down; NaN if none.
  double first_down(double from, double L) const {
    for (size_t k = segment_of(from) + 1; k-- > 0;) {
      const double t1 = std::min(y(k + 1) - y(k), from - y(k));
      const double t = first_root(k, L, 0.0, t1, false);
      if (std::isfinite(t)) return y(k) + t;
    }
    return std::numeric_limits<double>::quiet_NaN();
  }

 private:
  double y(size_t k) const { return dr_.y_m[k]; }
  double d(size_t k) const { return dr_.delta_r_m[k]; }
  double slope(size_t k) const { return (d(k + 1) - d(k)) / (y(k + 1) - y(k)); }
  // The root of P_k + d_k t + s t^2 / 2 = L in [t0, t1] nearest t0 (upwards)
  // or nearest t1 (downwards); NaN if none.
  double first_root(size_t k, double L, double t0, double t1, bool upwards) const {
    const double a = 0.5 * slope(k), b = d(k), c = P_[k] - L;
    double roots[2];
    int n = 0;
    if (std::abs(a) * (t1 - t0) <= 1e-14 * std::abs(b)) {
      if (b != 0.0) roots[n++] = -c / b;
    } else {
      const double disc = b * b - 4 * a * c;
      if (disc >= 0.0) {
        const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
        roots[n++] = q / a;
        if (q != 0.0) roots[n++] = c / q;
      }
    }
    const double tol = 1e-15 + 1e-12 * (t1 - t0);
    double best = std::numeric_limits<double>::quiet_NaN();
    for (int i = 0; i < n; ++i) {
      const double r = roots[i];
      if (!(r >= t0 - tol && r <= t1 + tol)) continue;
      const double clamped = std::clamp(r, t0, t1);
      if (!std::isfinite(best) || (upwards ? clamped < best : clamped > best)) best = clamped;
    }
    return best;
  }
  const DeltaRFunction& dr_;
  std::vector<double> P_;
};

}  // namespace

KlingelEquilibrium klingel_equilibrium(const DeltaRFunction& dr) {
  require_samples(dr);
  const std::vector<double>& y = dr.y_m;
  const std::vector<double>& d = dr.delta_r_m;
  const size_t n = y.size();
  auto zero = [&](size_t i) { return std::abs(d[i]) <= kDeltaRZero_m; };
  // Start at the sample nearest y = 0 and walk downhill in P (against the
  // sign of delta_r) to the first sample where delta_r is zero or has
  // changed sign.
  size_t i = size_t(std::min_element(y.begin(), y.end(),
                                     [](double a, double b) { return std::abs(a) < std::abs(b); }) -
                    y.begin());
  auto no_equilibrium = [&]() {
    std::ostringstream msg;
    msg << "equivalent conicity: delta_r does not change sign from negative to positive within "
           "the sampled shifts "
        << y.front() * 1e3 << " .. " << y.back() * 1e3
        << " mm; expected a restoring delta_r (the wheelset has no equilibrium to oscillate "
           "about)";
    throw std::invalid_argument(msg.str());
  };
  KlingelEquilibrium e;
  if (!zero(i) && d[i] > 0.0) {
    while (i > 0 && d[i] > kDeltaRZero_m) --i;
    if (d[i] > kDeltaRZero_m) no_equilibrium();
    if (!zero(i)) {  // sign change between i and i + 1
      const double w = d[i] / (d[i] - d[i + 1]);
      e.low_m = e.high_m = y[i] + w * (y[i + 1] - y[i]);
      return e;
    }
  } else if (!zero(i)) {
    while (i + 1 < n && d[i] < -kDeltaRZero_m) ++i;
    if (d[i] < -kDeltaRZero_m) no_equilibrium();
    if (!zero(i)) {  // sign change between i - 1 and i
      const double w = d[i - 1] / (d[i - 1] - d[i]);
      e.low_m = e.high_m = y[i - 1] + w * (y[i] - y[i - 1]);
      return e;
    }
  }
  // A stretch of zero delta_r around sample i.
  size_t lo = i, hi = i;
  while (lo > 0 && zero(lo - 1)) --lo;
  while (hi + 1 < n && zero(hi + 1)) ++hi;
  e.low_m = y[lo];
  e.high_m = y[hi];
  return e;
}

ConicityPoint equivalent_conicity(const DeltaRFunction& delta_r, double amplitude_m, double e0,
                                  double r0) {
  if (!(amplitude_m > 0.0) || !(e0 > 0.0) || !(r0 > 0.0))
    throw std::invalid_argument("equivalent conicity: amplitude, e0 and r0 must be positive");
  const KlingelEquilibrium eq = klingel_equilibrium(delta_r);
  const Potential P(delta_r);
  ConicityPoint out;
  out.amplitude_m = amplitude_m;
  const double flat_half_width = 0.5 * (eq.high_m - eq.low_m);
  if (amplitude_m <= flat_half_width) {
    // The motion stays on the zero stretch: no restoring, conicity 0.
    out.wavelength_m = std::numeric_limits<double>::infinity();
    out.equivalent_conicity = 0.0;
    out.lower_turning_point_m = eq.centre_m() - amplitude_m;
    out.upper_turning_point_m = eq.centre_m() + amplitude_m;
    return out;
  }
  // The level L of the turning points: half_width(L) = A, by bisection
  // between the well's bottom and the highest level both sides reach.
  auto half_width = [&](double L) {
    return 0.5 * (P.first_up(eq.high_m, L) - P.first_down(eq.low_m, L));
  };
  const double L_bottom = std::max(P.at(eq.low_m), P.at(eq.high_m));
  double top_up = -std::numeric_limits<double>::infinity(), top_down = top_up;
  for (size_t k = 0; k <= P.segments(); ++k) {
    if (delta_r.y_m[k] >= eq.high_m) top_up = std::max(top_up, P.sample(k));
    if (delta_r.y_m[k] <= eq.low_m) top_down = std::max(top_down, P.sample(k));
  }
  const double L_top = std::min(top_up, top_down);
  auto leaves = [&](double reach_m) {
    std::ostringstream msg;
    msg << "equivalent conicity: the Klingel motion at amplitude " << amplitude_m * 1e3
        << " mm about the equilibrium (" << eq.centre_m() * 1e3
        << " mm) leaves the delta_r function (" << delta_r.y_m.front() * 1e3 << " .. "
        << delta_r.y_m.back() * 1e3 << " mm; the largest amplitude it holds is "
        << reach_m * 1e3 << " mm); expected delta_r sampled beyond the motion";
    throw std::invalid_argument(msg.str());
  };
  if (!(L_top > L_bottom)) leaves(flat_half_width);
  const double reach = half_width(L_top);
  if (!(reach >= amplitude_m)) leaves(std::isfinite(reach) ? reach : flat_half_width);
  double lo = L_bottom, hi = L_top;
  for (int it = 0; it < 200 && hi - lo > 1e-15 * std::abs(hi) + 1e-30; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (half_width(mid) >= amplitude_m) hi = mid; else lo = mid;
  }
  const double L = hi;
  const double y_upper = P.first_up(eq.high_m, L), y_lower = P.first_down(eq.low_m, L);
  const double reached = 0.5 * (y_upper - y_lower);
  if (std::abs(reached - amplitude_m) > 1e-9 + 1e-6 * amplitude_m) {
    std::ostringstream msg;
    msg << "equivalent conicity: no Klingel cycle about the equilibrium (" << eq.centre_m() * 1e3
        << " mm) has the amplitude " << amplitude_m * 1e3
        << " mm: the half peak-to-peak motion jumps past it to " << reached * 1e3
        << " mm (delta_r changes sign again: a ridge of the potential integral delta_r dy)";
    throw std::invalid_argument(msg.str());
  }
  out.lower_turning_point_m = y_lower;
  out.upper_turning_point_m = y_upper;

  // Wavelength estimate from the energy integral (64-point midpoint rule in
  // theta, y = m + A sin(theta): smooth at the turning points), for the step.
  const double m = 0.5 * (y_lower + y_upper);
  double integral = 0.0;
  const int nodes = 64;
  for (int i = 0; i < nodes; ++i) {
    const double th = -0.5 * std::numbers::pi + std::numbers::pi * (i + 0.5) / nodes;
    const double gap = std::max(L - P.at(m + amplitude_m * std::sin(th)), 1e-300);
    integral += amplitude_m * std::cos(th) / std::sqrt(gap) * (std::numbers::pi / nodes);
  }
  const double lambda_est = 2.0 * std::sqrt(e0 * r0) * integral;

  const double k = 1.0 / (2.0 * e0 * r0);
  const double h = lambda_est / 4000.0;
  auto acc = [&](double y) { return -k * delta_r(y); };
  double s = 0.0, y = y_upper, v = 0.0;
  int sign_changes = 0;
  for (int step = 0; step < 400000 && s <= 4.0 * lambda_est; ++step) {
    // RK4 for (y, v)' = (v, acc(y))
    const double k1y = v, k1v = acc(y);
    const double k2y = v + 0.5 * h * k1v, k2v = acc(y + 0.5 * h * k1y);
    const double k3y = v + 0.5 * h * k2v, k3v = acc(y + 0.5 * h * k2y);
    const double k4y = v + h * k3v, k4v = acc(y + h * k3y);
    const double y1 = y + h / 6.0 * (k1y + 2 * k2y + 2 * k3y + k4y);
    const double v1 = v + h / 6.0 * (k1v + 2 * k2v + 2 * k3v + k4v);
    // A turning point (v = 0) after the start: the bottom (v - to +), then the
    // top again (v + to -) closes the cycle.
    const bool crossed = (sign_changes == 0 && v < 0.0 && v1 >= 0.0) ||
                         (sign_changes == 1 && v > 0.0 && v1 <= 0.0);
    if (crossed && ++sign_changes == 2) {
      // Cubic Hermite for v over the step (v' = acc): root by bisection.
      const double a0 = acc(y), a1 = acc(y1);
      auto vh = [&](double t) {
        const double t2 = t * t, t3 = t2 * t;
        return (2 * t3 - 3 * t2 + 1) * v + (t3 - 2 * t2 + t) * h * a0 + (-2 * t3 + 3 * t2) * v1 +
               (t3 - t2) * h * a1;
      };
      double tlo = 0.0, thi = 1.0;
      for (int it = 0; it < 60; ++it) {
        const double mid = 0.5 * (tlo + thi);
        if ((vh(mid) > 0.0) == (v > 0.0)) tlo = mid; else thi = mid;
      }
      out.wavelength_m = s + 0.5 * (tlo + thi) * h;
      const double two_pi_over = 2.0 * std::numbers::pi / out.wavelength_m;
      out.equivalent_conicity = r0 * e0 * two_pi_over * two_pi_over;
      return out;
    }
    s += h, y = y1, v = v1;
  }
  std::ostringstream msg;
  msg << "equivalent conicity: no full Klingel cycle within " << 4.0 * lambda_est
      << " m at amplitude " << amplitude_m * 1e3 << " mm";
  throw std::invalid_argument(msg.str());
}

}  // namespace railstab
