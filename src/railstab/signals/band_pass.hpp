#pragma once
// A digital Butterworth band-pass for EN 14363's running-stability signals
// (Sum Y and the bogie frame's lateral acceleration, filtered f0 +- 2 Hz
// around the instability frequency f0; docs/ride_quantities.md, "EN 14363 signal processing").
//
// Design (an independent implementation can reproduce it): the analog
// Butterworth low-pass prototype of order N, poles
//   p_k = exp(i pi (2k + N + 1) / (2N)),  k = 0..N-1,
// moved to the band by s -> (s^2 + w0^2) / (B s), B = w_hi - w_lo,
// w0^2 = w_hi w_lo, each p_k giving the two poles
//   q = p_k B / 2 +- sqrt((p_k B / 2)^2 - w0^2),
// with N zeros at s = 0 and N at infinity; then the bilinear transform
// z = (2/T + q) / (2/T - q) with the band edges prewarped,
// w = (2/T) tan(pi f T). The N poles of positive imaginary part each form a
// second-order section with their conjugates and the zeros +1 and -1:
//   H_j(z) = g (1 - z^-2) / (1 - 2 Re(z_j) z^-1 + |z_j|^2 z^-2),
// the gain g making |H(e^{i 2 pi f0 T})| = 1 at the centre f0, where the
// prewarped frequency is w0 (f0 = atan(w0 T / 2) / (pi T), within 0.1 % of
// sqrt(f_lo f_hi) well below Nyquist). The
// sections run in cascade, causally, from zero state. The response is -3 dB
// at f_lo and f_hi, as every Butterworth band-pass.
#include <vector>

namespace railstab {

struct SecondOrderSection {
  double b0, b1, b2, a1, a2;  // y = b0 x + b1 x1 + b2 x2 - a1 y1 - a2 y2
};

struct BandPassFilter {
  std::vector<SecondOrderSection> sections;
  double sample_interval_s = 0.0;
};

// Throws std::invalid_argument unless 0 < f_lo < f_hi < the Nyquist frequency
// and 1 <= order <= 10.
BandPassFilter butterworth_band_pass(double sample_interval_s, double f_lo_Hz, double f_hi_Hz,
                                     int order);

std::vector<double> filter_signal(const BandPassFilter& filter, const std::vector<double>& x);

// |H| at frequency f (for tests and reports).
double band_pass_gain(const BandPassFilter& filter, double f_Hz);

}  // namespace railstab
