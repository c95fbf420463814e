#pragma once
// bump_stop: a two-sided stop along one axis of body 1's attachment frame
// (e.g. the lateral bump stops between bogie and car body): free within the
// clearance c, then a progressive spring.
//   u = a . (d - d0)   relative displacement of point 2 from point 1 along
//                      the unit axis a (frame 1), from the nominal configuration
//   g+ = ramp(u - c),  g- = ramp(-u - c)           (penetrations of the stops)
//   P(g) = k g + k3 g^3                            (progressive stiffness)
//   f = a (P(g+) - P(g-))        (frame 1; applied as spring_damper_3d)
// ramp is max(0, s) made C1 over a width w (contact_smoothing_m):
//   ramp(s) = 0 (s <= -w),  (s + w)^2 / (4 w) (|s| < w),  s (s >= w),
// so the force is exact beyond c + w and Newton/AD see a continuous
// stiffness. Potential: V = W(u - c) + W(-u - c), W(s) = integral of P(ramp)
// (closed form below). No preload (at the nominal position a stop with
// clearance carries nothing).
#include <railstab/elements/axis_deflection.hpp>
#include <railstab/elements/element_ends.hpp>

#include <cmath>
#include <string>

namespace railstab {

template <class S> struct BumpStop {
  static constexpr const char* kType = "bump_stop";
  static constexpr int kInternalStates = 0;
  static constexpr bool kInGravitySag = true;
  ElementEnds ends;
  Eigen::Vector3d axis = Eigen::Vector3d::UnitY();  // unit, in frame 1
  S clearance_m = S(0);
  S stiffness_N_per_m = S(0);
  S progressive_stiffness_N_per_m3 = S(0);
  double contact_smoothing_m = 5e-4;
  Eigen::Vector3d free_vector_m = Eigen::Vector3d::Zero();  // d0, set by the builder

  void set_nominal(const Attachment<double>& a1, const Attachment<double>& a2) {
    free_vector_m = axis_deflection(a1, ends.point1_m, a2, ends.point2_m).d;
  }
  template <class T> Vec3<T> elastic_load(const Attachment<T>&, const Attachment<T>&) const {
    return Vec3<T>::Zero();
  }
  void set_preload(const Vec3<S>&) {}
  // No preload (it acts only beyond its clearance): no static deflection.
  template <class F> void for_each_preloaded_axis(F&&) const {}
  template <class F> void for_each_parameter(F&& f) {
    f("clearance_m", -1, clearance_m);
    f("stiffness_N_per_m", -1, stiffness_N_per_m);
    f("progressive_stiffness_N_per_m3", -1, progressive_stiffness_N_per_m3);
  }

  template <class T> T ramp(const T& s) const {
    const double w = contact_smoothing_m;
    const double sv = value_of(s);
    if (sv <= -w) return T(0);
    if (sv >= w) return s;
    return (s + T(w)) * (s + T(w)) / T(4.0 * w);
  }
  template <class T> T stop_force(const T& g) const {
    return lift<T>(stiffness_N_per_m) * g + lift<T>(progressive_stiffness_N_per_m3) * g * g * g;
  }
  // Force along the axis at relative displacement u (> 0 pushes back).
  template <class T> T axial_force(const T& u) const {
    const T c = lift<T>(clearance_m);
    return stop_force(ramp(T(u - c))) - stop_force(ramp(T(-u - c)));
  }

  template <class T>
  void apply(const Attachment<T>& a1, const Attachment<T>& a2, const T*, T*) const {
    const AxisDeflection<T> def = axis_deflection(a1, ends.point1_m, a2, ends.point2_m);
    const Vec3<T> a = to_scalar<T>(axis);
    const T u = a.dot(def.d - to_scalar<T>(free_vector_m));
    apply_axis_force(a1, a2, def, Vec3<T>(a * axial_force(u)));
  }

  // W(s) = integral from -inf to s of P(ramp(sigma)) d sigma.
  double stop_energy(double s) const {
    const double w = contact_smoothing_m, k = value_of(stiffness_N_per_m),
                 k3 = value_of(progressive_stiffness_N_per_m3);
    if (s <= -w) return 0.0;
    if (s < w) {
      const double v = s + w;
      return k * v * v * v / (12.0 * w) + k3 * std::pow(v, 7) / (448.0 * w * w * w);
    }
    return 2.0 * k * w * w / 3.0 + 2.0 * k3 * std::pow(w, 4) / 7.0 + 0.5 * k * (s * s - w * w) +
           0.25 * k3 * (std::pow(s, 4) - std::pow(w, 4));
  }

  double potential(const Attachment<double>& a1, const Attachment<double>& a2,
                   const double*) const {
    const double u =
        axis.dot(axis_deflection(a1, ends.point1_m, a2, ends.point2_m).d - free_vector_m);
    const double c = value_of(clearance_m);
    return stop_energy(u - c) + stop_energy(-u - c);
  }

  std::string internal_state_name(int) const { return {}; }

  template <class S2> BumpStop<S2> cast() const {
    BumpStop<S2> e;
    e.ends = ends;
    e.axis = axis;
    e.clearance_m = lift<S2>(clearance_m);
    e.stiffness_N_per_m = lift<S2>(stiffness_N_per_m);
    e.progressive_stiffness_N_per_m3 = lift<S2>(progressive_stiffness_N_per_m3);
    e.contact_smoothing_m = contact_smoothing_m;
    e.free_vector_m = free_vector_m;
    return e;
  }
};

}  // namespace railstab
