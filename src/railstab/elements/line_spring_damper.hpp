#pragma once
// line_spring_damper: a spring and a damper in parallel along the line
// between two points, each linear or a force characteristic from a table
// (elements/force_characteristic): e.g. a hydraulic damper with blow-off,
// a progressive rubber spring.
//   F = F_k(e) + F_c(de/dt) + F_pre,   e = l - l0    (tension > 0)
//   V = integral_0^e F_k + F_pre e
// l0: the length at the nominal configuration; F_pre: the preload that makes
// the nominal configuration the static equilibrium (solved by the builder).
#include <railstab/elements/element_ends.hpp>
#include <railstab/elements/force_characteristic.hpp>
#include <railstab/elements/line_motion.hpp>

#include <string>

namespace railstab {

template <class S> struct LineSpringDamper {
  static constexpr const char* kType = "line_spring_damper";
  static constexpr int kInternalStates = 0;
  static constexpr bool kInGravitySag = true;
  ElementEnds ends;
  ForceCharacteristic<S> spring;  // force against elongation
  ForceCharacteristic<S> damper;  // force against elongation rate
  S preload_N = S(0);             // solved by the builder
  double free_length_m = 0.0;     // l0, set by the builder

  void set_nominal(const Attachment<double>& a1, const Attachment<double>& a2) {
    free_length_m = value_of(line_motion(a1, ends.point1_m, a2, ends.point2_m).length_m);
  }
  template <class T>
  Vec3<T> elastic_load(const Attachment<T>& a1, const Attachment<T>& a2) const {
    const T e = line_motion(a1, ends.point1_m, a2, ends.point2_m).length_m - T(free_length_m);
    return Vec3<T>(spring.force(e), T(0), T(0));
  }
  void set_preload(const Vec3<S>& load) { preload_N = load.x(); }
  // The preload on each preloaded axis and the axis's stiffness, for the
  // model check's static deflections: f(axis, unit, preload, stiffness).
  template <class F> void for_each_preloaded_axis(F&& f) const {
    f("line", "m", value_of(preload_N), spring.slope_at_zero());
  }
  template <class F> void for_each_parameter(F&& f) {
    // A table characteristic is varied by its scale factor, a linear one by
    // its coefficient: each element has one parameter per characteristic.
    if (!spring.is_table) f("stiffness_N_per_m", -1, spring.coefficient);
    else f("spring_force_scale", -1, spring.scale);
    if (!damper.is_table) f("damping_N_s_per_m", -1, damper.coefficient);
    else f("damper_force_scale", -1, damper.scale);
  }

  template <class T>
  void apply(const Attachment<T>& a1, const Attachment<T>& a2, const T*, T*) const {
    const LineMotion<T> m = line_motion(a1, ends.point1_m, a2, ends.point2_m);
    const T e = m.length_m - T(free_length_m);
    const T tension = spring.force(e) + damper.force(m.rate_m_per_s) + lift<T>(preload_N);
    apply_line_tension(a1, a2, m, tension);
  }

  double potential(const Attachment<double>& a1, const Attachment<double>& a2,
                   const double*) const {
    const double e =
        value_of(line_motion(a1, ends.point1_m, a2, ends.point2_m).length_m) - free_length_m;
    return spring.integral(e) + value_of(preload_N) * e;
  }

  std::string internal_state_name(int) const { return {}; }

  template <class S2> LineSpringDamper<S2> cast() const {
    LineSpringDamper<S2> e;
    e.ends = ends;
    e.spring = spring.template cast<S2>();
    e.damper = damper.template cast<S2>();
    e.preload_N = lift<S2>(preload_N);
    e.free_length_m = free_length_m;
    return e;
  }
};

}  // namespace railstab
