#pragma once
// Rigid-contact characteristic functions of a wheelset over its lateral
// shift y: delta_r(y) = r_left - r_right, roll(y), contact angles, rolling
// radii and contact positions of the primary contact of each wheel, and of
// a second simultaneous contact (two-point contact) where one exists.
#include <railstab/contact_geometry/rigid_contact.hpp>

#include <string>

namespace railstab {

struct CharacteristicRow {
  RigidContactSolution solution;
  // Non-empty: no rigid contact was found at this shift (the reason);
  // solution then holds only lateral_m.
  std::string failure;
  bool computed() const { return failure.empty(); }
  double delta_r_m() const {
    return solution.left.front().rolling_radius_m - solution.right.front().rolling_radius_m;
  }
};

// Rows for y = y_min, y_min + step, ..., y_max (roll continued from row to
// row, from the centre outwards), a symmetric wheelset, shifts of the
// wheelset centre. Throws ContactGeometryError where a row has no solution.
std::vector<CharacteristicRow> characteristic_functions(const ProfilePair& pair, double y_min_m,
                                                        double y_max_m, double step_m);

// The same for a wheelset of two pairs, shifts in `reference`. Every row is
// tried: one without a rigid contact is recorded (failure) and the next
// starts from the last solved roll, so one bad shift costs one row, not the
// table.
std::vector<CharacteristicRow> characteristic_functions(const WheelsetProfilePairs& pairs,
                                                        double y_min_m, double y_max_m,
                                                        double step_m,
                                                        LateralShiftReference reference);

// Flange contact of the left wheel: the smallest lateral shift y in (0, y_max]
// at which the contact angle of the primary contact exceeds
// flange_contact_angle_rad (the contact jumps onto the flange face), refined
// by bisection to tolerance_m. The wheel positions of the contact just before
// and just after the jump are returned (the part of the wheel in between is
// never in rigid contact: the natural border between tread and flange).
inline constexpr double kFlangeContactAngle_rad = 0.7853981633974483;  // 45 degrees

struct FlangeContact {
  bool found = false;
  double lateral_shift_m = 0;
  double tread_wheel_u_m = 0, flange_wheel_u_m = 0;
  double tread_contact_angle_rad = 0, flange_contact_angle_rad = 0;
};
FlangeContact find_flange_contact(const ProfilePair& pair, double y_max_m = 0.012,
                                  double step_m = 2e-4, double tolerance_m = 1e-7,
                                  double flange_contact_angle_rad = kFlangeContactAngle_rad);
// The left wheel's flange contact of a wheelset of two pairs, the shift in
// `reference` (contact-geometry reports it in EN 15302's).
FlangeContact find_flange_contact(const WheelsetProfilePairs& pairs,
                                  LateralShiftReference reference, double y_max_m = 0.012,
                                  double step_m = 2e-4, double tolerance_m = 1e-7,
                                  double flange_contact_angle_rad = kFlangeContactAngle_rad);

// Borders between the parts of the wheel that carry the rigid contact: the
// left wheel's primary contact is followed over lateral shifts
// -half_range..+half_range (step step_m); wherever it jumps along the wheel
// by more than jump_m between neighbouring shifts, the middle of the jump is
// a border (the wheel between the jump's ends never carries a rigid contact).
// Sorted from the field side inwards (decreasing u). Shifts without a rigid
// contact are skipped.
std::vector<double> contact_jump_borders(const ProfilePair& pair, double half_range_m,
                                         double step_m = 1e-4, double jump_m = 1e-3);

}  // namespace railstab
