#pragma once
// Shen, Hedrick & Elkins (1983, "A comparison of alternative creep force
// models for rail vehicle dynamic analysis", Proc. 8th IAVSD Symposium):
// Kalker's linear forces scaled so that their resultant saturates at mu N.
//
//   Linear (reduced) forces: Fx_L = -r f11 xi_x,  Fy_L = -r (f22 xi_y + f23 phi),
//                            Mz_L = r (f23 xi_y - f33 phi)
//   u = |(Fx_L, Fy_L)| / (mu N)
//   resultant F_R = mu N g(u),  g(u) = u - u^2/3 + u^3/27 = 1 - (1 - u/3)^3  (u < 3)
//                                g(u) = 1                                 (u >= 3)
//   (g is the Johnson-Vermeulen cubic.) With e(u) = g(u)/u,
//   Fx = e Fx_L,  Fy = e Fy_L,  Mz = e Mz_L.
// Force direction: that of Kalker's linear force (spin included in Fy_L).
// Spin moment: SHE saturate the force resultant only; Mz is scaled by the
// same factor e (the common reading of SHE), which keeps it bounded: a choice
// of this code, stated here.
//
// Smoothness for AD:
//  - e(u) = 1 - u/3 + u^2/27 (u < 3), 1/u (u >= 3): value, first and second
//    derivative agree at u = 3 (1/3, -1/9, 2/27), so F is C2 across the
//    saturation point (tested); the third derivative jumps.
//  - u = |F_L| / (mu N) has the sqrt-at-zero problem. It is replaced by
//    u_r = u^2 / sqrt(u^2 + d^2) (creep_detail::regularised_norm) with
//    d = kResultantRegularisation = 1e-9 (dimensionless, in units of mu N):
//    F = e(u_r) F_L is C-infinity at F_L = 0 and its derivative there is
//    exactly r times Kalker's coefficients (e(0) = 1). u - d^2/(2u) <= u_r <= u,
//    so |F| differs from the unregularised law by at most mu N d^2/6 (~2e-19
//    mu N) and is exactly mu N to round-off once saturated; u_r departs from
//    u (first-order term u/3 of e replaced by u_r/3 ~ u^2/(3d)) only below
//    u ~ d, i.e. |F_L| < 1e-9 mu N.
//    Without regularisation F = F_L - |F_L| F_L / (3 mu N) + ... has a
//    continuous first derivative but a direction-dependent second one at 0.
// Zero normal force gives zero forces (the limit of mu N g -> 0).
#include <railstab/contact/creep/creep_input.hpp>

namespace railstab {

template <class S> struct ShenHedrickElkinsCreep {
  static constexpr const char* kName = "shen_hedrick_elkins";  // creep_law in scene files and reports
  static constexpr double kResultantRegularisation = 1e-9;  // d above, dimensionless

  // mu: dimensionless, > 0. Default 0.4, the dry-rail value commonly used in
  // vehicle dynamics simulation (wet ~0.2-0.3).
  S friction_coefficient{0.4};
  // r on f11, f22, f23, f33: dimensionless, in (0, 1]. Default 1.
  S kalker_reduction_factor{1.0};

  void validate() const;  // std::invalid_argument naming the field
  template <class T> CreepForces<T> forces(const CreepInput<T>& in) const;
  // f(scene key, -1, value&) for each parameter (sensitivity keys
  // contacts.<name>.<scene key>).
  template <class F> void for_each_parameter(F&& f) {
    f("friction_coefficient", -1, friction_coefficient);
    f("kalker_reduction_factor", -1, kalker_reduction_factor);
  }
  template <class S2> ShenHedrickElkinsCreep<S2> cast() const {
    return ShenHedrickElkinsCreep<S2>{cast_parameter<S2>(friction_coefficient),
                                      cast_parameter<S2>(kalker_reduction_factor)};
  }
};

}  // namespace railstab
