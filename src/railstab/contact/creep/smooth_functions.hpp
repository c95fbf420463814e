#pragma once
// Smooth replacements for the non-smooth pieces of the saturating creep laws,
// so that AD derivatives exist everywhere and are continuous.
//
// AD rules they rely on: d sqrt(x) = dx / (2 sqrt(x)) is 0/0 at x = 0, so a
// norm is never taken of an exactly-zero square; instead
//   regularised_norm(x, d) = x / sqrt(x + d^2) = sqrt(x) / sqrt(1 + d^2/x)
// is C-infinity in x >= 0, increasing, exactly 0 at x = 0 with derivative
// 1/d there, and lies in [sqrt(x) - d^2/(2 sqrt(x)), sqrt(x)]: for
// sqrt(x) >> d it equals sqrt(x) to round-off (with d = 1e-9 and
// sqrt(x) >= 1e-2 the relative error is < 1e-14). Applied to a sum of squares
// x = |v|^2 its derivative in v at v = 0 is (1/d) 2 v = 0, so a law
// F = v g(|v|) sees dF/dv = g(0) there: the linear slope, exactly.
#include <railstab/core/scalar.hpp>

#include <cmath>

namespace railstab::creep_detail {

template <class T> T regularised_norm(const T& x, double d) {
  using std::sqrt;
  return T(x / sqrt(T(x + d * d)));
}

// Smooth maximum of p, q >= 0 with transition width w (units of p):
//   smooth_max = (p + q + sqrt((p - q)^2 + w^2) - w) / 2
// lies in [max(p, q) - w/2, max(p, q)], is >= (p + q)/2 >= 0, equals 0 at
// p = q = 0, and is C-infinity.
template <class T> T smooth_max(const T& p, const T& q, double w) {
  using std::sqrt;
  const T d = p - q;
  return T(0.5 * (p + q + sqrt(T(d * d + w * w)) - w));
}

// atan(sqrt(x)) / sqrt(x) for x >= 0, as a smooth function of x (it is even
// in sqrt(x)): Taylor series sum_n (-x)^n / (2n + 1) below x = 0.01 (terms to
// n = 8, truncation < 0.01^9 / 19 ~ 5e-20), the closed form above.
template <class T> T atan_root_over_root(const T& x) {
  using std::atan2;
  using std::sqrt;
  if (value_of(x) < 1e-2) {
    // Horner: 1 - x/3 + x^2/5 - ... + x^8/17
    T sum = constant<T>(1.0 / 17.0);
    for (int n = 7; n >= 0; --n) sum = T(1.0 / (2.0 * n + 1.0) - x * sum);
    return sum;
  }
  const T r = sqrt(x);
  // atan(r) as atan2(r, 1): Eigen's AutoDiff has atan2 but no atan overload.
  return T(atan2(r, constant<T>(1.0)) / r);
}

}  // namespace railstab::creep_detail
