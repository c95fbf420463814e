#pragma once
// A contact table in a file (geometry = "table"; docs/contact_tables.md):
// what the elastic contact model evaluates, written by `railstab
// contact-geometry` (<stem>_contact_table.csv) and read back instead of
// building the table from profiles.
//
// railstab's own format (CSV, SI units, every number the shortest text that
// reads back to the same double; lines starting with '#' are comments):
//
//   key,value
//   format,railstab_contact_table_1
//   <key>,<value>              one per line, every key below, any order
//   slot,i,j,gap0_m,gap0_dq,gap0_droll_m_per_rad,gap0_dq_droll_per_rad,wheel_u_m,...
//   0,0,0,<35 numbers per row: slot, lateral node i, roll node j, then per
//           quantity its value and its node derivatives d/dq, d/droll,
//           d2/dq droll, each column named with its unit>
//
// Keys: written_from (text), the placement (nominal_rolling_radius_m,
// wheel_offset_y_m, rail_offset_y_m, rail_top_y_m, rail_top_z_m,
// gauge_point_y_m and the ProfilePairParameters track_gauge_m,
// gauge_measuring_height_m, flange_back_distance_m, rail_inclination_rad,
// tape_circle_from_flange_back_m), nominal_lateral_m, flange_angle_rad,
// flange_contact_shift_m (a number or `none`), the grid
// (table_lateral_half_range_m, table_lateral_step_m,
// table_roll_half_range_rad, table_roll_step_rad), slots and slot_borders_m
// (slots - 1 numbers, decreasing). The quantities are TableQuantity's, in
// its order (A and B as curvature_a_per_m, curvature_b_per_m); rows run slot
// by slot, i by i, j by j. The node values and derivatives are the table's
// own: a table read back evaluates bit for bit as the one written, so a
// model built on it gives the same numbers.
//
// Every error is a ContactTableFileError naming the file, the line, the key
// or column, what was expected and what was found.
#include <railstab/contact_geometry/profile_contact_geometry.hpp>

#include <iosfwd>
#include <memory>
#include <stdexcept>
#include <string>

namespace railstab {

struct ContactTableFileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

inline constexpr const char* kContactTableFormatTag = "railstab_contact_table_1";

// Writes the table of `geometry` with its placement numbers, flange angle
// and, where found, the flange contact shift (computed here from the
// profiles: `geometry` must have them). `source` describes where it came
// from (the profiles and scene).
void write_contact_table_file(std::ostream& out, const ProfileContactGeometry& geometry,
                              const std::string& source);

// Reads a table written by write_contact_table_file. The geometry's
// table_source is `path`; its pair holds the placement numbers only.
std::shared_ptr<const ProfileContactGeometry> read_contact_table_file(const std::string& path);

}  // namespace railstab
