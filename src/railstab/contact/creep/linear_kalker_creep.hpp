#pragma once
// Kalker's linear creep law, with a reduction factor on the coefficients
// (the form of contact/wheel_rail.hpp, kept available beside the saturating
// laws):
//   Fx = -r f11 xi_x,  Fy = -r (f22 xi_y + f23 phi),  Mz = r (f23 xi_y - f33 phi)
// Linear, hence smooth; no friction limit. The normal force, ellipse and
// speed in CreepInput are not used.
#include <railstab/contact/creep/creep_input.hpp>

namespace railstab {

template <class S> struct LinearKalkerCreep {
  static constexpr const char* kName = "linear_kalker";  // creep_law in scene files and reports
  // r: multiplies f11, f22, f23, f33; dimensionless, in (0, 1]. Default 1
  // (Kalker's theory as is; values ~0.5-0.8 are used for real, contaminated
  // surfaces).
  S kalker_reduction_factor{1.0};

  void validate() const;  // std::invalid_argument naming the field
  template <class T> CreepForces<T> forces(const CreepInput<T>& in) const;
  // f(scene key, -1, value&) for each parameter (sensitivity keys
  // contacts.<name>.<scene key>).
  template <class F> void for_each_parameter(F&& f) {
    f("kalker_reduction_factor", -1, kalker_reduction_factor);
  }
  template <class S2> LinearKalkerCreep<S2> cast() const {
    return LinearKalkerCreep<S2>{cast_parameter<S2>(kalker_reduction_factor)};
  }
};

}  // namespace railstab
