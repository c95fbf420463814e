#pragma once
// The irregularities against their target (`railstab track`): each
// channel's rms between the fades against the rms of the target PSD over the
// band, and Welch's PSD of the channel (sampled every sample_interval_m
// between the fades) against the target PSD (docs/irregular_track.md). A
// measured record has no target: its target fields are zero.
#include <railstab/irregularity/track_irregularities.hpp>
#include <railstab/irregularity/welch_psd.hpp>

#include <array>
#include <string>

namespace railstab {

struct IrregularityChannelCheck {
  double sample_rms_m = 0.0;        // of the samples between the fades
  double synthesised_rms_m = 0.0;   // sqrt(sum a_k^2 / 2)
  double target_rms_m = 0.0;        // scale sqrt(integral of S over the band)
  WelchPsd welch;
  std::vector<double> target_psd_m2_per_rad_per_m;  // at welch's Omega; 0 outside the band
};

struct IrregularityCheck {
  bool has_target = true;  // false: a measured record
  int segment_samples = 0;  // Welch segment: a power of two >= 2 wavelength_max / ds
  std::array<IrregularityChannelCheck, kIrregularityChannels> channels;
};

// Throws std::invalid_argument naming the length needed if the irregular
// stretch is shorter than one Welch segment.
IrregularityCheck check_irregularities(const TrackIrregularities& irregularities);

}  // namespace railstab
