#pragma once
// Track irregularities along the arc length (docs/irregular_track.md),
// synthesised from a PSD (irregularity_psd.hpp) with a seed, sampled on a
// grid and splined, or read from a measured file and splined through its
// rows. Synthesis:
//
//   z_c(s) = r(s) sum_k a_k cos(Omega_k (s - start) + phi_k),
//   a_k = scale sqrt(2 S_c(Omega_k) dOmega),
// with the band [2 pi / wavelength_max, 2 pi / wavelength_min] cut into
// `components` equal bands dOmega, Omega_k drawn uniformly inside band k and
// phi_k uniformly in [0, 2 pi) (so the sum has no period), from one
// SplitMix64 stream of the seed (reproducible on every platform: the
// generator and the mapping to [0, 1) are written here, not std::'s
// distributions). Channels draw in the order alignment, level, cross level,
// gauge: per channel `components` frequencies, then as many phases.
// r(s) = (1 - cos(pi (s - start) / fade_in)) / 2 over the first fade_in m,
// the same ramp down over the last fade_out m, 1 between; zero before start
// and after start + length. A measured record: z_c(s) = r(s) scale f_c(s)
// at the file's rows, start and length its first arc length and its span.
// The variance of the sum is sum_k a_k^2 / 2 = scale^2 sum_k S(Omega_k) dOmega,
// the PSD's integral over the band (irregularity_band_variance_m2) to the
// quadrature error of that sum.
#include <railstab/irregularity/irregularity_spec.hpp>
#include <railstab/profiles/cubic_spline.hpp>

#include <array>
#include <string>
#include <vector>

namespace railstab {

class TrackIrregularities {
 public:
  explicit TrackIrregularities(const IrregularitySpec& spec);

  const IrregularitySpec& spec() const { return spec_; }
  // The channel's value and its derivative d/ds at arc length s (spline of
  // the samples; zero outside [first_m, last_m]).
  CubicSpline::Value at(IrregularityChannel channel, double s_m) const {
    if (!(s_m >= first_m_ && s_m <= last_m_)) return {0.0, 0.0, 0.0};
    return splines_[size_t(channel)].evaluate(s_m);
  }
  // Where the irregular stretch begins and ends (arc lengths, m).
  double first_m() const { return first_m_; }
  double last_m() const { return last_m_; }
  bool measured() const { return spec_.measured.has_value(); }
  // The samples (s_m and per channel): the synthesis grid or the file's
  // rows, faded and scaled, as written by `railstab track`.
  const std::vector<double>& sample_arc_lengths_m() const { return s_; }
  const std::vector<double>& samples(IrregularityChannel channel) const {
    return values_[size_t(channel)];
  }
  // sum_k a_k^2 / 2 of the channel: the variance the synthesis carries (0
  // for a measured record).
  double synthesised_variance_m2(IrregularityChannel channel) const {
    return variance_[size_t(channel)];
  }

 private:
  IrregularitySpec spec_;
  std::vector<double> s_;
  std::array<std::vector<double>, kIrregularityChannels> values_;
  std::array<CubicSpline, kIrregularityChannels> splines_;
  std::array<double, kIrregularityChannels> variance_{};
  double first_m_ = 0.0, last_m_ = 0.0;
};

// One line naming the irregularities for reports: the spectrum with its
// seed and band, or the measured file; the stretch and the scale.
std::string irregularity_description(const TrackIrregularities& irregularities);

// The fade r(s) of the header comment at a point u m into a stretch of
// `length_m` (1 between the ramps).
double irregularity_fade(double u_m, double length_m, double fade_in_m, double fade_out_m);

}  // namespace railstab
