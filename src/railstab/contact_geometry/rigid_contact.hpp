#pragma once
// Rigid wheel-rail contact of a wheelset on its two rails (yaw neglected, see
// wheel_contact_points.hpp): for a lateral shift y of the wheelset centre, the
// roll phi and height z at which both wheels touch their rails, i.e. the
// lowest gap of each wheel is zero. With g0_s the lowest vertical gap of side
// s at z = 0, the heights differ by 2 D sin(phi) between the sides, so phi
// solves the scalar equation
//   f(phi) = g0_L(phi) - g0_R(phi) = 0   (z cancels),
// found by a bracketing secant (Illinois) method; then z = -g0_L.
#include <railstab/contact_geometry/wheel_contact_points.hpp>

#include <stdexcept>

namespace railstab {

struct ContactGeometryError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A further local minimum of a wheel's gap within this distance of zero (at
// the rigid solution) counts as a simultaneous contact (two-point contact).
inline constexpr double kSecondContactGapTolerance_m = 1e-5;

struct RigidContactSolution {
  double lateral_m = 0, roll_rad = 0, vertical_m = 0;
  // Local minima of each wheel's gap at the solution, lowest first: [0] is in
  // contact (gap 0 to ~1e-12 m); a further one is a contact if its gap is
  // within kSecondContactGapTolerance_m.
  std::vector<ContactPoint> left, right;
  int contacts_left() const;
  int contacts_right() const;
};

// Throws ContactGeometryError if a wheel finds no contact point on its rail.
RigidContactSolution solve_rigid_contact(const ProfilePair& pair, double lateral_m,
                                         double roll_guess_rad = 0.0);

// Checks that the centred wheelset touches both rails at an interior point of
// both profiles; the error names both files and what was expected.
void require_contact_at_nominal_position(const ProfilePair& pair);

}  // namespace railstab
