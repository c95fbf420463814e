#include <railstab/contact_geometry/equivalent_conicity.hpp>

#include <algorithm>
#include <cmath>
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

ConicityPoint equivalent_conicity(const DeltaRFunction& delta_r, double amplitude_m, double e0,
                                  double r0) {
  if (!(amplitude_m > 0.0) || !(e0 > 0.0) || !(r0 > 0.0))
    throw std::invalid_argument("equivalent conicity: amplitude, e0 and r0 must be positive");
  const double k = 1.0 / (2.0 * e0 * r0);
  const double restoring = delta_r(amplitude_m);
  if (!(restoring > 0.0)) {
    std::ostringstream msg;
    msg << "equivalent conicity: delta_r(" << amplitude_m * 1e3 << " mm) = " << restoring * 1e3
        << " mm does not restore the wheelset; expected delta_r(y) > 0 for y > 0";
    throw std::invalid_argument(msg.str());
  }
  // Wavelength estimate from the secant conicity delta_r(A) / (2 A).
  const double secant = restoring / (2.0 * amplitude_m);
  const double lambda_est = 2.0 * std::numbers::pi * std::sqrt(r0 * e0 / secant);
  const double h = lambda_est / 4000.0;
  auto acc = [&](double y) { return -k * delta_r(y); };
  double s = 0.0, y = amplitude_m, v = 0.0;
  int sign_changes = 0;
  for (int step = 0; step < 400000; ++step) {
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
    if (crossed) {
      if (++sign_changes == 2) {
        // Cubic Hermite for v over the step (v' = acc): root by bisection.
        const double a0 = acc(y), a1 = acc(y1);
        auto vh = [&](double t) {
          const double t2 = t * t, t3 = t2 * t;
          return (2 * t3 - 3 * t2 + 1) * v + (t3 - 2 * t2 + t) * h * a0 + (-2 * t3 + 3 * t2) * v1 +
                 (t3 - t2) * h * a1;
        };
        double lo = 0.0, hi = 1.0;
        for (int it = 0; it < 60; ++it) {
          const double mid = 0.5 * (lo + hi);
          if ((vh(mid) > 0.0) == (v > 0.0)) lo = mid; else hi = mid;
        }
        const double lambda = s + 0.5 * (lo + hi) * h;
        const double two_pi_over = 2.0 * std::numbers::pi / lambda;
        return {amplitude_m, lambda, r0 * e0 * two_pi_over * two_pi_over};
      }
    }
    s += h, y = y1, v = v1;
    if (s > 20.0 * lambda_est) break;
  }
  std::ostringstream msg;
  msg << "equivalent conicity: no full Klingel cycle within " << 20.0 * lambda_est
      << " m at amplitude " << amplitude_m * 1e3 << " mm";
  throw std::invalid_argument(msg.str());
}

}  // namespace railstab
