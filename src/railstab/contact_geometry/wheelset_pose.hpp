#pragma once
// From the wheelset's position in the track frame to each wheel's pose in its
// rail profile frame (profiles/profile_pair.hpp), templated on the scalar.
//
// Wheelset: centre at (y, z) in the track frame T (z: height of the centre
// above the plane of the rail tops, ~ r0), roll phi about x_T (positive raises
// the left wheel). Side s = +1 left, -1 right. The rail frame of side s has
// y_r = s y_T - rail_offset, z_r = z_T + rail_top_z. With D = wheel_offset
// and r0 the nominal rolling radius, the wheel profile origin (axle frame
// (s D, -r0)) is at
//   lateral  = s y - rail_offset + D cos(phi) + s r0 sin(phi)
//   vertical = z + rail_top_z + s D sin(phi) - r0 cos(phi)
//   roll     = s phi
// (mirroring the right side turns a roll phi into -phi).
#include <railstab/core/scalar.hpp>
#include <railstab/profiles/profile_pair.hpp>

namespace railstab {

template <class T> struct WheelPoseOf {
  T lateral_m, vertical_m, roll_rad;
};

template <class T>
WheelPoseOf<T> wheel_pose_in_rail_frame(const ProfilePair& pair, int side, const T& y_m,
                                        const T& z_m, const T& roll_rad) {
  using std::cos;
  using std::sin;
  const double s = side > 0 ? 1.0 : -1.0;
  const double D = pair.wheel_offset_y_m, r0 = pair.parameters.nominal_rolling_radius_m;
  WheelPoseOf<T> p;
  p.lateral_m = s * y_m - pair.rail_offset_y_m + D * cos(roll_rad) + s * r0 * sin(roll_rad);
  p.vertical_m = z_m + pair.rail_top_z_m + s * D * sin(roll_rad) - r0 * cos(roll_rad);
  p.roll_rad = s * roll_rad;
  return p;
}

}  // namespace railstab
