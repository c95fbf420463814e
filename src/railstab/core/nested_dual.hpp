#pragma once
// Dual3 = Dual<Dual<Dual<double>>>: forward mode along THREE directions at
// once, nested (core/dual.hpp), for exact second and third directional
// derivatives of the model equations (nonlinear/multilinear_forms.hpp):
//
//   x = x0 + e1 u + e2 v + e3 w,   e1^2 = e2^2 = e3^2 = 0,
//   f(x) = f + e1 f'u + e2 f'v + e3 f'w
//            + e1 e2 f''(u,v) + e1 e3 f''(u,w) + e2 e3 f''(v,w)
//            + e1 e2 e3 f'''(u,v,w)                                  (exact).
//
// e1 is the innermost Dual's direction, e3 the outermost: the coefficient
// of e1 e2 e3 is x.d.d.d, of e1 e2 x.v.d.d, of e1 x.v.v.d. Every Dual
// operation implements its first-order rule with the inner type's
// arithmetic, so the nesting multiplies out to the truncated multivariate
// Taylor expansion above (no truncation error, no step size).
//
// The model parameters stay double for Dual3 (ParameterScalar<Dual3> is the
// default, double): the derivatives are along the state only.
#include <railstab/core/dual.hpp>

#include <type_traits>

namespace railstab {

using Dual1 = Dual<double>;
using Dual2 = Dual<Dual1>;
using Dual3 = Dual<Dual2>;

// How many Dual layers wrap the scalar (double and AdScalar: 0; Dual3: 3):
// the derivative order an iterative rule must make exact for T (e.g. the
// Hertz root's chord steps, contact/hertz.cpp: one exact order per step).
template <class T> struct DualDepth : std::integral_constant<int, 0> {};
template <class U> struct DualDepth<Dual<U>> : std::integral_constant<int, 1 + DualDepth<U>::value> {};

// The seed x0 + e1 u + e2 v + e3 w (one component).
inline Dual3 seed_dual3(double x0, double u, double v, double w) {
  return Dual3(Dual2(Dual1(x0, u), Dual1(v, 0.0)), Dual2(Dual1(w, 0.0), Dual1(0.0, 0.0)));
}
// Coefficients of f(x0 + e1 u + e2 v + e3 w).
inline double dual3_first_u(const Dual3& y) { return y.v.v.d; }         // f' u
inline double dual3_second_uv(const Dual3& y) { return y.v.d.d; }       // f''(u, v)
inline double dual3_third_uvw(const Dual3& y) { return y.d.d.d; }       // f'''(u, v, w)

}  // namespace railstab
