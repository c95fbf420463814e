// Crests, troughs, the peak-to-peak envelope and the settled-oscillation
// test of integrate/oscillation.hpp on signals known in closed form.
#include <railstab/integrate/oscillation.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace railstab;

namespace {

struct Sampled {
  std::vector<double> t, y;
};

// y = mean + A exp(sigma t) sin(2 pi t / T + phase), every h seconds.
Sampled sinusoid(double A, double T, double sigma, double t_end, double h, double mean = 0.0) {
  Sampled s;
  for (int i = 0; i * h <= t_end + 1e-12; ++i) {
    const double t = i * h;
    s.t.push_back(t);
    s.y.push_back(mean + A * std::exp(sigma * t) * std::sin(2.0 * std::numbers::pi * t / T + 0.3));
  }
  return s;
}

}  // namespace

TEST(Oscillation, ParabolicExtremaOfASampledSinusoid) {
  // 0.7 s period sampled every 0.01 s (70 samples a period): the vertex of
  // the parabola through three samples misses the crest by A (pi h / T)^4 / 8
  // ~ 5e-7 A at most (the sinusoid's Taylor series), the raw samples by up to
  // A (1 - cos(pi h / T)) ~ 1e-3 A.
  const double A = 2e-3, T = 0.7;
  const Sampled s = sinusoid(A, T, 0.0, 7.0, 0.01, 0.01);
  const std::vector<Extremum> e = find_extrema(s.t, s.y);
  ASSERT_GE(e.size(), 19u);
  for (const Extremum& x : e) EXPECT_NEAR(std::abs(x.value - 0.01), A, 2e-6 * A);
  for (size_t k = 1; k < e.size(); ++k) {
    EXPECT_NE(e[k].crest, e[k - 1].crest);
    EXPECT_NEAR(e[k].time_s - e[k - 1].time_s, T / 2.0, 1e-4 * T);
  }
  for (const EnvelopePoint& p : peak_to_peak_envelope(e)) EXPECT_NEAR(p.peak_to_peak, 2.0 * A, 4e-6 * A);
  const SettledOscillation c = settled_oscillation(s.t, s.y);
  EXPECT_TRUE(c.settled) << c.reason;
  EXPECT_NEAR(c.amplitude, A, 2e-6 * A);
  EXPECT_NEAR(c.period_s, T, 1e-5 * T);
}

TEST(Oscillation, DecayingOrTinyMotionIsNotSettled) {
  // Decaying at 0.05 1/s over 5 periods of 0.7 s: amplitudes spread by
  // 1 - exp(-0.05 * 4 * 0.7) = 13 %, beyond the 1 % tolerance.
  const Sampled decaying = sinusoid(2e-3, 0.7, -0.05, 10.0, 0.01);
  const SettledOscillation d = settled_oscillation(decaying.t, decaying.y);
  EXPECT_FALSE(d.settled);
  EXPECT_NEAR(d.amplitude_spread, 1.0 - std::exp(-0.05 * 4 * 0.7), 0.01);
  EXPECT_NE(d.reason.find("amplitude varies"), std::string::npos) << d.reason;
  // 1e-7 m: below the 1 um floor, noise on a steady state.
  const Sampled tiny = sinusoid(1e-7, 0.7, 0.0, 10.0, 0.01);
  EXPECT_FALSE(settled_oscillation(tiny.t, tiny.y).settled);
  // Three periods only.
  const Sampled shortrun = sinusoid(2e-3, 0.7, 0.0, 2.2, 0.01);
  const SettledOscillation sh = settled_oscillation(shortrun.t, shortrun.y);
  EXPECT_FALSE(sh.settled);
  EXPECT_EQ(sh.cycles_found, 2);
}
