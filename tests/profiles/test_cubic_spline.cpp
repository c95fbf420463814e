// The natural cubic spline's interval lookup (a bucket grid and a walk,
// profiles/cubic_spline.cpp) against the plain binary search it replaces,
// and the value-only evaluation against evaluate().f, bit for bit: both are
// on the contact tables' path and must not change a number.
#include <gtest/gtest.h>

#include <railstab/profiles/cubic_spline.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using railstab::CubicSpline;

namespace {

// The largest i with x_i <= x, clamped to [0, n-2] (the reference).
size_t reference_interval(const std::vector<double>& x, double at) {
  if (at <= x.front()) return 0;
  if (at >= x.back()) return x.size() - 2;
  return size_t(std::upper_bound(x.begin(), x.end(), at) - x.begin()) - 1;
}

}  // namespace

TEST(CubicSplineLookup, IntervalEqualsTheBinarySearchOnUnevenKnots) {
  // Knots crowded at one end (as a flange's), sparse at the other, and a
  // cluster closer than a bucket: the walk must cross several knots.
  std::vector<double> x, f;
  for (int i = 0; i < 40; ++i) x.push_back(-0.07 + 1e-4 * i * i);
  for (int i = 1; i < 8; ++i) x.push_back(x.back() + 1e-7 * i);
  for (int i = 1; i < 30; ++i) x.push_back(x.back() + 3e-3);
  for (double xi : x) f.push_back(std::sin(40.0 * xi) * 1e-3);
  const CubicSpline s(x, f);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(x.front() - 0.01, x.back() + 0.01);
  int checked = 0;
  for (int k = 0; k < 20000; ++k) {
    const double at = uniform(random);
    ASSERT_EQ(s.interval(at), reference_interval(x, at)) << "x = " << at;
    ++checked;
  }
  // Exactly at every knot (where x_i <= x decides) and just beside it.
  for (double xi : x)
    for (double at : {xi, std::nextafter(xi, -1.0), std::nextafter(xi, 1.0)})
      ASSERT_EQ(s.interval(at), reference_interval(x, at)) << "x = " << at;
  EXPECT_EQ(checked, 20000);
}

TEST(CubicSplineLookup, ValueAloneIsEvaluatesValueToTheLastBit) {
  std::vector<double> x, f;
  for (int i = 0; i < 200; ++i) {
    x.push_back(-0.05 + 5e-4 * i + 1e-5 * std::sin(double(i)));
    f.push_back(1e-2 * std::cos(60.0 * x.back()));
  }
  const CubicSpline s(x, f);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> uniform(x.front() - 0.02, x.back() + 0.02);
  for (int k = 0; k < 20000; ++k) {
    const double at = uniform(random);
    ASSERT_EQ(s(at), s.evaluate(at).f) << "x = " << at;  // bitwise: no tolerance
  }
}
