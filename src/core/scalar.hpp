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

// The scalar of a model's parameters when the state scalar is T: double for
// double and AdScalar (derivatives with respect to the state only).
template <class T> struct ParameterScalarOf {
  using type = double;
};
template <class T> using ParameterScalar = typename ParameterScalarOf<T>::type;

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

// A model parameter of scalar S (double, or an AD type when parameters are
// differentiated) lifted into the evaluation scalar T: the same number, and
// no derivative with respect to the state directions of T.
template <class T, class S> inline T lift(const S& s) {
  if constexpr (std::is_same_v<T, S>) {
    return s;
  } else {
    return constant<T>(s);
  }
}
template <class T, class S> inline Vec3<T> lift(const Vec3<S>& v) {
  return Vec3<T>(lift<T>(v.x()), lift<T>(v.y()), lift<T>(v.z()));
}

// Plain values of a parameter vector (for reports, energy and preloads).
template <class S> inline Eigen::Vector3d value_of_each(const Vec3<S>& v) {
  return Eigen::Vector3d(value_of(v.x()), value_of(v.y()), value_of(v.z()));
}

}  // namespace railstab
