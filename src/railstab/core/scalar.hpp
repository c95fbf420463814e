#pragma once
// The two scalar types every model equation is instantiated for.
//
// `double` serves simulation; `AdScalar` serves linearisation. AdScalar is
// Eigen's forward-mode AutoDiffScalar with a *fixed-size* derivative vector of
// kAdChunk directions, so no operation allocates (dynamic-size AutoDiff was
// measured ~30x slower, Drake issue 1199). A Jacobian with more columns than
// kAdChunk is assembled chunk by chunk (see linear/jacobian.hpp).
#include <Eigen/Dense>
#include <unsupported/Eigen/AutoDiff>

#include <railstab/core/dual.hpp>

#include <cmath>

namespace railstab {

// 24 by measurement (analysis/bench_jacobian.cpp, issue 11): an AD evaluation
// of the thesis vehicle costs ~92 us + ~2.1 us per direction, so its 44
// colours take 2 evaluations of 24 (24 residuals) instead of 3 of 16 (32),
// and its equilibrium's 23 colours 1 instead of 2. 48 (1 evaluation) was
// 10 % faster for the whole Jacobian but doubled the equilibrium's.
inline constexpr int kAdChunk = 24;
using AdDerivatives = Eigen::Matrix<double, kAdChunk, 1>;
using AdScalar = Eigen::AutoDiffScalar<AdDerivatives>;

// Parameter sensitivities (sensitivity/parameter_derivative.hpp): one parameter
// direction on top of the plain value (ParamDual) or of the state AD scalar
// (ParamAdScalar: d/dp of the state Jacobian).
using ParamDual = Dual<double>;
using ParamAdScalar = Dual<AdScalar>;

// The scalar of a model's parameters when the state scalar is T: double for
// double and AdScalar (derivatives with respect to the state only), ParamDual
// for the two parameter-derivative scalars.
template <class T> struct ParameterScalarOf {
  using type = double;
};
template <> struct ParameterScalarOf<ParamDual> {
  using type = ParamDual;
};
template <> struct ParameterScalarOf<ParamAdScalar> {
  using type = ParamDual;
};
template <class T> using ParameterScalar = typename ParameterScalarOf<T>::type;

template <class T> using Vec3 = Eigen::Matrix<T, 3, 1>;
template <class T> using Mat3 = Eigen::Matrix<T, 3, 3>;
template <class T> using VecX = Eigen::Matrix<T, Eigen::Dynamic, 1>;
// A read-only view of a VecX (or a contiguous segment), with Eigen::Ref's
// stride spelled out: the default stride argument is an expression of T,
// and clang 14 numbers the substitutions in the mangled names of function
// templates taking Ref<const VecX<T>> differently in the defining and the
// using translation units (explicit instantiations then fail to link).
template <class T> using VecXConstRef = Eigen::Ref<const VecX<T>, 0, Eigen::InnerStride<1>>;

inline double value_of(double x) { return x; }
inline double value_of(const AdScalar& x) { return x.value(); }
template <class U> inline double value_of(const Dual<U>& x) { return value_of(x.v); }

template <class T> struct IsDual : std::false_type {};
template <class U> struct IsDual<Dual<U>> : std::true_type {};

// A value with a derivative along the Dual's direction (the speed, when the
// model is differentiated in V): Dual<U>(v, d); plain and state-AD scalars
// carry no such direction and keep the value.
template <class T> inline T seeded_scalar(double value, double derivative) {
  if constexpr (IsDual<T>::value) {
    using U = decltype(T{}.v);
    return T(U(value), U(derivative));
  } else {
    (void)derivative;
    return T(value);
  }
}
template <class T>
inline Eigen::Matrix<T, 3, 1> seeded_vector(const Eigen::Vector3d& value, const Eigen::Vector3d* derivative) {
  Eigen::Matrix<T, 3, 1> out;
  for (int i = 0; i < 3; ++i) out(i) = seeded_scalar<T>(value(i), derivative ? (*derivative)(i) : 0.0);
  return out;
}

// Convert a double into scalar T (an AD constant has zero derivatives).
template <class T> inline T constant(double x) {
  if constexpr (std::is_same_v<T, double>) {
    return x;
  } else if constexpr (IsDual<T>::value) {
    return T(x);
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
  } else if constexpr (std::is_same_v<S, double>) {
    return constant<T>(s);
  } else if constexpr (std::is_same_v<T, double>) {
    return value_of(s);  // dropping the parameter derivative (reports, preload values)
  } else {
    // ParamDual -> ParamAdScalar: value and parameter derivative, no state derivative.
    static_assert(std::is_same_v<S, ParamDual> && std::is_same_v<T, ParamAdScalar>);
    return T(constant<AdScalar>(s.v), constant<AdScalar>(s.d));
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
