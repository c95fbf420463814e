#pragma once
// Linear force elements between two attachments (thesis 4.82-4.95).
//
// spring_damper_3d: the deflection vector is measured in the frame of
// attachment 1 (as thesis 4.88), d = R_W1^T (r2 - r1), and
//   f = K (d - d0) + C dd/dt + f_act + f_pre        (components in frame 1)
// where dd/dt = R_W1^T (v2 - v1) - w1 x d is the true rate of those components
// (the thesis' 4.92 omits the w1 x d term; with it the damper dissipates
// exactly -dd/dt^T C dd/dt). Body 1 receives +R_W1 f at point 1, body 2
// receives -R_W1 f at point 2, and body 1 the moment R_W1 (d x f): the
// element's axes turn with body 1, and this moment is what makes the
// directional spring conservative (it is -dV/d(rotation of frame 1)) and
// keeps the pair free of net moment.
//   Potential: V = 1/2 (d - d0)^T K (d - d0) + (f_act + f_pre)^T (d - d0).
//
// rotational_spring_damper: theta = rotation vector of R_W1^T R_W2 (in frame
// 1), m = -K theta - C w_rel - m_act acts on body 2, its opposite on body 1.
// Exactly conservative for isotropic K and no constant moment
// (V = 1/2 k |theta|^2); otherwise conservative to first order in theta.
#include "elements/attachment.hpp"

namespace railstab {

template <class T> struct ElementDeflection {
  Vec3<T> d, d_rate;  // in frame 1
};

template <class T>
ElementDeflection<T> spring_deflection(const ModelElement& e, const Attachment<T>& a1,
                                       const Attachment<T>& a2, PointMotion<T>* p1_out = nullptr,
                                       PointMotion<T>* p2_out = nullptr) {
  const PointMotion<T> p1 = a1.point(e.point1_m);
  const PointMotion<T> p2 = a2.point(e.point2_m);
  ElementDeflection<T> out;
  out.d = a1.R_WF.transpose() * (p2.p_W - p1.p_W);
  const Vec3<T> w1_F = a1.R_WF.transpose() * a1.w_W;
  out.d_rate = a1.R_WF.transpose() * (p2.v_W - p1.v_W) - w1_F.cross(out.d);
  if (p1_out) *p1_out = p1;
  if (p2_out) *p2_out = p2;
  return out;
}

// Force in frame 1 of a spring_damper_3d; `with_damping` false gives the
// elastic part alone (used to solve preloads).
template <class T>
Vec3<T> spring_force_F1(const ModelElement& e, const ElementDeflection<T>& def,
                        bool with_damping = true) {
  Vec3<T> f = to_scalar<T>(e.stiffness).cwiseProduct(def.d - to_scalar<T>(e.free_vector_m)) +
              to_scalar<T>(e.actuator) + to_scalar<T>(e.preload);
  if (with_damping) f += to_scalar<T>(e.damping).cwiseProduct(def.d_rate);
  return f;
}

template <class T>
void apply_spring_damper_3d(const ModelElement& e, const Attachment<T>& a1,
                            const Attachment<T>& a2) {
  PointMotion<T> p1, p2;
  const ElementDeflection<T> def = spring_deflection(e, a1, a2, &p1, &p2);
  const Vec3<T> f_F1 = spring_force_F1(e, def);
  const Vec3<T> f_W = a1.R_WF * f_F1;
  a1.apply_force(p1.arm_W, f_W);
  a2.apply_force(p2.arm_W, Vec3<T>(-f_W));
  a1.apply_moment(a1.R_WF * def.d.cross(f_F1));
}

// Rotation vector of a rotation matrix, smooth at zero rotation (AD-safe):
// theta = angle/sin(angle) * vee(R - R^T)/2, with the factor's series
// 1 + (1 - cos)/3 near zero.
template <class T> Vec3<T> rotation_vector(const Mat3<T>& R) {
  using std::atan2;
  using std::sqrt;
  const Vec3<T> half_vee(T(0.5) * (R(2, 1) - R(1, 2)), T(0.5) * (R(0, 2) - R(2, 0)),
                         T(0.5) * (R(1, 0) - R(0, 1)));
  const T cos_angle = T(0.5) * (R.trace() - T(1));
  const T one_minus_cos = T(1) - cos_angle;
  if (value_of(one_minus_cos) < 1e-6) {
    return half_vee * (T(1) + one_minus_cos / T(3));
  }
  const T sin_angle = sqrt(half_vee.squaredNorm());
  const T angle = atan2(sin_angle, cos_angle);
  return half_vee * (angle / sin_angle);
}

template <class T>
void apply_rotational_spring_damper(const ModelElement& e, const Attachment<T>& a1,
                                    const Attachment<T>& a2) {
  const Mat3<T> R_12 = a1.R_WF.transpose() * a2.R_WF;
  const Vec3<T> theta = rotation_vector(R_12);
  const Vec3<T> w_rel_F1 = a1.R_WF.transpose() * (a2.w_W - a1.w_W);
  const Vec3<T> m_F1 = -(to_scalar<T>(e.stiffness).cwiseProduct(theta) +
                         to_scalar<T>(e.damping).cwiseProduct(w_rel_F1) +
                         to_scalar<T>(e.actuator) + to_scalar<T>(e.preload));
  const Vec3<T> m_W = a1.R_WF * m_F1;
  a2.apply_moment(m_W);
  a1.apply_moment(Vec3<T>(-m_W));
}

}  // namespace railstab
