#pragma once
// DYTSI's RSGEO table (the Technical University of Denmark's open DYnamics
// Train SImulation code, github.com/daniele-bigoni/dytsi;
// docs/contact_tables.md) as a railstab contact geometry
// (geometry = "table", contact_table_format = "rsgeo").
//
// The file: lines up to a line starting with '#' are skipped; the next line
// names the columns (quoted, whitespace-separated); then one row per
// lateral shift y of the wheelset (DYTSI: step 1e-5 m, +-17 mm), 13
// whitespace-separated numbers, up to the end of the file:
//   0 y (m)  1 normal force N0 (N)  2 contact angle delta (rad, of the
//   normal to the axle)  3 a, 4 b (Hertz semi-axes at N0, m)  5 a_w: the
//   wheel contact point's lateral distance from the wheelset centre (m)
//   6 rolling radius r (m)  7-9 Kalker's C11, C22, C23  10 z_r: the rail
//   contact point's height (m, up)  11 penetration at N0 (m)  12 the rail
//   contact point's lateral position (DYTSI fills it at run time: 0).
// One table serves both wheels: the left wheel is looked up at +y, the
// right at -y (y positive to the left, as railstab's).
//
// What railstab makes of it: a rigid-contact table over y only, turned into
// the elastic model's one-slot table in (q, roll) (contact_tables.hpp):
// - the wheelset's rigid roll phi(y) from both wheels touching:
//     (a_L + a_R) sin(phi) - (r_L - r_R) cos(phi) = z_L - z_R
//   (L at +y, R at -y), the height from the left contact;
// - placement: wheel profile origin at D = a_w(0) from the centre, rail
//   profile origin under it (rail_offset = D, top of rail at 0), r0 the
//   contact's nominal_rolling_radius_m; wheel coordinate u = a_w - D, the
//   wheel's profile height z_w = r0 - r;
// - per lateral node q the rigid state at the y with q_rig(y) = q
//   (q_rig = y - D + D cos(phi) + r0 sin(phi), linear interpolation between
//   rows); in roll the gap is extended to first order about the rigid roll,
//     g0(q, theta) = g0_rig(q) + G (theta - phi(q)),
//     G = u cos(phi) - z_w sin(phi) + tan(gamma) (u sin(phi) + z_w cos(phi))
//   (the envelope theorem: the contact point's own motion does not enter),
//   the contact angle in the rail frame gamma = delta + theta (the wheel's
//   normal fixed in the wheel), the other quantities constant in roll;
// - Hertz curvatures: A = cos(delta) / (2 r); B such that Hertz's a/b for
//   (A, B) is the table's a/b; railstab computes the normal force from the
//   penetration (N0, the penetration at N0 and C11..C23 are not used: the
//   contact's creep law takes Kalker's coefficients from the Hertz ellipse).
// - a single contact per wheel: a two-point contact of the rigid table is a
//   jump of the contact point, smoothed over a lateral step of the grid.
// The flange angle (Nadal) is the largest contact angle in the file; the
// flange contact shift the smallest y > 0 with delta > 45 degrees.
#include <railstab/contact_geometry/contact_table_file.hpp>

#include <array>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

namespace railstab {

// The columns of an RSGEO file, in its order.
enum class RsgeoColumn : int {
  y_m = 0, normal_force_N, contact_angle_rad, semi_axis_a_m, semi_axis_b_m, wheel_lateral_m,
  rolling_radius_m, c11, c22, c23, rail_height_m, penetration_m, rail_lateral_m, count
};
inline constexpr int kRsgeoColumns = int(RsgeoColumn::count);

struct RsgeoTable {
  std::string path;
  std::vector<std::array<double, kRsgeoColumns>> rows;  // increasing y
  std::vector<int> line;                                // file line of each row
};

// Reads the first table of an RSGEO file. ContactTableFileError naming the
// file, the line, the column and what was expected.
RsgeoTable read_rsgeo_table(const std::string& path);

// The table as the elastic model's contact geometry on `grid`, the wheel
// profile origin at r0 = nominal_rolling_radius_m. Errors (the grid beyond
// the file's range, a rigid state that cannot be solved) name the file and
// the key.
std::shared_ptr<const ProfileContactGeometry> rsgeo_contact_geometry(
    const RsgeoTable& table, const ContactTableOptions& grid, double nominal_rolling_radius_m);

inline std::shared_ptr<const ProfileContactGeometry> read_rsgeo_contact_geometry(
    const std::string& path, const ContactTableOptions& grid, double nominal_rolling_radius_m) {
  return rsgeo_contact_geometry(read_rsgeo_table(path), grid, nominal_rolling_radius_m);
}

// Writes an RSGEO file (for tests and converters): the header line and
// rows as given.
void write_rsgeo_table(std::ostream& out, const std::vector<std::array<double, kRsgeoColumns>>& rows);

}  // namespace railstab
