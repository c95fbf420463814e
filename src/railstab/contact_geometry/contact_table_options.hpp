#pragma once
// Grid of a contact table (contact_tables.hpp): lateral displacement of the
// wheel relative to its rail from the centred position, and roll. A wheel
// outside the grid is derailed (evaluation throws). Scene keys (geometry =
// "profiles"): table_lateral_half_range_m, table_lateral_step_m,
// table_roll_half_range_rad, table_roll_step_rad.

namespace railstab {

struct ContactTableOptions {
  double lateral_half_range_m = 0.012;
  double lateral_step_m = 1e-4;
  double roll_half_range_rad = 0.02;
  double roll_step_rad = 0.005;
};

}  // namespace railstab
