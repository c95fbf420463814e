#include <railstab/signals/band_pass.hpp>

#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>
#include <string>

namespace railstab {

namespace {
using Complex = std::complex<double>;

Complex section_response(const SecondOrderSection& s, Complex z_inv) {
  return (s.b0 + s.b1 * z_inv + s.b2 * z_inv * z_inv) / (1.0 + s.a1 * z_inv + s.a2 * z_inv * z_inv);
}
}  // namespace

BandPassFilter butterworth_band_pass(double T, double f_lo, double f_hi, int order) {
  const double nyquist = 0.5 / T;
  if (!(T > 0.0) || !(f_lo > 0.0 && f_lo < f_hi && f_hi < nyquist) || order < 1 || order > 10)
    throw std::invalid_argument("butterworth_band_pass: expected 0 < f_lo < f_hi < " +
                                std::to_string(nyquist) + " Hz (Nyquist) and order 1-10, got " +
                                std::to_string(f_lo) + " - " + std::to_string(f_hi) + " Hz, order " +
                                std::to_string(order));
  const double pi = std::numbers::pi;
  const double w_lo = 2.0 / T * std::tan(pi * f_lo * T), w_hi = 2.0 / T * std::tan(pi * f_hi * T);
  const double B = w_hi - w_lo, w0_sq = w_lo * w_hi;
  BandPassFilter filter;
  filter.sample_interval_s = T;
  std::vector<double> real_poles;  // a very wide band's real poles, paired below
  for (int k = 0; k < order; ++k) {
    const Complex p = std::polar(1.0, pi * (2.0 * k + order + 1.0) / (2.0 * order));
    const Complex half = p * B / 2.0;
    const Complex root = std::sqrt(half * half - w0_sq);
    for (const Complex q : {half + root, half - root}) {
      const Complex z = (2.0 / T + q) / (2.0 / T - q);
      if (std::abs(q.imag()) <= 1e-12 * std::abs(q))
        real_poles.push_back(z.real());
      else if (q.imag() > 0.0)  // the other half are these poles' conjugates
        filter.sections.push_back({1.0, 0.0, -1.0, -2.0 * z.real(), std::norm(z)});
    }
  }
  for (size_t i = 0; i + 1 < real_poles.size(); i += 2)
    filter.sections.push_back(
        {1.0, 0.0, -1.0, -(real_poles[i] + real_poles[i + 1]), real_poles[i] * real_poles[i + 1]});
  // Scale to unit gain at the band's centre: the frequency whose prewarped
  // w is w0 (the analog response's peak, mapped exactly).
  const double f_centre = std::atan(std::sqrt(w0_sq) * T / 2.0) / (pi * T);
  const double gain = band_pass_gain(filter, f_centre);
  const double per_section = std::pow(1.0 / gain, 1.0 / double(filter.sections.size()));
  for (SecondOrderSection& s : filter.sections) {
    s.b0 *= per_section;
    s.b1 *= per_section;
    s.b2 *= per_section;
  }
  return filter;
}

std::vector<double> filter_signal(const BandPassFilter& filter, const std::vector<double>& x) {
  std::vector<double> y = x;
  for (const SecondOrderSection& s : filter.sections) {
    double x1 = 0.0, x2 = 0.0, y1 = 0.0, y2 = 0.0;
    for (double& v : y) {
      const double out = s.b0 * v + s.b1 * x1 + s.b2 * x2 - s.a1 * y1 - s.a2 * y2;
      x2 = x1;
      x1 = v;
      y2 = y1;
      y1 = out;
      v = out;
    }
  }
  return y;
}

double band_pass_gain(const BandPassFilter& filter, double f) {
  const Complex z_inv = std::polar(1.0, -2.0 * std::numbers::pi * f * filter.sample_interval_s);
  Complex h = 1.0;
  for (const SecondOrderSection& s : filter.sections) h *= section_response(s, z_inv);
  return std::abs(h);
}

}  // namespace railstab
