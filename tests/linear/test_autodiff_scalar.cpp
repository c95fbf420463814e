// The AD scalar differentiates a known function exactly (to round-off).
#include <railstab/core/scalar.hpp>

#include <gtest/gtest.h>

#include <cmath>

using namespace railstab;

// f(x, y) = sin(x) exp(y) + x^3 / y + atan2(y, x) sqrt(x y)
TEST(AutoDiff, KnownFunctionExactToRoundOff) {
  for (double x0 : {0.3, 1.7, 2.9})
    for (double y0 : {0.5, 1.1}) {
      AdScalar x(x0, AdDerivatives::Unit(0)), y(y0, AdDerivatives::Unit(1));
      using std::atan2;
      using std::exp;
      using std::sin;
      using std::sqrt;
      const AdScalar f = sin(x) * exp(y) + x * x * x / y + atan2(y, x) * sqrt(x * y);
      const double r2 = x0 * x0 + y0 * y0, s = std::sqrt(x0 * y0), a = std::atan2(y0, x0);
      const double dfdx = std::cos(x0) * std::exp(y0) + 3 * x0 * x0 / y0 + (-y0 / r2) * s +
                          a * 0.5 * y0 / s;
      const double dfdy = std::sin(x0) * std::exp(y0) - x0 * x0 * x0 / (y0 * y0) + (x0 / r2) * s +
                          a * 0.5 * x0 / s;
      EXPECT_NEAR(f.derivatives()(0), dfdx, 4e-15 * std::abs(dfdx));
      EXPECT_NEAR(f.derivatives()(1), dfdy, 4e-15 * std::abs(dfdy));
      EXPECT_EQ(f.derivatives().tail(kAdChunk - 2).norm(), 0.0);
    }
}
