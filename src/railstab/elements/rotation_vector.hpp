#pragma once
// Rotation vector of a rotation matrix, smooth at zero rotation (AD-safe):
// theta = angle/sin(angle) * vee(R - R^T)/2, with the factor's series
// 1 + (1 - cos)/3 near zero.
#include <railstab/core/scalar.hpp>

namespace railstab {

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

}  // namespace railstab
