#pragma once
// The two scalar types every model equation is instantiated for.
//
// `double` serves simulation; `AdScalar` serves linearisation. AdScalar is
// Eigen's forward-mode AutoDiffScalar with a *fixed-size* derivative vector of
// kAdChunk directions, so no operation allocates (dynamic-size AutoDiff was
// measured ~30x slower, Drake issue 1199). A Jacobian with more columns than
// kAdChunk is assembled chunk by chunk (see linear/ad_jacobian.hpp).
#include <Eigen/Dense>
#include <unsupported/Eigen/AutoDiff>

#include <cmath>

namespace railstab {

inline constexpr int kAdChunk = 16;
using AdDerivatives = Eigen::Matrix<double, kAdChunk, 1>;
using AdScalar = Eigen::AutoDiffScalar<AdDerivatives>;

template <class T> using Vec3 = Eigen::Matrix<T, 3, 1>;
template <class T> using Mat3 = Eigen::Matrix<T, 3, 3>;
template <class T> using VecX = Eigen::Matrix<T, Eigen::Dynamic, 1>;

inline double value_of(double x) { return x; }
inline double value_of(const AdScalar& x) { return x.value(); }

// Convert a double into scalar T (an AD constant has zero derivatives).
template <class T> inline T constant(double x) {
  if constexpr (std::is_same_v<T, double>) {
    return x;
  } else {
    return T(x, AdDerivatives::Zero());
  }
}

template <class T> inline Vec3<T> to_scalar(const Eigen::Vector3d& v) {
  return Vec3<T>(constant<T>(v.x()), constant<T>(v.y()), constant<T>(v.z()));
}

}  // namespace railstab
