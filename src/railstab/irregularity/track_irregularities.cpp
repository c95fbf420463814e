#include <railstab/irregularity/track_irregularities.hpp>

#include <railstab/irregularity/irregularity_psd.hpp>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace railstab {

namespace {

// SplitMix64 (Steele, Lea, Flood 2014): a fixed, portable stream.
struct SplitMix64 {
  std::uint64_t state;
  std::uint64_t next() {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double uniform() { return double(next() >> 11) * 0x1.0p-53; }  // [0, 1)
};

}  // namespace

TrackIrregularities::TrackIrregularities(const IrregularitySpec& spec) : spec_(spec) {
  if (!(spec.wavelength_min_m > 0.0 && spec.wavelength_max_m > spec.wavelength_min_m) ||
      !(spec.length_m > 0.0) || !(spec.sample_interval_m > 0.0) || spec.components < 1)
    throw std::invalid_argument("TrackIrregularities: an invalid spec (the scene checker admits none)");
  const double w_lo = 2.0 * std::numbers::pi / spec.wavelength_max_m;
  const double w_hi = 2.0 * std::numbers::pi / spec.wavelength_min_m;
  const int n = spec.components;
  const double dw = (w_hi - w_lo) / n;
  const int samples = int(std::ceil(spec.length_m / spec.sample_interval_m)) + 1;
  s_.resize(size_t(samples));
  for (int i = 0; i < samples; ++i)
    s_[size_t(i)] = spec.start_m + std::min(i * spec.sample_interval_m, spec.length_m);
  SplitMix64 rng{spec.seed};
  for (int c = 0; c < kIrregularityChannels; ++c) {
    const auto channel = IrregularityChannel(c);
    const size_t count = static_cast<size_t>(n);
    std::vector<double> omega(count), amplitude(count), phase(count);
    for (int k = 0; k < n; ++k) omega[size_t(k)] = w_lo + (k + rng.uniform()) * dw;
    for (int k = 0; k < n; ++k) phase[size_t(k)] = 2.0 * std::numbers::pi * rng.uniform();
    double variance = 0.0;
    for (int k = 0; k < n; ++k) {
      const double S = irregularity_psd_m2_per_rad_per_m(spec.spectrum, channel, omega[size_t(k)]);
      amplitude[size_t(k)] = spec.amplitude_scale * std::sqrt(2.0 * S * dw);
      variance += 0.5 * amplitude[size_t(k)] * amplitude[size_t(k)];
    }
    variance_[size_t(c)] = variance;
    std::vector<double>& v = values_[size_t(c)];
    v.assign(size_t(samples), 0.0);
    for (int i = 0; i < samples; ++i) {
      const double u = s_[size_t(i)] - spec.start_m;
      double sum = 0.0;
      for (int k = 0; k < n; ++k) sum += amplitude[size_t(k)] * std::cos(omega[size_t(k)] * u + phase[size_t(k)]);
      const double ramp = spec.fade_in_m > 0.0 && u < spec.fade_in_m
                              ? 0.5 * (1.0 - std::cos(std::numbers::pi * u / spec.fade_in_m))
                              : 1.0;
      v[size_t(i)] = ramp * sum;
    }
    // Duplicate end knots (a length that is not a multiple of the interval)
    // would break the spline: drop the repeated last abscissa.
    std::vector<double> x = s_, f = v;
    if (x.size() >= 2 && x[x.size() - 1] <= x[x.size() - 2]) {
      x.pop_back();
      f.pop_back();
    }
    splines_[size_t(c)] = CubicSpline(std::move(x), std::move(f));
  }
}

CubicSpline::Value TrackIrregularities::at(IrregularityChannel channel, double s_m) const {
  if (s_m < spec_.start_m || s_m > spec_.start_m + spec_.length_m) return {0.0, 0.0, 0.0};
  return splines_[size_t(channel)].evaluate(s_m);
}

}  // namespace railstab
