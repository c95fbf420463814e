#pragma once
// Kinematics of a line element: the straight line between a point on each
// attachment (a damper, a rod). Length l = |r2 - r1|, unit vector
// n = (r2 - r1)/l from point 1 to point 2, rate dl/dt = n . (v2 - v1).
// A tension F (> 0 pulls the points together) acts as +F n on body 1 at
// point 1 and -F n on body 2 at point 2: the power it absorbs is F dl/dt,
// and a tension F = dV/dl derives from the potential V(l).
// Line elements must not collapse (l > 0): the builder checks the free length.
#include <railstab/kinematics/attachment.hpp>

namespace railstab {

template <class T> struct LineMotion {
  PointMotion<T> p1, p2;
  T length_m, rate_m_per_s;
  Vec3<T> unit_W;
};

template <class T>
LineMotion<T> line_motion(const Attachment<T>& a1, const Eigen::Vector3d& point1_m,
                          const Attachment<T>& a2, const Eigen::Vector3d& point2_m) {
  using std::sqrt;
  LineMotion<T> m;
  m.p1 = a1.point(point1_m);
  m.p2 = a2.point(point2_m);
  const Vec3<T> delta = m.p2.p_W - m.p1.p_W;
  m.length_m = sqrt(delta.squaredNorm());
  m.unit_W = delta / m.length_m;
  m.rate_m_per_s = m.unit_W.dot(m.p2.v_W - m.p1.v_W);
  return m;
}

template <class T>
void apply_line_tension(const Attachment<T>& a1, const Attachment<T>& a2,
                        const LineMotion<T>& m, const T& tension_N) {
  const Vec3<T> f_W = tension_N * m.unit_W;
  a1.apply_force(m.p1.arm_W, f_W);
  a2.apply_force(m.p2.arm_W, Vec3<T>(-f_W));
}

}  // namespace railstab
