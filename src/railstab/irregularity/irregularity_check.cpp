#include <railstab/irregularity/irregularity_check.hpp>

#include <railstab/irregularity/irregularity_psd.hpp>

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace railstab {

IrregularityCheck check_irregularities(const TrackIrregularities& irr) {
  const IrregularitySpec& spec = irr.spec();
  const double ds = spec.sample_interval_m;
  IrregularityCheck check;
  check.segment_samples = 8;
  while (check.segment_samples * ds < 2.0 * spec.wavelength_max_m) check.segment_samples *= 2;
  const std::vector<double>& s = irr.sample_arc_lengths_m();
  size_t first = 0;
  while (first < s.size() && s[first] < spec.start_m + spec.fade_in_m) ++first;
  if (s.size() - first < size_t(check.segment_samples)) {
    std::ostringstream msg;
    msg << "track.irregularities.length_m: expected at least fade_in_m + "
        << check.segment_samples * ds << " m (one Welch segment of 2 wavelength_max_m, rounded up "
        << "to a power of two of samples) to check the PSD, got " << spec.length_m << " m";
    throw std::invalid_argument(msg.str());
  }
  const double w_lo = 2.0 * std::numbers::pi / spec.wavelength_max_m;
  const double w_hi = 2.0 * std::numbers::pi / spec.wavelength_min_m;
  for (int c = 0; c < kIrregularityChannels; ++c) {
    const auto channel = IrregularityChannel(c);
    IrregularityChannelCheck& out = check.channels[size_t(c)];
    const std::vector<double> signal(irr.samples(channel).begin() + std::ptrdiff_t(first),
                                     irr.samples(channel).end());
    double sum2 = 0.0;
    for (double v : signal) sum2 += v * v;
    out.sample_rms_m = std::sqrt(sum2 / double(signal.size()));
    out.synthesised_rms_m = std::sqrt(irr.synthesised_variance_m2(channel));
    out.target_rms_m =
        spec.amplitude_scale * std::sqrt(irregularity_band_variance_m2(spec.spectrum, channel, w_lo, w_hi));
    out.welch = welch_psd(signal, ds, check.segment_samples);
    for (double w : out.welch.omega_rad_per_m)
      out.target_psd_m2_per_rad_per_m.push_back(
          w >= w_lo && w <= w_hi ? spec.amplitude_scale * spec.amplitude_scale *
                                       irregularity_psd_m2_per_rad_per_m(spec.spectrum, channel, w)
                                 : 0.0);
  }
  return check;
}

}  // namespace railstab
