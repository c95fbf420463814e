#pragma once
// Rigid wheel-rail contact of a wheelset on its two rails (yaw neglected, see
// wheel_contact_points.hpp): for a lateral shift y of the wheelset centre, the
// roll phi and height z at which both wheels touch their rails, i.e. the
// lowest gap of each wheel is zero. With g0_s the lowest vertical gap of side
// s at z = 0, the heights differ by 2 D sin(phi) between the sides, so phi
// solves the scalar equation
//   f(phi) = g0_L(phi) - g0_R(phi) = 0   (z cancels),
// found by a bracketing secant (Illinois) method; then z = -g0_L.
//
// Lateral shift: two references (LateralShiftReference). railstab's model
// uses the wheelset centre y_c (on the axle). EN 15302 uses the lateral
// displacement of the wheelset relative to the track, which we take as the
// displacement of the wheel profiles relative to the rails: the midpoint of
// the two tape circles' lowest points (axle frame (0, -r0_mean)), which a
// roll phi about the centre moves by r0_mean sin(phi):
//   y_EN = y_c + r0_mean sin(phi),  r0_mean = (r0_left + r0_right) / 2.
// (At flange contact phi ~ 1 mrad: y_EN - y_c ~ 0.4 mm.) For a given y_EN
// the roll solves f(phi) = 0 with y_c = y_EN - r0_mean sin(phi).
//
// Wheels: each side has its own placed profile pair (WheelsetProfilePairs):
// an asymmetric or measured worn wheelset has different wheel profiles
// and/or tape-circle radii left and right (the right pair is placed as the
// mirror image, profiles/profile_pair.hpp, with its own r0).
#include <railstab/contact_geometry/wheel_contact_points.hpp>

#include <stdexcept>

namespace railstab {

struct ContactGeometryError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A further local minimum of a wheel's gap within this distance of zero (at
// the rigid solution) counts as a simultaneous contact (two-point contact).
inline constexpr double kSecondContactGapTolerance_m = 1e-5;

// The placed pairs of the left and the right wheel (references: the pairs
// outlive this view). A symmetric wheelset has the same pair on both sides.
struct WheelsetProfilePairs {
  const ProfilePair& left;
  const ProfilePair& right;
  const ProfilePair& side(int s) const { return s > 0 ? left : right; }
  // (r0_left + r0_right) / 2: the r0 of y_EN and of the Klingel formula.
  double mean_nominal_rolling_radius_m() const {
    return 0.5 * (left.parameters.nominal_rolling_radius_m +
                  right.parameters.nominal_rolling_radius_m);
  }
};

enum class LateralShiftReference {
  wheelset_centre,  // y = y_c, the wheelset centre (railstab's model, contact tables)
  en15302,          // y = y_c + r0_mean sin(phi): the wheel profiles relative to the rails
};

struct RigidContactSolution {
  // lateral_m: the shift as asked for (in the reference asked for);
  // centre_lateral_m: the wheelset centre's y_c (equal for wheelset_centre).
  double lateral_m = 0, roll_rad = 0, vertical_m = 0;
  double centre_lateral_m = 0;
  // Local minima of each wheel's gap at the solution, lowest first: [0] is in
  // contact (gap 0 to ~1e-12 m); a further one is a contact if its gap is
  // within kSecondContactGapTolerance_m.
  std::vector<ContactPoint> left, right;
  int contacts_left() const;
  int contacts_right() const;
};

// Throws ContactGeometryError if a wheel finds no contact point on its rail.
RigidContactSolution solve_rigid_contact(const WheelsetProfilePairs& pairs, double lateral_m,
                                         double roll_guess_rad, LateralShiftReference reference);
// A symmetric wheelset, shift of the wheelset centre.
inline RigidContactSolution solve_rigid_contact(const ProfilePair& pair, double lateral_m,
                                                double roll_guess_rad = 0.0) {
  return solve_rigid_contact(WheelsetProfilePairs{pair, pair}, lateral_m, roll_guess_rad,
                             LateralShiftReference::wheelset_centre);
}

// Checks that the centred wheelset touches both rails at an interior point of
// both profiles; the error names both files and what was expected.
void require_contact_at_nominal_position(const ProfilePair& pair);
void require_contact_at_nominal_position(const WheelsetProfilePairs& pairs);

}  // namespace railstab
