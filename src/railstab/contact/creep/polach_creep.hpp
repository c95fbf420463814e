#pragma once
// Polach's creep force method: the fast method for vehicle dynamics with spin
// (Polach 1999, "A fast wheel-rail forces calculation computer code", Vehicle
// System Dynamics 33 Suppl., 728-739) and its extension to large creepage with
// falling friction and reduction factors (Polach 2005, "Creep forces in
// simulations of traction vehicles running on adhesion limit", Wear 258,
// 992-1000). Formulas taken from the papers, written in the contact frame and
// signs of contact/wheel_rail.hpp (Polach's Q is N, his psi is phi).
//
//   Friction falling with the slip velocity w (2005):
//     mu = mu0 ((1 - A) exp(-B w) + A),   w = V s_C
//   Lateral creepage corrected for spin (1999):
//     s_yC = xi_y + phi a  if |xi_y + phi a| > |xi_y|,  else xi_y
//     s_C  = sqrt(xi_x^2 + s_yC^2)
//   Gradient of tangential stress in the adhesion area (1999, with
//   C = (3/8) (G/a) c_jj this is eps = (2/3) C pi a^2 b s_C / (mu N)):
//     eps = (pi / 4) |(r f11 xi_x, r f22 s_yC)| / (mu N)
//   Resultant from xi_x, xi_y (2005, k_S <= k_A <= 1):
//     F = (2 mu N / pi) (k_A eps / (1 + (k_A eps)^2) + atan(k_S eps))
//   Lateral force from spin (1999; Polach writes -(9/16) a Q f K_M ... psi/s_C
//   oriented like his F, along the creepage; on the wheel it is the negative):
//     F_yS = (9/16) a mu N K_M (1 + 6.3 (1 - exp(-a/b))) phi / s_C,
//     K_M = |eps_M| (d^3/3 - d^2/2 + 1/6) - (1/3) sqrt((1 - d^2)^3),
//     d = (eps_M^2 - 1) / (eps_M^2 + 1),
//     eps_M = (8/3) G b sqrt(ab) c23 s_C / (mu N (1 + 6.3 (1 - exp(-a/b))))
//           = (8/3) r f23 s_C / (a mu N K_S),  K_S = 1 + 6.3 (1 - exp(-a/b)).
//   Writing t = eps_M^2/(1 + eps_M^2), K_M / |eps_M| = -(2/3) (1 - t)^2 exactly,
//   so F_yS = -r f23 phi / (1 + eps_M^2)^2: a rational function of s_C^2.
//
// Force directions. Polach directs F along the creepage (xi_x, xi_y)/s_C and
// weights Kalker's coefficients by that direction (c_jj); with c11 != c22
// this makes F(xi) non-differentiable at xi = 0 (degree-one homogeneous, not
// linear). Here F is directed along Kalker's linear force instead, with the
// same magnitude:
//     Fx = -r f11 xi_x R,  Fy = -r f22 xi_y R + F_yS,
//     R = F / |(r f11 xi_x, r f22 s_yC)| = (1/2) (k_A/(1 + k_A^2 eps^2) + atan(k_S eps)/eps)
// which is Polach's exactly when c11 = c22 (then c_jj s_C = c11 s_C), or
// xi_x = 0, or s_yC = xi_y (no spin correction active); otherwise (c11 !=
// c22 with longitudinal creepage and the spin switch active, e.g. pure
// longitudinal creepage plus spin) the magnitude differs from Polach's
// c_jj s_C weighting (review 2026-11-30).
// Spin moment: not part of Polach's method. Mz = r (f23 xi_y - f33 phi) R/R0,
// R0 = R(0) = (k_A + k_S)/2: Kalker's moment with the saturation of the
// force, normalised so that its slope at zero creepage is Kalker's (a choice
// of this code).
//
// Small creepage: Fx -> -r f11 (k_A + k_S)/2 xi_x, Fy -> -r f22 (k_A + k_S)/2 xi_y
// - r f23 phi, Mz -> r (f23 xi_y - f33 phi): the 2005 factors k_A, k_S reduce
// the initial slope of the xi_x, xi_y forces to (k_A + k_S)/2 of Kalker's
// (that is their purpose); the 1999 spin force is not reduced by them.
// Large creepage (no spin): |F| -> mu N, and with A < 1 at high slip
// velocity -> A mu0 N.
//
// Smoothness for AD (R depends on eps^2 only, and eps^2, eps_M^2 are sums of
// squares: no sqrt of the creepage resultant enters the forces):
//  - atan(k_S eps)/eps is evaluated as a function of eps^2 (Taylor series
//    near 0, creep_detail::atan_root_over_root), exact to round-off.
//  - The spin switch |xi_y + phi a| > |xi_y| is s_yC^2 = max(xi_y^2,
//    (xi_y + phi a)^2), replaced by smooth_max with width
//    kSpinSwitchWidth = 1e-16 (creepage^2): s_yC^2 is low by at most 5e-17.
//  - w = V s_C is sqrt at zero: w = regularised_norm(V^2 s_C^2, w0)
//    = V^2 s_C^2 / sqrt(V^2 s_C^2 + w0^2) with w0 =
//    kSlipVelocityRegularisation_m_per_s = 1e-6 m/s: w is low by at most
//    w0^2 / (2 w) (5e-10 m/s at w = 1 mm/s), and below w ~ w0 the friction
//    is mu0 to first order, where it has no effect on the forces anyway
//    (mu enters only through eps^2 ~ 0).
//  Hence d(forces)/d(creepages) at zero creepage is exactly the limit above.
// Zero normal force gives zero forces (the limit N -> 0+ of all three).
#include <railstab/contact/creep/creep_input.hpp>

namespace railstab {

template <class S> struct PolachCreep {
  static constexpr const char* kName = "polach";  // creep_law in scene files and reports
  static constexpr double kSpinSwitchWidth = 1e-16;                // creepage^2
  static constexpr double kSlipVelocityRegularisation_m_per_s = 1e-6;

  // Defaults: the parameter set Polach 2005 recommends for dry rail
  // (k_A = 1.00, k_S = 0.40, mu0 = 0.55, A = 0.40, B = 0.60 s/m; for wet rail
  // 0.30, 0.10, 0.30, 0.40, 0.20 s/m). Values as widely cited from the paper
  // (the table itself not at hand; a review found them consistent with
  // secondary sources: Open Rails' PolachCalculator fits k_A = 2.8 mu - 0.54,
  // k_S = 1.2 mu - 0.26, B = 1.6 mu - 0.28, A = 0.4, which give exactly these
  // sets at mu0 = 0.55 and 0.30). The set belongs together: changing only
  // friction_coefficient (e.g. to 0.3) keeps the dry k_A, k_S, B, a mix not
  // in Polach's table. kalker_reduction_factor < 1 reduces the initial slope
  // on top of k_A, k_S (twice); Polach's method has only k_A, k_S for that.
  // A, k_A, k_S and the reduction factor are dimensionless.
  S friction_coefficient{0.55};            // mu0, at zero slip velocity; > 0
  S limit_friction_ratio{0.40};            // A = mu_inf / mu0, in (0, 1]; 1: constant mu
  S friction_decrease_rate_s_per_m{0.60};  // B, >= 0
  S adhesion_reduction_factor{1.00};       // k_A, in (0, 1]
  S slip_reduction_factor{0.40};           // k_S, in (0, k_A]
  S kalker_reduction_factor{1.0};          // r on f11..f33, in (0, 1]; Polach's C reduction

  void validate() const;  // std::invalid_argument naming the field
  // Needs semi_axis_a_m, semi_axis_b_m > 0 when normal_force_N > 0.
  template <class T> CreepForces<T> forces(const CreepInput<T>& in) const;
  // f(scene key, -1, value&) for each parameter (sensitivity keys
  // contacts.<name>.<scene key>; the scene keys of scene_reading/creep_law_reader).
  template <class F> void for_each_parameter(F&& f) {
    f("friction_coefficient", -1, friction_coefficient);
    f("kalker_reduction_factor", -1, kalker_reduction_factor);
    f("polach_limit_friction_ratio", -1, limit_friction_ratio);
    f("polach_friction_decrease_s_per_m", -1, friction_decrease_rate_s_per_m);
    f("polach_adhesion_reduction_factor", -1, adhesion_reduction_factor);
    f("polach_slip_reduction_factor", -1, slip_reduction_factor);
  }
  template <class S2> PolachCreep<S2> cast() const {
    return PolachCreep<S2>{cast_parameter<S2>(friction_coefficient),
                           cast_parameter<S2>(limit_friction_ratio),
                           cast_parameter<S2>(friction_decrease_rate_s_per_m),
                           cast_parameter<S2>(adhesion_reduction_factor),
                           cast_parameter<S2>(slip_reduction_factor),
                           cast_parameter<S2>(kalker_reduction_factor)};
  }
};

}  // namespace railstab
