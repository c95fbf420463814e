// Synthesised irregularities (irregularity/track_irregularities.hpp): their
// variance against the PSD's band integral, their PSD (Welch, many seeds)
// against the target within the estimator's spread, reproducibility from
// the seed, the fade-in, and Welch's estimator against Parseval.
#include <gtest/gtest.h>

#include <railstab/irregularity/irregularity_check.hpp>
#include <railstab/irregularity/irregularity_psd.hpp>
#include <railstab/irregularity/track_irregularities.hpp>
#include <railstab/irregularity/welch_psd.hpp>

#include <cmath>
#include <numbers>

namespace railstab {
namespace {

IrregularitySpec test_spec(std::uint64_t seed) {
  IrregularitySpec spec;
  spec.spectrum = IrregularitySpectrum::erri_b176_low;
  spec.seed = seed;
  spec.length_m = 3072.0;
  spec.sample_interval_m = 0.5;
  spec.components = 500;
  spec.fade_in_m = 0.0;
  return spec;
}

TEST(IrregularitySynthesis, SynthesisedVarianceIsTheBandIntegral) {
  const TrackIrregularities irr(test_spec(7));
  const double w1 = 2.0 * std::numbers::pi / 150.0, w2 = 2.0 * std::numbers::pi / 3.0;
  for (const auto& [name, channel] : kIrregularityChannelNames) {
    const double target = irregularity_band_variance_m2(IrregularitySpectrum::erri_b176_low, channel, w1, w2);
    // Sum of S at one random point per band times the band width: the
    // quadrature error of 500 bands, well below 1 %.
    EXPECT_NEAR(irr.synthesised_variance_m2(channel), target, 0.01 * target) << name;
  }
}

TEST(IrregularitySynthesis, RmsAndWelchPsdOverManySeedsMatchTheTarget) {
  const int seeds = 16;
  std::array<double, kIrregularityChannels> mean_variance{};
  std::array<std::vector<double>, kIrregularityChannels> mean_psd;
  IrregularityCheck last;
  for (int seed = 1; seed <= seeds; ++seed) {
    const TrackIrregularities irr(test_spec(std::uint64_t(seed)));
    last = check_irregularities(irr);
    for (int c = 0; c < kIrregularityChannels; ++c) {
      const IrregularityChannelCheck& ch = last.channels[size_t(c)];
      mean_variance[size_t(c)] += ch.sample_rms_m * ch.sample_rms_m / seeds;
      if (mean_psd[size_t(c)].empty()) mean_psd[size_t(c)].assign(ch.welch.psd_m2_per_rad_per_m.size(), 0.0);
      for (size_t k = 0; k < mean_psd[size_t(c)].size(); ++k)
        mean_psd[size_t(c)][k] += ch.welch.psd_m2_per_rad_per_m[k] / seeds;
    }
  }
  const double w_lo = 2.0 * std::numbers::pi / 150.0, w_hi = 2.0 * std::numbers::pi / 3.0;
  for (int c = 0; c < kIrregularityChannels; ++c) {
    const IrregularityChannelCheck& ch = last.channels[size_t(c)];
    // rms: the sample variance of one 3 km realisation scatters by ~15 %
    // (the 150 m waves repeat only 20 times); the mean of 16 seeds by ~4 %.
    EXPECT_NEAR(mean_variance[size_t(c)], ch.target_rms_m * ch.target_rms_m,
                0.12 * ch.target_rms_m * ch.target_rms_m)
        << "channel " << c;
    // PSD in octaves from 2 w_lo to w_hi / 2: each octave averages >= 10
    // bins of 16 seeds x 11 Hann segments (50 % overlap): a spread of a few
    // per cent; 15 % allowed. The band's edges are left out (a segment's
    // resolution 2 pi / 512 m smears them).
    const std::vector<double>& w = ch.welch.omega_rad_per_m;
    for (double lo = 2.0 * w_lo; lo * 2.0 <= w_hi / 2.0; lo *= 2.0) {
      double estimate = 0.0, target = 0.0;
      int bins = 0;
      for (size_t k = 0; k < w.size(); ++k)
        if (w[k] >= lo && w[k] < 2.0 * lo) {
          estimate += mean_psd[size_t(c)][k];
          target += ch.target_psd_m2_per_rad_per_m[k];
          ++bins;
        }
      ASSERT_GE(bins, 4);
      EXPECT_NEAR(estimate / target, 1.0, 0.15) << "channel " << c << ", octave from " << lo << " rad/m";
    }
  }
}

TEST(IrregularitySynthesis, TheSeedReproducesTheTrackAndAnotherSeedChangesIt) {
  IrregularitySpec spec = test_spec(3);
  spec.length_m = 200.0;
  const TrackIrregularities a(spec), b(spec);
  spec.seed = 4;
  const TrackIrregularities c(spec);
  EXPECT_EQ(a.samples(IrregularityChannel::level), b.samples(IrregularityChannel::level));
  EXPECT_NE(a.samples(IrregularityChannel::level), c.samples(IrregularityChannel::level));
}

TEST(IrregularitySynthesis, FadesInFromZeroAndIsZeroOutsideItsStretch) {
  IrregularitySpec spec = test_spec(5);
  spec.start_m = 100.0;
  spec.length_m = 300.0;
  spec.fade_in_m = 20.0;
  const TrackIrregularities irr(spec);
  for (const auto& [name, channel] : kIrregularityChannelNames) {
    EXPECT_EQ(irr.at(channel, 99.0).f, 0.0);
    EXPECT_EQ(irr.at(channel, 401.0).f, 0.0);
    EXPECT_NEAR(irr.at(channel, 100.0).f, 0.0, 1e-15) << name;
    // The ramp (1 - cos)/2 has zero slope at the start: a run is not kicked.
    EXPECT_LT(std::abs(irr.at(channel, 100.5).f), 0.01 * std::sqrt(irr.synthesised_variance_m2(channel)) + 1e-12)
        << name;
  }
}

TEST(WelchPsd, SumOfPsdTimesBinWidthIsTheVariance) {
  // Parseval for a signal of two cosines (variance 0.5 + 0.125): the
  // estimate's sum over the bins equals it to the window's edge loss.
  std::vector<double> x(8192);
  const double ds = 0.5;
  for (size_t i = 0; i < x.size(); ++i)
    x[i] = std::cos(0.3 * i * ds + 0.1) + 0.5 * std::cos(1.7 * i * ds);
  const WelchPsd p = welch_psd(x, ds, 1024);
  const double dw = 2.0 * std::numbers::pi / (1024 * ds);
  double sum = 0.0;
  for (double s : p.psd_m2_per_rad_per_m) sum += s * dw;
  EXPECT_NEAR(sum, 0.625, 0.01 * 0.625);
  EXPECT_EQ(p.segments, 15);
}

}  // namespace
}  // namespace railstab
