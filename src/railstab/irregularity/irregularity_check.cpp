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
  check.has_target = !irr.measured();
  check.segment_samples = 8;
  while (check.segment_samples * ds < 2.0 * spec.wavelength_max_m) check.segment_samples *= 2;
  // Uniform samples between the fades (the synthesis grid itself when synthesised).
  const double from = irr.first_m() + spec.fade_in_m, to = irr.last_m() - spec.fade_out_m;
  std::vector<double> s;
  for (int i = 0; from + i * ds <= to; ++i) s.push_back(from + i * ds);
  // A measured record shorter than that gets the longest segment it holds
  // (at least 64 samples): its PSD is then resolved more coarsely.
  if (!check.has_target)
    while (check.segment_samples > 64 && s.size() < size_t(check.segment_samples)) check.segment_samples /= 2;
  if (s.size() < size_t(check.segment_samples)) {
    std::ostringstream msg;
    msg << "track.irregularities: expected at least fade_in_m + fade_out_m + "
        << check.segment_samples * ds << " m of irregular track (one Welch segment of 2 wavelength_max_m, "
        << "rounded up to a power of two of samples) to check the PSD, got " << irr.last_m() - irr.first_m()
        << " m";
    throw std::invalid_argument(msg.str());
  }
  const double w_lo = 2.0 * std::numbers::pi / spec.wavelength_max_m;
  const double w_hi = 2.0 * std::numbers::pi / spec.wavelength_min_m;
  for (int c = 0; c < kIrregularityChannels; ++c) {
    const auto channel = IrregularityChannel(c);
    IrregularityChannelCheck& out = check.channels[size_t(c)];
    std::vector<double> signal(s.size());
    for (size_t i = 0; i < s.size(); ++i) signal[i] = irr.at(channel, s[i]).f;
    double sum2 = 0.0;
    for (double v : signal) sum2 += v * v;
    out.sample_rms_m = std::sqrt(sum2 / double(signal.size()));
    out.welch = welch_psd(signal, ds, check.segment_samples);
    out.target_psd_m2_per_rad_per_m.assign(out.welch.omega_rad_per_m.size(), 0.0);
    if (!check.has_target) continue;
    out.synthesised_rms_m = std::sqrt(irr.synthesised_variance_m2(channel));
    out.target_rms_m =
        spec.amplitude_scale * std::sqrt(irregularity_band_variance_m2(spec.spectrum, channel, w_lo, w_hi));
    for (size_t k = 0; k < out.welch.omega_rad_per_m.size(); ++k) {
      const double w = out.welch.omega_rad_per_m[k];
      if (w >= w_lo && w <= w_hi)
        out.target_psd_m2_per_rad_per_m[k] = spec.amplitude_scale * spec.amplitude_scale *
                                             irregularity_psd_m2_per_rad_per_m(spec.spectrum, channel, w);
    }
  }
  return check;
}

}  // namespace railstab
