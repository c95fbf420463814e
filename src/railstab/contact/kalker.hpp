#pragma once
// Kalker's linear creep coefficients (thesis table B.1, ERRATA 9).
//
// Table B.1 gives c11, c22, c23, c33 at a/b = 0.1..0.9, 1, then b/a = 0.9..0.1
// (a: semi-axis in the rolling direction, b: lateral) for nu = 0, 0.25, 0.5.
// The interpolation is C1 (cubic spline in the ratio, quadratic in nu) so AD
// can differentiate through it, and it reproduces the table at its nodes.
//   f11 = G a b c11,  f22 = G a b c22,  f23 = G (ab)^(3/2) c23,  f33 = G (ab)^2 c33
//   Fx = -f11 xi_x,  Fy = -f22 xi_y - f23 xi_sp,  Mz = f23 xi_y - f33 xi_sp
#include <railstab/core/scalar.hpp>

namespace railstab {

template <class T> struct KalkerTableValues {
  T c11, c22, c23, c33;
};

template <class T> struct CreepCoefficients {
  T f11_N, f22_N, f23_N_m, f33_N_m2;
};

// Interpolated table values; a_over_b must lie in [0.1, 10] (throws
// std::domain_error otherwise), poisson ratio in [0, 0.5].
template <class T> KalkerTableValues<T> kalker_table(const T& a_over_b, double poisson_ratio);

template <class T> CreepCoefficients<T> kalker_coefficients(const T& a_m, const T& b_m,
                                                           double shear_modulus_Pa,
                                                           double poisson_ratio);

extern template KalkerTableValues<double> kalker_table(const double&, double);
extern template KalkerTableValues<AdScalar> kalker_table(const AdScalar&, double);
extern template KalkerTableValues<ParamDual> kalker_table(const ParamDual&, double);
extern template KalkerTableValues<ParamAdScalar> kalker_table(const ParamAdScalar&, double);
extern template CreepCoefficients<ParamDual> kalker_coefficients(const ParamDual&, const ParamDual&,
                                                          double, double);
extern template CreepCoefficients<ParamAdScalar> kalker_coefficients(const ParamAdScalar&,
                                                              const ParamAdScalar&, double,
                                                              double);
extern template CreepCoefficients<double> kalker_coefficients(const double&, const double&,
                                                              double, double);
extern template CreepCoefficients<AdScalar> kalker_coefficients(const AdScalar&,
                                                                const AdScalar&, double,
                                                                double);

}  // namespace railstab
