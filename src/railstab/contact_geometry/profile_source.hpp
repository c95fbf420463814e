#pragma once
// A contact with geometry = "profiles" as a scene gives it: where the wheel
// and rail profiles come from and how they are placed
// (profiles/profile_pair.hpp; the pair's nominal rolling radius is the
// contact's nominal_rolling_radius_m), and the grid of its contact table
// (contact_tables.hpp). The set-up step builds the table from it
// (profile_contact_geometry.hpp).
#include <railstab/contact_geometry/contact_table_options.hpp>
#include <railstab/profiles/profile.hpp>
#include <railstab/profiles/profile_pair.hpp>

#include <optional>
#include <string>

namespace railstab {

struct ProfileSourceSpec {
  std::string wheel_profile_path, rail_profile_path;  // resolved against the scene's folder
  LengthUnit wheel_unit = LengthUnit::millimetre, rail_unit = LengthUnit::millimetre;
  ProfilePairParameters placement;
  ContactTableOptions table;
  // An asymmetric (e.g. measured worn) wheelset: the right wheel's profile,
  // the right rail's, the right wheel's tape-circle radius and the right
  // rail's gauge point, each where it differs from the left's (empty: the
  // left's, mirrored). Any of them set: ProfileContactGeometry::right_pair.
  std::string right_wheel_profile_path, right_rail_profile_path;
  LengthUnit right_wheel_unit = LengthUnit::millimetre, right_rail_unit = LengthUnit::millimetre;
  std::optional<double> right_nominal_rolling_radius_m;
  std::optional<double> right_rail_gauge_point_y_m;
  bool asymmetric() const {
    return !right_wheel_profile_path.empty() || !right_rail_profile_path.empty() ||
           right_nominal_rolling_radius_m.has_value() || right_rail_gauge_point_y_m.has_value();
  }
};

}  // namespace railstab
