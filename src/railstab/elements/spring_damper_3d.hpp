#pragma once
// spring_damper_3d: linear springs and dampers along the three axes of
// body 1's attachment frame (thesis 4.82-4.95: primary and secondary
// suspension). With d the deflection in frame 1 (elements/axis_deflection):
//   f = K (d - d0) + C dd/dt + f_act + f_pre          (components in frame 1)
//   V = 1/2 (d - d0)^T K (d - d0) + (f_act + f_pre)^T (d - d0)
// d0: the deflection at the nominal configuration (free vector, builder);
// f_pre: the preload that makes the nominal configuration the static
// equilibrium under gravity (ERRATA 13, solved by the builder); f_act: the
// scene's constant actuator force. The damper dissipates exactly
// dd/dt^T C dd/dt.
#include <railstab/elements/axis_deflection.hpp>
#include <railstab/elements/element_ends.hpp>

#include <string>

namespace railstab {

template <class S> struct SpringDamper3d {
  static constexpr const char* kType = "spring_damper_3d";
  static constexpr int kInternalStates = 0;
  static constexpr bool kInGravitySag = true;
  ElementEnds ends;
  Vec3<S> stiffness_N_per_m = Vec3<S>::Zero();
  Vec3<S> damping_N_s_per_m = Vec3<S>::Zero();
  Vec3<S> actuator_force_N = Vec3<S>::Zero();
  Vec3<S> preload_N = Vec3<S>::Zero();            // solved by the builder
  Eigen::Vector3d free_vector_m = Eigen::Vector3d::Zero();  // d0, set by the builder

  void set_nominal(const Attachment<double>& a1, const Attachment<double>& a2) {
    free_vector_m = axis_deflection(a1, ends.point1_m, a2, ends.point2_m).d;
  }
  // The elastic force at a configuration: what becomes the preload when it
  // is the sagged static equilibrium.
  template <class T>
  Vec3<T> elastic_load(const Attachment<T>& a1, const Attachment<T>& a2) const {
    const Vec3<T> d = axis_deflection(a1, ends.point1_m, a2, ends.point2_m).d;
    return lift<T>(stiffness_N_per_m).cwiseProduct(d - to_scalar<T>(free_vector_m));
  }
  void set_preload(const Vec3<S>& load) { preload_N = load; }
  // The preload on each preloaded axis and the axis's stiffness, for the
  // model check's static deflections: f(axis, unit, preload, stiffness).
  template <class F> void for_each_preloaded_axis(F&& f) const {
    static const char* const xyz[3] = {"x", "y", "z"};
    for (int i = 0; i < 3; ++i)
      f(xyz[i], "m", value_of(preload_N(i)), value_of(stiffness_N_per_m(i)));
  }
  template <class F> void for_each_parameter(F&& f) {
    for (int i = 0; i < 3; ++i) {
      f("stiffness_N_per_m", i, stiffness_N_per_m(i));
      f("damping_N_s_per_m", i, damping_N_s_per_m(i));
    }
  }

  template <class T>
  Vec3<T> elastic_force_F1(const AxisDeflection<T>& def) const {
    return lift<T>(stiffness_N_per_m).cwiseProduct(def.d - to_scalar<T>(free_vector_m)) +
           lift<T>(actuator_force_N) + lift<T>(preload_N);
  }

  template <class T>
  void apply(const Attachment<T>& a1, const Attachment<T>& a2, const T*, T*) const {
    const AxisDeflection<T> def = axis_deflection(a1, ends.point1_m, a2, ends.point2_m);
    const Vec3<T> f = elastic_force_F1(def) + lift<T>(damping_N_s_per_m).cwiseProduct(def.d_rate);
    apply_axis_force(a1, a2, def, f);
  }

  double potential(const Attachment<double>& a1, const Attachment<double>& a2,
                   const double*) const {
    const Eigen::Vector3d dd =
        axis_deflection(a1, ends.point1_m, a2, ends.point2_m).d - free_vector_m;
    const Eigen::Vector3d f0 = value_of_each(actuator_force_N) + value_of_each(preload_N);
    return 0.5 * dd.dot(value_of_each(stiffness_N_per_m).cwiseProduct(dd)) + f0.dot(dd);
  }

  std::string internal_state_name(int) const { return {}; }

  template <class S2> SpringDamper3d<S2> cast() const {
    SpringDamper3d<S2> e;
    e.ends = ends;
    e.stiffness_N_per_m = lift<S2>(stiffness_N_per_m);
    e.damping_N_s_per_m = lift<S2>(damping_N_s_per_m);
    e.actuator_force_N = lift<S2>(actuator_force_N);
    e.preload_N = lift<S2>(preload_N);
    e.free_vector_m = free_vector_m;
    return e;
  }
};

}  // namespace railstab
