#pragma once
// rotational_spring_damper (bushing): a moment from the relative rotation of
// the two attachment frames. theta = rotation vector of R_W1^T R_W2 (frame 1
// components), w_rel = R_W1^T (w2 - w1):
//   m = -(K theta + C w_rel + m_act + m_pre)  on body 2, its opposite on body 1.
// Exactly conservative for isotropic K and no constant moment
// (V = 1/2 k |theta|^2); otherwise conservative to first order in theta.
// The points only document where the bushing sits: a pure moment acts the
// same wherever it is applied.
#include <railstab/elements/element_ends.hpp>
#include <railstab/elements/rotation_vector.hpp>
#include <railstab/kinematics/attachment.hpp>

#include <string>

namespace railstab {

template <class S> struct RotationalSpringDamper {
  static constexpr const char* kType = "rotational_spring_damper";
  static constexpr int kInternalStates = 0;
  static constexpr bool kInGravitySag = true;
  ElementEnds ends;
  Vec3<S> stiffness_N_m_per_rad = Vec3<S>::Zero();
  Vec3<S> damping_N_m_s_per_rad = Vec3<S>::Zero();
  Vec3<S> actuator_moment_N_m = Vec3<S>::Zero();
  Vec3<S> preload_N_m = Vec3<S>::Zero();  // solved by the builder

  void set_nominal(const Attachment<double>&, const Attachment<double>&) {}
  template <class T>
  Vec3<T> elastic_load(const Attachment<T>& a1, const Attachment<T>& a2) const {
    const Mat3<T> R_12 = a1.R_WF.transpose() * a2.R_WF;
    return lift<T>(stiffness_N_m_per_rad).cwiseProduct(rotation_vector<T>(R_12));
  }
  void set_preload(const Vec3<S>& load) { preload_N_m = load; }
  // The preload on each preloaded axis and the axis's stiffness, for the
  // model check's static deflections: f(axis, unit, preload, stiffness).
  template <class F> void for_each_preloaded_axis(F&& f) const {
    static const char* const rpy[3] = {"roll", "pitch", "yaw"};
    for (int i = 0; i < 3; ++i)
      f(rpy[i], "rad", value_of(preload_N_m(i)), value_of(stiffness_N_m_per_rad(i)));
  }
  template <class F> void for_each_parameter(F&& f) {
    for (int i = 0; i < 3; ++i) {
      f("stiffness_N_m_per_rad", i, stiffness_N_m_per_rad(i));
      f("damping_N_m_s_per_rad", i, damping_N_m_s_per_rad(i));
    }
  }

  template <class T>
  void apply(const Attachment<T>& a1, const Attachment<T>& a2, const T*, T*) const {
    const Mat3<T> R_12 = a1.R_WF.transpose() * a2.R_WF;
    const Vec3<T> theta = rotation_vector(R_12);
    const Vec3<T> w_rel_F1 = a1.R_WF.transpose() * (a2.w_W - a1.w_W);
    const Vec3<T> m_F1 = -(lift<T>(stiffness_N_m_per_rad).cwiseProduct(theta) +
                           lift<T>(damping_N_m_s_per_rad).cwiseProduct(w_rel_F1) +
                           lift<T>(actuator_moment_N_m) + lift<T>(preload_N_m));
    const Vec3<T> m_W = a1.R_WF * m_F1;
    a2.apply_moment(m_W);
    a1.apply_moment(Vec3<T>(-m_W));
  }

  double potential(const Attachment<double>& a1, const Attachment<double>& a2,
                   const double*) const {
    const Eigen::Vector3d th = rotation_vector<double>(a1.R_WF.transpose() * a2.R_WF);
    const Eigen::Vector3d m0 = value_of_each(actuator_moment_N_m) + value_of_each(preload_N_m);
    return 0.5 * th.dot(value_of_each(stiffness_N_m_per_rad).cwiseProduct(th)) + m0.dot(th);
  }

  std::string internal_state_name(int) const { return {}; }

  template <class S2> RotationalSpringDamper<S2> cast() const {
    RotationalSpringDamper<S2> e;
    e.ends = ends;
    e.stiffness_N_m_per_rad = lift<S2>(stiffness_N_m_per_rad);
    e.damping_N_m_s_per_rad = lift<S2>(damping_N_m_s_per_rad);
    e.actuator_moment_N_m = lift<S2>(actuator_moment_N_m);
    e.preload_N_m = lift<S2>(preload_N_m);
    return e;
  }
};

}  // namespace railstab
