// The run summary's extremes (ride/ride_history.hpp): EN 14363's 2 m means
// of Sum Y and Y/Q against a signal whose mean over 2 m is known.
#include <gtest/gtest.h>

#include <railstab/ride/ride_history.hpp>

#include <cmath>
#include <numbers>

namespace railstab {
namespace {

// Sum Y = c + A sin(2 pi s / 2 m) sampled every 0.1 m: every 2 m window
// holds 20 samples over exactly one period, so its mean is c.
RideHistory synthetic_history(double spacing_m) {
  RideHistory h;
  h.static_loads.push_back({0, 60e3, 60e3});
  for (int i = 0; i <= 400; ++i) {
    const double s = spacing_m * i;
    h.times_s.push_back(s / 50.0);
    h.distance_m.push_back(s);
    WheelsetForces f;
    f.sum_y_N = 12e3 + 30e3 * std::sin(std::numbers::pi * s);
    f.left.y_over_q = 0.1 + 0.5 * std::sin(std::numbers::pi * s);
    f.right.y_over_q = -0.1;
    h.wheelsets.push_back({f});
  }
  return h;
}

TEST(RideExtremes, TwoMetreMeansRemoveWhatAveragesOutOverTwoMetres) {
  const std::vector<WheelsetExtremes> e = wheelset_extremes(synthetic_history(0.1));
  ASSERT_EQ(e.size(), 1u);
  EXPECT_NEAR(e[0].max_abs_sum_y_N, 42e3, 1.0);  // the peak of the samples
  ASSERT_TRUE(e[0].max_abs_sum_y_2m_N);
  EXPECT_NEAR(*e[0].max_abs_sum_y_2m_N, 12e3, 1e-6);
  ASSERT_TRUE(e[0].max_y_over_q_2m);
  EXPECT_NEAR(*e[0].max_y_over_q_2m, 0.1, 1e-12);
  EXPECT_NEAR(*e[0].max_y_over_q_left, 0.6, 1e-3);
  EXPECT_NEAR(e[0].prudhomme_limit_N, 10e3 + 120e3 / 3.0, 1e-9);
}

TEST(RideExtremes, NoTwoMetreMeanFromSamplesTooSparse) {
  // 1.5 m between outputs: a 2 m window holds one sample.
  const std::vector<WheelsetExtremes> e = wheelset_extremes(synthetic_history(1.5));
  EXPECT_FALSE(e[0].max_abs_sum_y_2m_N);
  EXPECT_FALSE(e[0].max_y_over_q_2m);
}

}  // namespace
}  // namespace railstab
