#pragma once
// series_spring_damper: a damper in series with a spring along the line
// between two points: a hydraulic yaw or lateral damper with the stiffness
// of its rubber end mounts (and oil column) in series.
//
// With e = l - l0 the elongation of the whole element (l0: its length at the
// nominal configuration) and e_d the elongation of the damper alone (an
// internal state of the model), the same tension F passes through both:
//   F = k_s (e - e_d)              (series spring)
//   F = F_d(de_d/dt)               (damper: linear c v, or a table)
//   =>  de_d/dt = F_d^-1(k_s (e - e_d))
// (a table F_d = a P(v) with its scale a: de_d/dt = P^-1(k_s (e - e_d) / a))
// For a linear damper the element's complex stiffness at s is
//   K(s) = k_s c s / (k_s + c s):  a damper at low frequency, the spring
// at high frequency. With a table, the damper's velocity is interpolated
// against force (the inverse table), so the rate of the internal state is
// explicit; the table must have force strictly increasing with velocity.
// Potential: 1/2 k_s (e - e_d)^2 (the series spring); the damper dissipates
// F de_d/dt >= 0. No preload: in a static equilibrium the damper carries no
// force, so neither does the spring.
#include <railstab/elements/element_ends.hpp>
#include <railstab/elements/force_characteristic.hpp>
#include <railstab/elements/line_motion.hpp>

#include <string>

namespace railstab {

template <class S> struct SeriesSpringDamper {
  static constexpr const char* kType = "series_spring_damper";
  static constexpr int kInternalStates = 1;  // e_d, the damper elongation (m)
  // Takes no part in the gravity sag: at any equilibrium the damper, and so
  // the series spring, carries no force (dz/dt = 0 <=> F = 0).
  static constexpr bool kInGravitySag = false;
  ElementEnds ends;
  S series_stiffness_N_per_m = S(0);
  ForceCharacteristic<S> damper;           // force against damper velocity
  ForceCharacteristic<S> damper_velocity;  // its inverse: velocity against force
  double free_length_m = 0.0;              // l0, set by the builder

  void set_damper(const ForceCharacteristic<S>& d) {
    damper = d;
    damper_velocity = d.inverse();
  }
  void set_nominal(const Attachment<double>& a1, const Attachment<double>& a2) {
    free_length_m = value_of(line_motion(a1, ends.point1_m, a2, ends.point2_m).length_m);
  }
  template <class T> Vec3<T> elastic_load(const Attachment<T>&, const Attachment<T>&) const {
    return Vec3<T>::Zero();
  }
  void set_preload(const Vec3<S>&) {}
  // No preload (a damper carries no static load): no static deflection.
  template <class F> void for_each_preloaded_axis(F&&) const {}
  template <class F> void for_each_parameter(F&& f) {
    f("series_stiffness_N_per_m", -1, series_stiffness_N_per_m);
    if (!damper.is_table) {
      f("damping_N_s_per_m", -1, damper.coefficient);
      damper_velocity.coefficient = S(1.0) / damper.coefficient;  // keep the inverse consistent
    } else {
      f("damper_force_scale", -1, damper.scale);  // the inverse divides by it (apply)
    }
  }

  template <class T>
  void apply(const Attachment<T>& a1, const Attachment<T>& a2, const T* z, T* zdot) const {
    const LineMotion<T> m = line_motion(a1, ends.point1_m, a2, ends.point2_m);
    const T tension = lift<T>(series_stiffness_N_per_m) * (m.length_m - T(free_length_m) - z[0]);
    // A table's inverse is of P alone: v = P^-1(F / a); a linear damper's
    // scale is 1.
    zdot[0] = damper_velocity.force(T(tension / lift<T>(damper.scale)));
    apply_line_tension(a1, a2, m, tension);
  }

  double potential(const Attachment<double>& a1, const Attachment<double>& a2,
                   const double* z) const {
    const double e =
        value_of(line_motion(a1, ends.point1_m, a2, ends.point2_m).length_m) - free_length_m;
    return 0.5 * value_of(series_stiffness_N_per_m) * (e - z[0]) * (e - z[0]);
  }

  std::string internal_state_name(int) const { return "damper_elongation_m"; }

  template <class S2> SeriesSpringDamper<S2> cast() const {
    SeriesSpringDamper<S2> e;
    e.ends = ends;
    e.series_stiffness_N_per_m = lift<S2>(series_stiffness_N_per_m);
    e.damper = damper.template cast<S2>();
    e.damper_velocity = damper_velocity.template cast<S2>();
    e.free_length_m = free_length_m;
    return e;
  }
};

}  // namespace railstab
