// The EN 14363 signal processing (signals/) against signals with a known
// answer: a Butterworth band-pass's -3 dB edges, unit centre gain and
// order-dependent fall-off; the sliding rms and mean of sinusoids.
#include <gtest/gtest.h>

#include <railstab/signals/band_pass.hpp>
#include <railstab/signals/sliding_window.hpp>

#include <cmath>
#include <numbers>

namespace railstab {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(BandPass, CentreGainOneEdgesMinusThreeDecibelsAndButterworthFallOff) {
  const double T = 0.005;  // 200 Hz sampling
  for (int order : {1, 2, 3, 4, 6}) {
    const BandPassFilter f = butterworth_band_pass(T, 3.0, 7.0, order);
    EXPECT_EQ(int(f.sections.size()), order);
    EXPECT_NEAR(band_pass_gain(f, std::sqrt(21.0)), 1.0, 1e-5) << order;  // near the centre
    EXPECT_NEAR(band_pass_gain(f, 3.0), 1.0 / std::sqrt(2.0), 1e-9) << order;
    EXPECT_NEAR(band_pass_gain(f, 7.0), 1.0 / std::sqrt(2.0), 1e-9) << order;
    // Analog Butterworth band-pass, |H|^2 = 1 / (1 + ((w^2 - w0^2)/(B w))^(2N))
    // in the prewarped frequencies (the bilinear map is exact on them).
    auto warped = [&](double hz) { return 2.0 / T * std::tan(kPi * hz * T); };
    const double w0_sq = warped(3.0) * warped(7.0), B = warped(7.0) - warped(3.0);
    for (double hz : {1.0, 2.0, 4.0, 6.0, 10.0, 20.0}) {
      const double w = warped(hz), u = (w * w - w0_sq) / (B * w);
      EXPECT_NEAR(band_pass_gain(f, hz), 1.0 / std::sqrt(1.0 + std::pow(u * u, order)), 1e-9)
          << order << " at " << hz << " Hz";
    }
  }
  // A very wide band (real poles) still has the order's sections.
  EXPECT_EQ(butterworth_band_pass(0.005, 0.2, 40.0, 3).sections.size(), 3u);
  EXPECT_NEAR(band_pass_gain(butterworth_band_pass(0.005, 0.2, 40.0, 3), 0.2), 1.0 / std::sqrt(2.0), 1e-9);
  EXPECT_THROW(butterworth_band_pass(0.005, 7.0, 3.0, 4), std::invalid_argument);
  EXPECT_THROW(butterworth_band_pass(0.005, 3.0, 120.0, 4), std::invalid_argument);
}

TEST(BandPass, FilteredSinusoidsKeepTheirRmsTimesTheGain) {
  const double T = 0.005;
  const BandPassFilter f = butterworth_band_pass(T, 3.0, 7.0, 4);
  for (double hz : {4.58, 3.0, 9.0}) {
    std::vector<double> x(20000);
    for (size_t i = 0; i < x.size(); ++i) x[i] = 2.0 * std::sin(2.0 * kPi * hz * i * T);
    const std::vector<double> y = filter_signal(f, x);
    double sum = 0.0;
    for (size_t i = 10000; i < y.size(); ++i) sum += y[i] * y[i];  // past the start transient
    EXPECT_NEAR(std::sqrt(sum / 10000.0), std::sqrt(2.0) * band_pass_gain(f, hz), 2e-3) << hz;
  }
}

TEST(SlidingWindow, RmsAndMeanOfKnownSignals) {
  // 100 m windows, 10 m steps, over 1 km sampled every 0.5 m; a sinusoid
  // of 20 m wavelength (5 periods per window) has rms A / sqrt(2) exactly.
  std::vector<double> s, x, y;
  for (int i = 0; i <= 2000; ++i) {
    s.push_back(0.5 * i);
    x.push_back(3.0 * std::cos(2.0 * kPi * s.back() / 20.0 + 0.3));
    y.push_back(1.5 + (s.back() < 500.0 ? 0.0 : 1.0));
  }
  const std::vector<WindowValue> rms = sliding_rms(s, x, 100.0, 10.0);
  ASSERT_EQ(rms.size(), 91u);  // windows starting at 0, 10, ..., 900 m
  for (const WindowValue& w : rms) {
    EXPECT_EQ(w.samples, 200);
    EXPECT_NEAR(w.value, 3.0 / std::sqrt(2.0), 1e-12);
  }
  const std::vector<WindowValue> mean = sliding_mean(s, y, 2.0, 0.5);
  for (const WindowValue& w : mean) {
    if (w.end_m <= 500.0) EXPECT_DOUBLE_EQ(w.value, 1.5);
    else if (w.start_m >= 500.0) EXPECT_DOUBLE_EQ(w.value, 2.5);
    else  // straddling the step: the fraction of the window past 500 m
      EXPECT_NEAR(w.value, 1.5 + (w.end_m - 500.0) / 2.0, 1e-12) << w.start_m;
  }
  EXPECT_THROW(sliding_rms(s, x, 0.0, 10.0), std::invalid_argument);
}

}  // namespace
}  // namespace railstab
