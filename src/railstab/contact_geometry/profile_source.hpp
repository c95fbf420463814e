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

#include <string>

namespace railstab {

struct ProfileSourceSpec {
  std::string wheel_profile_path, rail_profile_path;  // resolved against the scene's folder
  LengthUnit wheel_unit = LengthUnit::millimetre, rail_unit = LengthUnit::millimetre;
  ProfilePairParameters placement;
  ContactTableOptions table;
};

}  // namespace railstab
