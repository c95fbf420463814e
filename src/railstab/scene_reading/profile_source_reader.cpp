#include <railstab/scene_reading/profile_source_reader.hpp>

#include <railstab/io/regular_file.hpp>

#include <optional>
#include <string>
#include <utility>

namespace railstab::scene_reading {

namespace {

// Keys of the flangeless models that the profiles replace.
const std::vector<std::string_view> kFlangelessKeys = {
    "cone_angle_rad", "conicity", "half_contact_distance_m", "rail_head_transverse_radius_m",
    "flange_clearance_m"};

// One of KEY (a SIMPACK .prw/.prr file, unit from its header), KEY_mm or
// KEY_m (plain two-column text in that unit); the path relative to the scene.
void read_profile_file_key(const TableReader& contact, const std::string& key, std::string& path,
                           LengthUnit& unit) {
  int found = 0;
  for (const auto& [suffix, u] : {std::pair<std::string, LengthUnit>{"", LengthUnit::millimetre},
                                  {"_mm", LengthUnit::millimetre},
                                  {"_m", LengthUnit::metre}}) {
    const std::string k = key + suffix;
    if (!contact.has(k)) continue;
    ++found;
    path = contact.text(k);
    unit = u;
    const auto ends_with = [&](const char* ext) {
      return path.size() >= 4 && path.compare(path.size() - 4, 4, ext) == 0;
    };
    if (suffix.empty() && !ends_with(".prw") && !ends_with(".prr"))
      contact.fail(k, "a SIMPACK .prw/.prr file (a plain-text profile names its unit: " + key +
                          "_mm or " + key + "_m)",
                   quoted(path));
  }
  if (found != 1)
    contact.fail(key, "exactly one of " + key + " (SIMPACK), " + key + "_mm or " + key +
                          "_m (plain text)",
                 found == 0 ? std::string(kMissingKey) : std::to_string(found) + " of them");
  path = path_relative_to_file(contact.source(), path);
}

bool has_profile_file_key(const TableReader& contact, const std::string& key) {
  return contact.has(key) || contact.has(key + "_mm") || contact.has(key + "_m");
}

// An optional number in [lo, hi] `unit`.
std::optional<double> optional_in_range(const TableReader& contact, std::string_view key,
                                        std::string_view unit, double lo, double hi) {
  if (!contact.has(key)) return std::nullopt;
  const double v = contact.number_or(key, unit, 0.0);
  if (!(v >= lo && v <= hi))
    contact.fail(key, "a number in [" + format_number(lo) + ", " + format_number(hi) + "] " +
                          std::string(unit),
                 format_number(v));
  return v;
}

ProfileSourceSpec read_profile_source(const TableReader& contact) {
  ProfileSourceSpec s;
  read_profile_file_key(contact, "wheel_profile", s.wheel_profile_path, s.wheel_unit);
  read_profile_file_key(contact, "rail_profile", s.rail_profile_path, s.rail_unit);
  // An asymmetric wheelset: the right side's own files, radius, gauge point.
  if (has_profile_file_key(contact, "right_wheel_profile"))
    read_profile_file_key(contact, "right_wheel_profile", s.right_wheel_profile_path,
                          s.right_wheel_unit);
  if (has_profile_file_key(contact, "right_rail_profile"))
    read_profile_file_key(contact, "right_rail_profile", s.right_rail_profile_path,
                          s.right_rail_unit);
  s.right_nominal_rolling_radius_m =
      optional_in_range(contact, "right_nominal_rolling_radius_m", "m", 0.1, 1.0);
  // The gauge point placed by its y in the rail file instead of searched at
  // gauge_measuring_height_m below the top (profiles/profile_pair.hpp).
  s.placement.rail_gauge_point_y_m =
      optional_in_range(contact, "rail_gauge_point_y_m", "m", -0.2, 0.2);
  s.right_rail_gauge_point_y_m =
      optional_in_range(contact, "right_rail_gauge_point_y_m", "m", -0.2, 0.2);
  if (s.placement.rail_gauge_point_y_m && contact.has("gauge_measuring_height_m"))
    contact.fail("gauge_measuring_height_m",
                 "no gauge_measuring_height_m together with rail_gauge_point_y_m (the gauge point "
                 "is either searched at a height or given by its y)",
                 "both");
  if (s.right_rail_gauge_point_y_m && !s.placement.rail_gauge_point_y_m)
    contact.fail_missing("rail_gauge_point_y_m",
                         "the left rail's gauge point y, required with "
                         "right_rail_gauge_point_y_m (both rails placed the same way)");
  ProfilePairParameters& p = s.placement;
  p.track_gauge_m = contact.number_or("track_gauge_m", "m", p.track_gauge_m);
  p.gauge_measuring_height_m =
      contact.number_or("gauge_measuring_height_m", "m", p.gauge_measuring_height_m);
  p.flange_back_distance_m =
      contact.number_or("flange_back_distance_m", "m", p.flange_back_distance_m);
  p.rail_inclination_rad = contact.number_or("rail_inclination_rad", "rad", p.rail_inclination_rad);
  p.tape_circle_from_flange_back_m =
      contact.number_or("tape_circle_from_flange_back_m", "m", p.tape_circle_from_flange_back_m);
  read_table_grid(contact, s.table);
  return s;
}

}  // namespace

void read_table_grid(const TableReader& contact, ContactTableOptions& t) {
  auto in_range = [&](std::string_view key, std::string_view unit, double fallback, double lo,
                      double hi) {
    const double v = contact.number_or(key, unit, fallback);
    if (!(v >= lo && v <= hi))
      contact.fail(key, "a number in [" + format_number(lo) + ", " + format_number(hi) + "] " +
                            std::string(unit),
                   format_number(v));
    return v;
  };
  t.lateral_half_range_m = in_range("table_lateral_half_range_m", "m", t.lateral_half_range_m, 0.002, 0.03);
  t.lateral_step_m = in_range("table_lateral_step_m", "m", t.lateral_step_m, 2e-5, 1e-3);
  t.roll_half_range_rad = in_range("table_roll_half_range_rad", "rad", t.roll_half_range_rad, 0.002, 0.1);
  t.roll_step_rad = in_range("table_roll_step_rad", "rad", t.roll_step_rad, 1e-4, 0.02);
}

// geometry = "profiles": the keys of the profile files, their placement and
// the contact table's grid (contact_geometry/profile_contact_geometry.hpp).
const std::vector<std::string_view>& profile_keys() {
  static const std::vector<std::string_view> keys = {
      "wheel_profile", "wheel_profile_mm", "wheel_profile_m", "rail_profile", "rail_profile_mm",
      "rail_profile_m", "track_gauge_m", "gauge_measuring_height_m", "flange_back_distance_m",
      "rail_inclination_rad", "tape_circle_from_flange_back_m", "table_lateral_half_range_m",
      "table_lateral_step_m", "table_roll_half_range_rad", "table_roll_step_rad",
      "right_wheel_profile", "right_wheel_profile_mm", "right_wheel_profile_m",
      "right_rail_profile", "right_rail_profile_mm", "right_rail_profile_m",
      "right_nominal_rolling_radius_m", "rail_gauge_point_y_m", "right_rail_gauge_point_y_m"};
  return keys;
}

void read_profile_contact(const TableReader& contact, ContactSpec& spec) {
  for (std::string_view key : kFlangelessKeys)
    contact.reject_if_present(key, "no " + std::string(key) +
                                       " with geometry = \"profiles\" (the profiles define it)");
  if (spec.normal != NormalForceKind::hertz)
    contact.fail("normal", "\"hertz\" with geometry = \"profiles\" (the normal force follows "
                           "from the penetration at each contact point)",
                 "another normal force model");
  spec.profile_source = read_profile_source(contact);
}

const std::vector<std::string_view>& table_file_keys() {
  static const std::vector<std::string_view> keys = {"contact_table", "contact_table_format"};
  return keys;
}

void read_table_contact(const TableReader& contact, ContactSpec& spec) {
  static const Choices<ContactTableFormat> formats = choices_of(kContactTableFormatNames);
  for (std::string_view key : kFlangelessKeys)
    contact.reject_if_present(key, "no " + std::string(key) +
                                       " with geometry = \"table\" (the table defines it)");
  if (spec.normal != NormalForceKind::hertz)
    contact.fail("normal", "\"hertz\" with geometry = \"table\" (the normal force follows "
                           "from the penetration at each contact point)",
                 "another normal force model");
  if (!contact.has("contact_table"))
    contact.fail_missing("contact_table", "the path of a contact table file (relative to the "
                                          "scene), required when geometry = \"table\"");
  spec.contact_table_path = path_relative_to_file(contact.source(), contact.text("contact_table"));
  spec.contact_table_format =
      contact.choice_or("contact_table_format", formats, ContactTableFormat::railstab);
  const bool rsgeo = spec.contact_table_format == ContactTableFormat::rsgeo;
  // The profiles and their placement are the table's; an RSGEO table is
  // resampled on the grid keys, railstab's own table has its grid.
  for (std::string_view key : profile_keys()) {
    const bool grid_key = key.substr(0, 6) == "table_";
    if (grid_key && rsgeo) continue;
    contact.reject_if_present(key, "no " + std::string(key) + " with geometry = \"table\"" +
                                       (grid_key ? " and contact_table_format = \"railstab\" "
                                                   "(the file has its grid)"
                                                 : " (the table file holds the placement)"));
  }
  if (rsgeo) read_table_grid(contact, spec.profile_source.table);
}

}  // namespace railstab::scene_reading
