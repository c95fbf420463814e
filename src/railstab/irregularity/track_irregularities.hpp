#pragma once
// Track irregularities along the arc length, synthesised from a PSD
// (irregularity_psd.hpp) with a seed, sampled on a grid and splined
// (docs/irregular_track.md):
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
// then 1; zero before start and after start + length.
// The variance of the sum is sum_k a_k^2 / 2 = scale^2 sum_k S(Omega_k) dOmega,
// the PSD's integral over the band (irregularity_band_variance_m2) to the
// quadrature error of that sum.
#include <railstab/irregularity/irregularity_spec.hpp>
#include <railstab/profiles/cubic_spline.hpp>

#include <array>
#include <vector>

namespace railstab {

class TrackIrregularities {
 public:
  explicit TrackIrregularities(const IrregularitySpec& spec);

  const IrregularitySpec& spec() const { return spec_; }
  // The channel's value and its derivative d/ds at arc length s (spline of
  // the samples; zero outside [start, start + length]).
  CubicSpline::Value at(IrregularityChannel channel, double s_m) const;
  // The samples (s_m and per channel), as written by `railstab track`.
  const std::vector<double>& sample_arc_lengths_m() const { return s_; }
  const std::vector<double>& samples(IrregularityChannel channel) const {
    return values_[size_t(channel)];
  }
  // sum_k a_k^2 / 2 of the channel: the variance the synthesis carries.
  double synthesised_variance_m2(IrregularityChannel channel) const {
    return variance_[size_t(channel)];
  }

 private:
  IrregularitySpec spec_;
  std::vector<double> s_;
  std::array<std::vector<double>, kIrregularityChannels> values_;
  std::array<CubicSpline, kIrregularityChannels> splines_;
  std::array<double, kIrregularityChannels> variance_{};
};

}  // namespace railstab
