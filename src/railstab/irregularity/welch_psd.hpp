#pragma once
// Welch's estimate of a one-sided PSD of a signal sampled at equal steps of
// the arc length (docs/irregular_track.md): segments of `segment_samples`
// with 50 % overlap, each multiplied by a Hann window
// w_n = 0.5 (1 - cos(2 pi n / N)), transformed (Eigen's FFT, kissfft), and
//   S(Omega_k) = 2 ds |X_k|^2 / (2 pi sum_n w_n^2),  Omega_k = 2 pi k / (N ds),
// averaged over the segments; in m^2/(rad/m) like irregularity_psd.hpp (the
// variance is the sum of S dOmega with dOmega = 2 pi / (N ds)). The DC and
// Nyquist bins are not doubled.
#include <vector>

namespace railstab {

struct WelchPsd {
  std::vector<double> omega_rad_per_m;
  std::vector<double> psd_m2_per_rad_per_m;
  int segments = 0;
};

// Throws std::invalid_argument if the signal is shorter than one segment.
WelchPsd welch_psd(const std::vector<double>& signal, double sample_interval_m, int segment_samples);

}  // namespace railstab
