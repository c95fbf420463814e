#pragma once
// Common interface of the creep laws in this folder (issue 9, part 3).
//
// A creep law maps the creepages of one wheel-rail contact to the tangential
// creep forces and the spin moment on the wheel, in the contact frame of
// contact/wheel_rail.hpp (l rolling direction, t lateral, nu normal from the
// rail into the wheel), with the signs of Kalker's linear theory used there:
//   Fx = -f11 xi_x,  Fy = -f22 xi_y - f23 phi,  Mz = f23 xi_y - f33 phi
// (xi_x, xi_y dimensionless, spin phi in 1/m). Every law reduces to these at
// small creepage, up to its stated reduction factors.
//
// Scalars: the evaluation scalar T is double or AdScalar. The parameter
// scalar S of a law (its struct) is double or AdScalar; S = AdScalar requires
// T = AdScalar (parameter sensitivities), lifted with lift<T>(s).
#include <railstab/core/scalar.hpp>

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <type_traits>

namespace railstab {

template <class T> struct CreepInput {
  T creep_x{0.0};              // xi_x = v_slip.l / V, dimensionless
  T creep_y{0.0};              // xi_y = v_slip.t / V, dimensionless
  T creep_spin_per_m{0.0};     // phi = w_wheel.nu / V, 1/m
  T normal_force_N{0.0};       // N (Polach's Q), >= 0
  T semi_axis_a_m{0.0};        // contact ellipse, along the rolling direction
  T semi_axis_b_m{0.0};        // contact ellipse, lateral
  T f11_N{0.0}, f22_N{0.0};    // Kalker's linear coefficients (contact/kalker.hpp)
  T f23_N_m{0.0}, f33_N_m2{0.0};
  T speed_m_per_s{0.0};        // V > 0 normalises the creepages; slip velocity = V |xi|
};

template <class T> struct CreepForces {
  T force_x_N{0.0};        // on the wheel, along l
  T force_y_N{0.0};        // on the wheel, along t
  T spin_moment_N_m{0.0};  // on the wheel, about nu
};

// Parameter scalar S into evaluation scalar T: lift<T>(s) (core/scalar.hpp).

// Parameter conversion for cast<S2>(): to double keeps the value (drops the
// derivatives), to AdScalar a double becomes a constant.
template <class S2, class S> S2 cast_parameter(const S& s) {
  if constexpr (std::is_same_v<S2, S>) {
    return s;
  } else if constexpr (std::is_same_v<S2, double>) {
    return value_of(s);
  } else {
    return constant<S2>(s);
  }
}

namespace creep_detail {

inline void require_finite(double x, const char* law, const char* field) {
  if (!std::isfinite(x)) {
    std::ostringstream msg;
    msg << law << ": input " << field << " must be finite, got " << x;
    throw std::domain_error(msg.str());
  }
}

inline void require_parameter(bool ok, const char* law, const char* field, double value,
                              const char* expected) {
  if (!ok) {
    std::ostringstream msg;
    msg << law << ": parameter " << field << " = " << value << " is invalid, expected "
        << expected;
    throw std::invalid_argument(msg.str());
  }
}

// Every input finite, the normal force and the Kalker coefficients >= 0.
template <class T> void require_valid_input(const CreepInput<T>& in, const char* law) {
  require_finite(value_of(in.creep_x), law, "creep_x");
  require_finite(value_of(in.creep_y), law, "creep_y");
  require_finite(value_of(in.creep_spin_per_m), law, "creep_spin_per_m");
  require_finite(value_of(in.normal_force_N), law, "normal_force_N");
  require_finite(value_of(in.semi_axis_a_m), law, "semi_axis_a_m");
  require_finite(value_of(in.semi_axis_b_m), law, "semi_axis_b_m");
  require_finite(value_of(in.f11_N), law, "f11_N");
  require_finite(value_of(in.f22_N), law, "f22_N");
  require_finite(value_of(in.f23_N_m), law, "f23_N_m");
  require_finite(value_of(in.f33_N_m2), law, "f33_N_m2");
  require_finite(value_of(in.speed_m_per_s), law, "speed_m_per_s");
  const auto nonnegative = [&](double x, const char* field) {
    if (x < 0.0) {
      std::ostringstream msg;
      msg << law << ": input " << field << " must be >= 0, got " << x;
      throw std::domain_error(msg.str());
    }
  };
  nonnegative(value_of(in.normal_force_N), "normal_force_N");
  nonnegative(value_of(in.f11_N), "f11_N");
  nonnegative(value_of(in.f22_N), "f22_N");
  nonnegative(value_of(in.f33_N_m2), "f33_N_m2");
  nonnegative(value_of(in.speed_m_per_s), "speed_m_per_s");
}

// Kalker's linear forces with all coefficients scaled by r.
template <class T>
CreepForces<T> linear_kalker_forces(const CreepInput<T>& in, const T& r) {
  CreepForces<T> out;
  out.force_x_N = -r * in.f11_N * in.creep_x;
  out.force_y_N = -r * (in.f22_N * in.creep_y + in.f23_N_m * in.creep_spin_per_m);
  out.spin_moment_N_m = r * (in.f23_N_m * in.creep_y - in.f33_N_m2 * in.creep_spin_per_m);
  return out;
}

template <class T> CreepForces<T> zero_forces() {
  return CreepForces<T>{constant<T>(0.0), constant<T>(0.0), constant<T>(0.0)};
}

}  // namespace creep_detail
}  // namespace railstab
