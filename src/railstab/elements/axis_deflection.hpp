#pragma once
// Deflection of two attachment points measured in the axes of attachment 1
// (thesis 4.88), shared by the elements whose axes turn with body 1:
//   d = R_W1^T (r2 - r1),   dd/dt = R_W1^T (v2 - v1) - w1 x d
// (dd/dt is the true rate of the components in the turning frame; the
// thesis' 4.92 omits w1 x d). A force f (components in frame 1) acting on
// body 2 as -R_W1 f at point 2 and on body 1 as +R_W1 f at point 1, plus the
// moment R_W1 (d x f) on body 1, is the exact generalised force of a
// potential V(d): the moment is -dV/d(rotation of frame 1), and the pair
// carries no net moment.
#include <railstab/kinematics/attachment.hpp>

namespace railstab {

template <class T> struct AxisDeflection {
  Vec3<T> d, d_rate;  // in frame 1
  PointMotion<T> p1, p2;
};

template <class T>
AxisDeflection<T> axis_deflection(const Attachment<T>& a1, const Eigen::Vector3d& point1_m,
                                  const Attachment<T>& a2, const Eigen::Vector3d& point2_m) {
  AxisDeflection<T> out;
  out.p1 = a1.point(point1_m);
  out.p2 = a2.point(point2_m);
  out.d = a1.R_WF.transpose() * (out.p2.p_W - out.p1.p_W);
  const Vec3<T> w1_F = a1.R_WF.transpose() * a1.w_W;
  out.d_rate = a1.R_WF.transpose() * (out.p2.v_W - out.p1.v_W) - w1_F.cross(out.d);
  return out;
}

// Applies the force f (frame-1 components, the pull of the element on
// body 1 towards body 2 counted positive along d) as described above.
template <class T>
void apply_axis_force(const Attachment<T>& a1, const Attachment<T>& a2,
                      const AxisDeflection<T>& def, const Vec3<T>& f_F1) {
  const Vec3<T> f_W = a1.R_WF * f_F1;
  a1.apply_force(def.p1.arm_W, f_W);
  a2.apply_force(def.p2.arm_W, Vec3<T>(-f_W));
  a1.apply_moment(a1.R_WF * def.d.cross(f_F1));
}

}  // namespace railstab
