#pragma once
// Elementary rotation matrices and the skew operator, templated on the scalar.
//
// R_x(a) rotates components of a frame rotated by +a about x into the parent
// frame: v_parent = R_x(a) v_child. The track frame is A = Az Ay Ax (thesis
// 2.5); a body relative to its track frame is B = Bz Bx By (Z-X-Y, thesis 2.3.2),
// and Bzx = Bz Bx is the wheelset's non-spinning intermediate frame (thesis 4.40).
#include <railstab/core/scalar.hpp>

namespace railstab {

template <class T> Mat3<T> rot_x(const T& a) {
  using std::cos;
  using std::sin;
  const T c = cos(a), s = sin(a);
  Mat3<T> r;
  r << T(1), T(0), T(0), T(0), c, -s, T(0), s, c;
  return r;
}

template <class T> Mat3<T> rot_y(const T& a) {
  using std::cos;
  using std::sin;
  const T c = cos(a), s = sin(a);
  Mat3<T> r;
  r << c, T(0), s, T(0), T(1), T(0), -s, T(0), c;
  return r;
}

template <class T> Mat3<T> rot_z(const T& a) {
  using std::cos;
  using std::sin;
  const T c = cos(a), s = sin(a);
  Mat3<T> r;
  r << c, -s, T(0), s, c, T(0), T(0), T(0), T(1);
  return r;
}

// skew(v) w = v x w.
template <class T> Mat3<T> skew(const Vec3<T>& v) {
  Mat3<T> m;
  m << T(0), -v.z(), v.y(), v.z(), T(0), -v.x(), -v.y(), v.x(), T(0);
  return m;
}

}  // namespace railstab
