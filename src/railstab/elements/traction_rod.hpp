#pragma once
// traction_rod: a stiff link along the line between two points (bogie to car
// body traction rods, wheelset guidance links), its stiffness that of the
// rubber bushes at its ends:
//   F = k (l - l0) + c dl/dt + F_pre        (tension > 0),   V = 1/2 k e^2 + F_pre e
// It transmits force only along its line: across it the two ends are free
// (to first order), which is what distinguishes it from a 3-axis bush.
//
// In the static sag of the preload solve (setup/build_model.hpp, ERRATA 13)
// the rod is linearised about its nominal line, n0 = (r2 - r1)/|r2 - r1| at
// the nominal configuration, held fixed in W (the sag's twin stands on
// straight, level track):
//   e = n0 . (r2 - r1) - l0,   F = k e + c n0 . (v2 - v1),   force +F n0 on
//   body 1, -F n0 on body 2,   V = 1/2 k e^2
// so the rod takes the share of the static load that its line carries to
// first order in the sag: an inclined rod or a hanger its part of the weight,
// a rod across the sag (a horizontal traction rod between a bogie and a car
// body sagging 0.18 m on air springs) none. Measured along its actual line
// instead, such a rod fought the sag through the second-order change of its
// length and got an 83 kN preload along its tilted line, which balanced
// nothing at nominal (the car body settled 1.05 mm low). The scene's model
// uses the exact line law above; the preload from the sag is its F_pre.
#include <railstab/elements/element_ends.hpp>
#include <railstab/elements/line_motion.hpp>

#include <string>

namespace railstab {

template <class S> struct TractionRod {
  static constexpr const char* kType = "traction_rod";
  static constexpr int kInternalStates = 0;
  // Takes part in the gravity sag linearised about its nominal line (above).
  static constexpr bool kInGravitySag = true;
  ElementEnds ends;
  S stiffness_N_per_m = S(0);
  S damping_N_s_per_m = S(0);
  S preload_N = S(0);          // solved by the builder
  double free_length_m = 0.0;  // l0, set by the builder
  // The nominal line n0 in W, set by the builder with l0; used only where
  // linearised_about_nominal_line (the preload solve's twin sets it).
  Eigen::Vector3d nominal_unit_W = Eigen::Vector3d::UnitX();
  bool linearised_about_nominal_line = false;

  void set_nominal(const Attachment<double>& a1, const Attachment<double>& a2) {
    const LineMotion<double> m = line_motion(a1, ends.point1_m, a2, ends.point2_m);
    free_length_m = m.length_m;
    nominal_unit_W = m.unit_W;
  }
  // Elongation e and its rate: along the actual line, or along n0 when
  // linearised.
  template <class T> struct Stretch {
    LineMotion<T> line;
    T elongation_m, rate_m_per_s;
    Vec3<T> unit_W;
  };
  template <class T> Stretch<T> stretch(const Attachment<T>& a1, const Attachment<T>& a2) const {
    Stretch<T> s{line_motion(a1, ends.point1_m, a2, ends.point2_m), T(0), T(0), Vec3<T>::Zero()};
    if (!linearised_about_nominal_line) {
      s.elongation_m = s.line.length_m - T(free_length_m);
      s.rate_m_per_s = s.line.rate_m_per_s;
      s.unit_W = s.line.unit_W;
      return s;
    }
    s.unit_W = to_scalar<T>(nominal_unit_W);
    s.elongation_m = s.unit_W.dot(Vec3<T>(s.line.p2.p_W - s.line.p1.p_W)) - T(free_length_m);
    s.rate_m_per_s = s.unit_W.dot(Vec3<T>(s.line.p2.v_W - s.line.p1.v_W));
    return s;
  }
  template <class T>
  Vec3<T> elastic_load(const Attachment<T>& a1, const Attachment<T>& a2) const {
    return Vec3<T>(lift<T>(stiffness_N_per_m) * stretch(a1, a2).elongation_m, T(0), T(0));
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
    const Stretch<T> s = stretch(a1, a2);
    const T tension = lift<T>(stiffness_N_per_m) * s.elongation_m +
                      lift<T>(damping_N_s_per_m) * s.rate_m_per_s + lift<T>(preload_N);
    const Vec3<T> f_W = tension * s.unit_W;
    a1.apply_force(s.line.p1.arm_W, f_W);
    a2.apply_force(s.line.p2.arm_W, Vec3<T>(-f_W));
  }

  double potential(const Attachment<double>& a1, const Attachment<double>& a2,
                   const double*) const {
    const double e = stretch(a1, a2).elongation_m;
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
    e.nominal_unit_W = nominal_unit_W;
    e.linearised_about_nominal_line = linearised_about_nominal_line;
    return e;
  }
};

}  // namespace railstab
