#pragma once
// traction_rod: a stiff link along the line between two points (bogie to car
// body traction rods, wheelset guidance links), its stiffness that of the
// rubber bushes at its ends:
//   F = k (l - l0) + c dl/dt + F_pre        (tension > 0),   V = 1/2 k e^2 + F_pre e
// It transmits force only along its line: across it the two ends are free
// (to first order), which is what distinguishes it from a 3-axis bush.
#include <railstab/elements/element_ends.hpp>
#include <railstab/elements/line_motion.hpp>

#include <string>

namespace railstab {

template <class S> struct TractionRod {
  static constexpr const char* kType = "traction_rod";
  static constexpr int kInternalStates = 0;
  // Takes no part in the gravity sag: a traction rod is adjusted to its
  // length with the vehicle loaded, i.e. at the nominal configuration, and
  // carries no static load (a rod fighting the sag of a soft secondary
  // would otherwise get a large preload along its sagged, tilted line that
  // no longer balances anything at nominal).
  static constexpr bool kInGravitySag = false;
  ElementEnds ends;
  S stiffness_N_per_m = S(0);
  S damping_N_s_per_m = S(0);
  S preload_N = S(0);          // solved by the builder
  double free_length_m = 0.0;  // l0, set by the builder

  void set_nominal(const Attachment<double>& a1, const Attachment<double>& a2) {
    free_length_m = value_of(line_motion(a1, ends.point1_m, a2, ends.point2_m).length_m);
  }
  template <class T>
  Vec3<T> elastic_load(const Attachment<T>& a1, const Attachment<T>& a2) const {
    const T e = line_motion(a1, ends.point1_m, a2, ends.point2_m).length_m - T(free_length_m);
    return Vec3<T>(lift<T>(stiffness_N_per_m) * e, T(0), T(0));
  }
  void set_preload(const Vec3<S>& load) { preload_N = load.x(); }
  // The preload on each preloaded axis and the axis's stiffness, for the
  // model check's static deflections: f(axis, unit, preload, stiffness).
  template <class F> void for_each_preloaded_axis(F&& f) const {
    f("line", "m", value_of(preload_N), value_of(stiffness_N_per_m));
  }
  template <class F> void for_each_parameter(F&& f) {
    f("stiffness_N_per_m", -1, stiffness_N_per_m);
    f("damping_N_s_per_m", -1, damping_N_s_per_m);
  }

  template <class T>
  void apply(const Attachment<T>& a1, const Attachment<T>& a2, const T*, T*) const {
    const LineMotion<T> m = line_motion(a1, ends.point1_m, a2, ends.point2_m);
    const T tension = lift<T>(stiffness_N_per_m) * (m.length_m - T(free_length_m)) +
                      lift<T>(damping_N_s_per_m) * m.rate_m_per_s + lift<T>(preload_N);
    apply_line_tension(a1, a2, m, tension);
  }

  double potential(const Attachment<double>& a1, const Attachment<double>& a2,
                   const double*) const {
    const double e =
        value_of(line_motion(a1, ends.point1_m, a2, ends.point2_m).length_m) - free_length_m;
    return 0.5 * value_of(stiffness_N_per_m) * e * e + value_of(preload_N) * e;
  }

  std::string internal_state_name(int) const { return {}; }

  template <class S2> TractionRod<S2> cast() const {
    TractionRod<S2> e;
    e.ends = ends;
    e.stiffness_N_per_m = lift<S2>(stiffness_N_per_m);
    e.damping_N_s_per_m = lift<S2>(damping_N_s_per_m);
    e.preload_N = lift<S2>(preload_N);
    e.free_length_m = free_length_m;
    return e;
  }
};

}  // namespace railstab
