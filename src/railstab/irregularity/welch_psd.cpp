#include <railstab/irregularity/welch_psd.hpp>

#include <unsupported/Eigen/FFT>

#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>

namespace railstab {

WelchPsd welch_psd(const std::vector<double>& signal, double ds, int n) {
  if (n < 8 || int(signal.size()) < n)
    throw std::invalid_argument("welch_psd: a signal of " + std::to_string(signal.size()) +
                                " samples is shorter than one segment of " + std::to_string(n));
  std::vector<double> window(static_cast<size_t>(n));
  double window_power = 0.0;
  for (int i = 0; i < n; ++i) {
    window[size_t(i)] = 0.5 * (1.0 - std::cos(2.0 * std::numbers::pi * i / n));
    window_power += window[size_t(i)] * window[size_t(i)];
  }
  const int bins = n / 2 + 1;
  WelchPsd result;
  result.psd_m2_per_rad_per_m.assign(size_t(bins), 0.0);
  result.omega_rad_per_m.resize(size_t(bins));
  for (int k = 0; k < bins; ++k) result.omega_rad_per_m[size_t(k)] = 2.0 * std::numbers::pi * k / (n * ds);
  Eigen::FFT<double> fft;
  std::vector<double> segment(static_cast<size_t>(n));
  std::vector<std::complex<double>> spectrum;
  for (size_t start = 0; start + size_t(n) <= signal.size(); start += size_t(n / 2)) {
    for (int i = 0; i < n; ++i) segment[size_t(i)] = window[size_t(i)] * signal[start + size_t(i)];
    fft.fwd(spectrum, segment);
    for (int k = 0; k < bins; ++k) {
      const double one_sided = (k == 0 || 2 * k == n) ? 1.0 : 2.0;
      result.psd_m2_per_rad_per_m[size_t(k)] +=
          one_sided * ds * std::norm(spectrum[size_t(k)]) / (2.0 * std::numbers::pi * window_power);
    }
    ++result.segments;
  }
  for (double& v : result.psd_m2_per_rad_per_m) v /= result.segments;
  return result;
}

}  // namespace railstab
