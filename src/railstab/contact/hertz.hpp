#pragma once
// Hertz normal contact from complete elliptic integrals (ERRATA 7-8),
// templated on the scalar so AD differentiates through it.
//
// Relative curvatures (Johnson, Contact Mechanics, 4.2): A in the rolling
// direction x, B in the transverse direction y,
//   A = (1/R_wheel_x + 1/R_rail_x) / 2,  B = (1/R_wheel_y + 1/R_rail_y) / 2.
// The ellipse semi-axes are a (along x) and b (along y). With e the
// eccentricity of the ellipse (major semi-axis m, minor n, e^2 = 1 - n^2/m^2),
// the ratio of the curvatures fixes e:
//   B/A = [(m/n)^2 E(e) - K(e)] / [K(e) - E(e)]   (major axis along the smaller curvature)
// and the load-approach law is F = K_H delta^(3/2) with
//   K_H = (2 pi / 3) E* sqrt(E(e)) / (k sqrt(A + B) K(e)^(3/2)),  k = n/m.
// E* = 1 / ((1 - nu1^2)/E1 + (1 - nu2^2)/E2).
#include <railstab/core/scalar.hpp>

namespace railstab {

struct ElasticPair {
  double effective_modulus_Pa;  // E*
  double shear_modulus_Pa;      // combined G: 2/G = 1/G1 + 1/G2
  double poisson_ratio;         // combined nu = (G/2) (nu1/G1 + nu2/G2)
};
ElasticPair combine_materials(double young1_Pa, double poisson1, double young2_Pa,
                              double poisson2);

// Shape of the contact ellipse: depends on A and B only.
template <class T> struct HertzShape {
  T a_over_b;       // semi-axis along x over semi-axis along y
  T stiffness;      // K_H in F = K_H delta^(3/2), N/m^(3/2)
  T approach_per_force_23;  // delta = approach_per_force_23 * F^(2/3)
  T semi_axis_a_per_force_13;  // a = this * F^(1/3)
  T semi_axis_b_per_force_13;  // b = this * F^(1/3)
};

template <class T> HertzShape<T> hertz_shape(const T& A_per_m, const T& B_per_m,
                                             double effective_modulus_Pa);

// Complete elliptic integrals of the first and second kind of modulus k,
// differentiable: dK/dk = E/(k(1-k^2)) - K/k, dE/dk = (E - K)/k.
template <class T> T elliptic_K(const T& k);
template <class T> T elliptic_E(const T& k);

extern template HertzShape<double> hertz_shape(const double&, const double&, double);
extern template HertzShape<AdScalar> hertz_shape(const AdScalar&, const AdScalar&, double);
extern template HertzShape<ParamDual> hertz_shape(const ParamDual&, const ParamDual&, double);
extern template HertzShape<ParamAdScalar> hertz_shape(const ParamAdScalar&,
                                                      const ParamAdScalar&, double);
extern template double elliptic_K(const double&);
extern template AdScalar elliptic_K(const AdScalar&);
extern template double elliptic_E(const double&);
extern template AdScalar elliptic_E(const AdScalar&);

}  // namespace railstab
