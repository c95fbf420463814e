#pragma once
// Contact points of one wheel on its rail, in the rail profile frame (y
// outward, z up; profiles/profile.hpp), for a given pose of the wheel profile.
//
// Pose: the wheel profile frame sits at (lateral_m, vertical_m) in the rail
// profile frame and is rotated by roll_rad (counter-clockwise in the (y, z)
// plane, i.e. positive raises the wheel's outer side). A wheel profile point
// (u, z_w(u)) is then at
//   Y(u) = lateral + u cos(roll) - z_w(u) sin(roll),
//   Z(u) = vertical + u sin(roll) + z_w(u) cos(roll).
// Yaw is neglected: for a non-yawed wheelset the plane x = 0 contains the
// axle, so this rigid 2-D transform is the exact cross-section; a yaw angle
// psi would shift the contact forward and change the gap by O(psi^2 r).
//
// Gap: the VERTICAL distance from the rail to the wheel at the same y,
//   g(u) = Z(u) - z_r(Y(u)).
// Contact points are the interior local minima of g (where the two surfaces
// are parallel: dg/du = 0). The vertical gap is exact for rigid contact (a
// zero minimum is a touching point); for small overlaps the distance along the
// common normal is g cos(gamma) to first order (the surfaces are parallel
// there), reported as normal_gap_m.
//
// Per contact point (signs for either side, in that side's profile frame):
//   contact_angle_rad  gamma = atan(z_r'(y_rail)): the angle of the common
//                      tangent to the track plane; > 0 when the contact normal
//                      on the wheel points towards the track centre (tread of a
//                      coned wheel, flange).
//   rolling_radius_m   r = r0 - z_w(u).
//   Relative curvatures for Hertz (contact/hertz.hpp: A along the rolling
//   direction, B across):
//     A = cos(alpha_w) / (2 r),  alpha_w = atan(z_w'(u)) the angle of the
//         normal to the wheel's radius (Meusnier: the circumferential normal
//         curvature of a surface of revolution); the rail is straight along x.
//     B = (kappa_w - kappa_r) / 2, kappa = z'' / (1 + z'^2)^(3/2) of each
//         profile in its own frame; kappa_w > 0 for a wheel convex towards the
//         rail, -kappa_r > 0 for a convex rail head. B = g''(y)/(2 (1+z'^2)^(3/2))
//         >= 0 at every local minimum; B -> 0 where a contact appears or
//         vanishes (conformal contact, where Hertz fails).
#include <railstab/profiles/profile_pair.hpp>

#include <vector>

namespace railstab {

struct WheelPose {
  double lateral_m = 0, vertical_m = 0, roll_rad = 0;
};

struct ContactPoint {
  double wheel_u_m = 0;           // on the wheel profile (wheel profile frame)
  double rail_y_m = 0, rail_z_m = 0;  // on the rail (rail profile frame)
  double vertical_gap_m = 0;      // g at the minimum (< 0: overlap)
  double normal_gap_m = 0;        // g cos(gamma)
  double contact_angle_rad = 0;   // gamma
  double wheel_slope_rad = 0;     // alpha_w = gamma - roll
  double rolling_radius_m = 0;
  double wheel_curvature_per_m = 0;  // kappa_w (> 0 convex)
  double rail_curvature_per_m = 0;   // -kappa_r (> 0 convex rail head)
  double A_per_m = 0, B_per_m = 0;   // Hertz relative curvatures
  bool interior = true;           // false: the minimum sits at the end of the searched range
};

// Sampling step of the search along the wheel profile; minima closer than
// about two steps merge.
inline constexpr double kContactSearchStep_m = 2.5e-4;

// Every interior local minimum of g over the overlap of the two profiles,
// sorted by gap (lowest first). Empty if none.
std::vector<ContactPoint> find_contact_points(const ProfilePair& pair, const WheelPose& pose);

// The lowest point of g over the part u_min <= u <= u_max of the wheel profile
// (not clipped to the rail: the rail spline continues straight beyond its ends); interior = false if it lies at an
// end of that range. Used for the table slots (tread, flange).
ContactPoint minimum_gap_in_wheel_range(const ProfilePair& pair, const WheelPose& pose,
                                        double u_min, double u_max);

// The highest g on the wheel between u_a and u_b (either order): the saddle
// an overlap must cross to join the contacts at u_a and u_b (< 0: their
// overlaps are one connected region): the largest sample at
// kContactSearchStep_m (within ~1e-8 m of the maximum).
double maximum_gap_between(const ProfilePair& pair, const WheelPose& pose, double u_a, double u_b);

}  // namespace railstab
