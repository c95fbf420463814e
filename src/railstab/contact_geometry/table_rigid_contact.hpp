#pragma once
// Rigid contact of a wheelset on its two rails evaluated on a contact table
// (contact_tables.hpp) instead of the profiles: what `contact-geometry`
// reports for a contact with geometry = "table", and how a table is checked
// against the profiles it came from.
//
// For a lateral shift y the roll phi solves, as solve_rigid_contact
// (rigid_contact.hpp) does on the profiles,
//   g_L(phi) - g_R(phi) = 0,
// g_s the lowest vertical gap over the table's slots of side s at height 0
// (bracketing secant, Illinois); the wheel quantities are those of the
// slot with the lowest gap. Differences from the profiles' own functions are
// the table's interpolation error (stated in the tests).
#include <railstab/contact_geometry/profile_contact_geometry.hpp>

#include <vector>

namespace railstab {

struct TableWheelContact {
  int slot = 0;
  double wheel_u_m = 0, rail_y_m = 0, contact_angle_rad = 0, rolling_radius_m = 0;
};

struct TableRigidRow {
  double lateral_m = 0, roll_rad = 0;  // the shift in the reference asked for
  double centre_lateral_m = 0;         // the wheelset centre's (rigid_contact.hpp)
  TableWheelContact left, right;
  double delta_r_m() const { return left.rolling_radius_m - right.rolling_radius_m; }
};

// Throws ContactGeometryError (rigid_contact.hpp) where no roll within the
// table's range makes both wheels touch.
TableRigidRow table_rigid_contact(
    const ProfileContactGeometry& geometry, double lateral_m, double roll_guess_rad = 0.0,
    LateralShiftReference reference = LateralShiftReference::wheelset_centre);

// Rows for y = y_min, y_min + step, ..., y_max (roll continued from the centre out).
std::vector<TableRigidRow> table_characteristic_functions(const ProfileContactGeometry& geometry,
                                                          double y_min_m, double y_max_m,
                                                          double step_m);

}  // namespace railstab
