#pragma once
// Dual<U>: forward-mode derivative along ONE parameter direction on top of a
// scalar U (double, or AdScalar for derivatives along the state as well):
//   x = v + d eps,  eps^2 = 0.
// Every operation implements its first-order rule on (v, d) with U's own
// arithmetic, so Dual<AdScalar> carries the mixed second derivatives
// d^2 f / (dx dp) that the derivative of the state matrix A = df/dx with
// respect to a parameter p needs. (Eigen's nested AutoDiffScalar lacks atan
// and pow(AD<AD>, double) with GCC 12, hence this small type.)
//   f(v + d eps) = f(v) + f'(v) d eps
// Comparisons and branches use the plain value (value_of), as for AdScalar.
#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include <cmath>
#include <type_traits>

namespace railstab {

template <class U> struct Dual {
  U v{}, d{};
  Dual() : v(0.0), d(0.0) {}
  Dual(double x) : v(x), d(0.0) {}  // NOLINT: constants convert implicitly, as for AdScalar
  template <class V, class = std::enable_if_t<!std::is_same_v<U, double> && std::is_same_v<V, U>>>
  Dual(const V& x) : v(x), d(0.0) {}  // NOLINT
  Dual(const U& value, const U& derivative) : v(value), d(derivative) {}

  Dual& operator+=(const Dual& o) { v += o.v; d += o.d; return *this; }
  Dual& operator-=(const Dual& o) { v -= o.v; d -= o.d; return *this; }
  Dual& operator*=(const Dual& o) { d = d * o.v + v * o.d; v *= o.v; return *this; }
  Dual& operator/=(const Dual& o) {
    d = (d * o.v - v * o.d) / (o.v * o.v);
    v /= o.v;
    return *this;
  }
};

template <class U> inline Dual<U> operator+(Dual<U> a, const Dual<U>& b) { return a += b; }
template <class U> inline Dual<U> operator-(Dual<U> a, const Dual<U>& b) { return a -= b; }
template <class U> inline Dual<U> operator*(Dual<U> a, const Dual<U>& b) { return a *= b; }
template <class U> inline Dual<U> operator/(Dual<U> a, const Dual<U>& b) { return a /= b; }
template <class U> inline Dual<U> operator-(const Dual<U>& a) { return Dual<U>(-a.v, -a.d); }
template <class U> inline Dual<U> operator+(const Dual<U>& a) { return a; }
// Mixed with plain doubles (constants of the model equations).
template <class U> inline Dual<U> operator+(const Dual<U>& a, double b) { return Dual<U>(a.v + b, a.d); }
template <class U> inline Dual<U> operator+(double b, const Dual<U>& a) { return Dual<U>(a.v + b, a.d); }
template <class U> inline Dual<U> operator-(const Dual<U>& a, double b) { return Dual<U>(a.v - b, a.d); }
template <class U> inline Dual<U> operator-(double b, const Dual<U>& a) { return Dual<U>(b - a.v, -a.d); }
template <class U> inline Dual<U> operator*(const Dual<U>& a, double b) { return Dual<U>(a.v * b, a.d * b); }
template <class U> inline Dual<U> operator*(double b, const Dual<U>& a) { return Dual<U>(a.v * b, a.d * b); }
template <class U> inline Dual<U> operator/(const Dual<U>& a, double b) { return Dual<U>(a.v / b, a.d / b); }
template <class U> inline Dual<U> operator/(double b, const Dual<U>& a) {
  return Dual<U>(b / a.v, -b * a.d / (a.v * a.v));
}

inline double dual_value(double x) { return x; }
template <class D> inline double dual_value(const Eigen::AutoDiffScalar<D>& x) { return x.value(); }
template <class U> inline double dual_value(const Dual<U>& x) { return dual_value(x.v); }

template <class U> inline bool operator<(const Dual<U>& a, const Dual<U>& b) { return dual_value(a) < dual_value(b); }
template <class U> inline bool operator>(const Dual<U>& a, const Dual<U>& b) { return dual_value(a) > dual_value(b); }
template <class U> inline bool operator<=(const Dual<U>& a, const Dual<U>& b) { return dual_value(a) <= dual_value(b); }
template <class U> inline bool operator>=(const Dual<U>& a, const Dual<U>& b) { return dual_value(a) >= dual_value(b); }
template <class U> inline bool operator==(const Dual<U>& a, const Dual<U>& b) { return dual_value(a) == dual_value(b); }
template <class U> inline bool operator!=(const Dual<U>& a, const Dual<U>& b) { return dual_value(a) != dual_value(b); }

// Elementary functions: f(v) + f'(v) d eps.
template <class U> inline Dual<U> sqrt(const Dual<U>& a) {
  using std::sqrt;
  const U s = sqrt(a.v);
  return Dual<U>(s, a.d / (2.0 * s));
}
template <class U> inline Dual<U> sin(const Dual<U>& a) {
  using std::cos;
  using std::sin;
  return Dual<U>(sin(a.v), cos(a.v) * a.d);
}
template <class U> inline Dual<U> cos(const Dual<U>& a) {
  using std::cos;
  using std::sin;
  return Dual<U>(cos(a.v), -sin(a.v) * a.d);
}
template <class U> inline Dual<U> tan(const Dual<U>& a) {
  using std::tan;
  const U t = tan(a.v);
  return Dual<U>(t, (1.0 + t * t) * a.d);
}
template <class U> inline Dual<U> exp(const Dual<U>& a) {
  using std::exp;
  const U e = exp(a.v);
  return Dual<U>(e, e * a.d);
}
template <class U> inline Dual<U> log(const Dual<U>& a) {
  using std::log;
  return Dual<U>(log(a.v), a.d / a.v);
}
template <class U> inline Dual<U> pow(const Dual<U>& a, double n) {
  using std::pow;
  return Dual<U>(pow(a.v, n), n * pow(a.v, n - 1.0) * a.d);
}
template <class U> inline Dual<U> atan(const Dual<U>& a) {
  using std::atan;
  return Dual<U>(atan(a.v), a.d / (1.0 + a.v * a.v));
}
template <class U> inline Dual<U> atan2(const Dual<U>& y, const Dual<U>& x) {
  using std::atan2;
  return Dual<U>(atan2(y.v, x.v), (x.v * y.d - y.v * x.d) / (x.v * x.v + y.v * y.v));
}
template <class U> inline Dual<U> abs(const Dual<U>& a) { return dual_value(a) < 0.0 ? -a : a; }
template <class U> inline Dual<U> expm1(const Dual<U>& a) {
  using std::exp;
  return Dual<U>(exp(a.v) - 1.0, exp(a.v) * a.d);
}

}  // namespace railstab

namespace Eigen {
template <class U> struct NumTraits<railstab::Dual<U>> : NumTraits<double> {
  using Real = railstab::Dual<U>;
  using NonInteger = railstab::Dual<U>;
  using Nested = railstab::Dual<U>;
  using Literal = double;
  enum { IsComplex = 0, IsInteger = 0, IsSigned = 1, RequireInitialization = 1,
         ReadCost = 2, AddCost = 4, MulCost = 8 };
};
template <class U, typename BinaryOp>
struct ScalarBinaryOpTraits<railstab::Dual<U>, double, BinaryOp> {
  using ReturnType = railstab::Dual<U>;
};
template <class U, typename BinaryOp>
struct ScalarBinaryOpTraits<double, railstab::Dual<U>, BinaryOp> {
  using ReturnType = railstab::Dual<U>;
};
}  // namespace Eigen
