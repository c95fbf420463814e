#include <railstab/irregularity/track_irregularities.hpp>

#include <railstab/irregularity/irregularity_psd.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
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

std::string irregularity_description(const TrackIrregularities& irr) {
  const IrregularitySpec& spec = irr.spec();
  std::ostringstream out;
  out << std::setprecision(6);
  if (irr.measured())
    out << "measured file " << spec.measured->path;
  else
    out << name_in(kIrregularitySpectrumNames, spec.spectrum) << ", seed " << spec.seed << ", wavelengths "
        << spec.wavelength_min_m << "-" << spec.wavelength_max_m << " m";
  out << ", " << irr.last_m() - irr.first_m() << " m from s = " << irr.first_m() << " m, amplitude scale "
      << spec.amplitude_scale;
  return out.str();
}

double irregularity_fade(double u_m, double length_m, double fade_in_m, double fade_out_m) {
  double r = 1.0;
  if (fade_in_m > 0.0 && u_m < fade_in_m)
    r *= 0.5 * (1.0 - std::cos(std::numbers::pi * std::max(u_m, 0.0) / fade_in_m));
  const double to_end = length_m - u_m;
  if (fade_out_m > 0.0 && to_end < fade_out_m)
    r *= 0.5 * (1.0 - std::cos(std::numbers::pi * std::max(to_end, 0.0) / fade_out_m));
  return r;
}

TrackIrregularities::TrackIrregularities(const IrregularitySpec& spec) : spec_(spec) {
  if (spec.measured) {
    const MeasuredIrregularities& m = *spec.measured;
    if (m.arc_length_m.size() < 4)
      throw std::invalid_argument("TrackIrregularities: a measured record of fewer than 4 rows (the reader admits none)");
    s_ = m.arc_length_m;
    first_m_ = s_.front();
    last_m_ = s_.back();
    const double length = last_m_ - first_m_;
    for (int c = 0; c < kIrregularityChannels; ++c) {
      std::vector<double>& v = values_[size_t(c)];
      v.resize(s_.size());
      for (size_t i = 0; i < s_.size(); ++i)
        v[i] = spec.amplitude_scale * m.channels_m[size_t(c)][i] *
               irregularity_fade(s_[i] - first_m_, length, spec.fade_in_m, spec.fade_out_m);
      splines_[size_t(c)] = CubicSpline(s_, v);
    }
    return;
  }
  if (!(spec.wavelength_min_m > 0.0 && spec.wavelength_max_m > spec.wavelength_min_m) ||
      !(spec.length_m > 0.0) || !(spec.sample_interval_m > 0.0) || spec.components < 1)
    throw std::invalid_argument("TrackIrregularities: an invalid spec (the scene checker admits none)");
  const double w_lo = 2.0 * std::numbers::pi / spec.wavelength_max_m;
  const double w_hi = 2.0 * std::numbers::pi / spec.wavelength_min_m;
  const int n = spec.components;
  const double dw = (w_hi - w_lo) / n;
  const int samples = int(std::ceil(spec.length_m / spec.sample_interval_m)) + 1;
  first_m_ = spec.start_m;
  last_m_ = spec.start_m + spec.length_m;
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
      v[size_t(i)] = irregularity_fade(u, spec.length_m, spec.fade_in_m, spec.fade_out_m) * sum;
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


}  // namespace railstab
