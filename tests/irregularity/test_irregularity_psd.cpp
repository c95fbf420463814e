// The irregularity PSDs (irregularity/irregularity_psd.hpp) against GENSYS's
// published ORE B176 high-level table (an independent tabulation), and the
// closed-form band variance against numerical quadrature of the PSD.
#include <gtest/gtest.h>

#include <railstab/irregularity/irregularity_psd.hpp>

#include <cmath>
#include <numbers>

namespace railstab {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// GENSYS, program TRC_IPSD, block "ORE B176 high level" (www.gensys.se,
// doc_html/trc_ipsd.html): PSD in m^2/(1/m) at spatial frequency n (1/m),
// i.e. 2 pi S(Omega = 2 pi n) of our m^2/(rad/m).
TEST(IrregularityPsd, ErriHighLevelEqualsGensysTable) {
  struct Row {
    double n_per_m, lateral, vertical;
  };
  for (const Row& r : {Row{0.02, 2.3194e-4, 4.0897e-4}, Row{0.1, 6.1608e-6, 1.0863e-5},
                       Row{0.2, 7.3333e-7, 1.2931e-6}, Row{100.0, 1.6790e-17, 2.9605e-17}}) {
    const double w = kTwoPi * r.n_per_m;
    // Five significant digits in the table: 1e-4 relative.
    EXPECT_NEAR(kTwoPi * irregularity_psd_m2_per_rad_per_m(IrregularitySpectrum::erri_b176_high,
                                                           IrregularityChannel::alignment, w),
                r.lateral, 1e-4 * r.lateral)
        << "n = " << r.n_per_m;
    EXPECT_NEAR(kTwoPi * irregularity_psd_m2_per_rad_per_m(IrregularitySpectrum::erri_b176_high,
                                                           IrregularityChannel::level, w),
                r.vertical, 1e-4 * r.vertical)
        << "n = " << r.n_per_m;
  }
}

// Composite Simpson on a logarithmic grid (the PSDs span decades).
double simpson_log(IrregularitySpectrum s, IrregularityChannel c, double w1, double w2) {
  const int n = 20000;
  const double a = std::log(w1), b = std::log(w2), h = (b - a) / n;
  double sum = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double w = std::exp(a + i * h);
    const double f = irregularity_psd_m2_per_rad_per_m(s, c, w) * w;  // dW = W du
    sum += f * (i == 0 || i == n ? 1.0 : (i % 2 ? 4.0 : 2.0));
  }
  return sum * h / 3.0;
}

TEST(IrregularityPsd, BandVarianceIsTheIntegralOfThePsd) {
  const double w1 = kTwoPi / 150.0, w2 = kTwoPi / 3.0;
  for (const auto& [spectrum_name, spectrum] : kIrregularitySpectrumNames)
    for (const auto& [channel_name, channel] : kIrregularityChannelNames) {
      const double closed = irregularity_band_variance_m2(spectrum, channel, w1, w2);
      const double numeric = simpson_log(spectrum, channel, w1, w2);
      EXPECT_NEAR(closed, numeric, 1e-9 * std::abs(numeric) + 1e-20) << spectrum_name << " " << channel_name;
    }
  // Published magnitudes (3-150 m): ERRI B176 low alignment 2.08 mm, high
  // level 4.69 mm rms (independent quadrature of the same formulas).
  EXPECT_NEAR(std::sqrt(irregularity_band_variance_m2(IrregularitySpectrum::erri_b176_low,
                                                      IrregularityChannel::alignment, w1, w2)),
              2.08e-3, 0.01e-3);
  EXPECT_NEAR(std::sqrt(irregularity_band_variance_m2(IrregularitySpectrum::erri_b176_high,
                                                      IrregularityChannel::level, w1, w2)),
              4.69e-3, 0.01e-3);
  // FRA class 6 is better track than class 4.
  EXPECT_LT(irregularity_band_variance_m2(IrregularitySpectrum::fra_class_6, IrregularityChannel::level, w1, w2),
            irregularity_band_variance_m2(IrregularitySpectrum::fra_class_4, IrregularityChannel::level, w1, w2));
}

}  // namespace
}  // namespace railstab
