#pragma once
// Temporary reader of a profile contact from a scene file, until the scene
// loader knows geometry = "profiles": reads the table [contacts.NAME] with
//   geometry = "profiles"
//   wheel_profile = "profiles/MBench_S1002_v3.prw"   # SIMPACK .prw: unit from its header
//   wheel_profile_mm = "..." or wheel_profile_m = "..."  # plain text, unit in the key
//   rail_profile / rail_profile_mm / rail_profile_m  # likewise (.prr)
//   track_gauge_m, gauge_measuring_height_m, flange_back_distance_m,
//   nominal_rolling_radius_m, rail_inclination_rad,
//   tape_circle_from_flange_back_m                   # optional, defaults in profile_pair.hpp
// Paths are relative to the scene file. Other keys of the table belong to the
// scene loader (normal and tangential force models) and are not read here.
// Errors (ProfileError) read "<scene>: contacts.NAME.<key>: expected ..., got ...".
#include "profiles/profile_pair.hpp"

namespace railstab {

struct ProfileContactSpec {
  std::string name;
  std::string wheel_profile_path, rail_profile_path;  // resolved against the scene's folder
  LengthUnit wheel_unit = LengthUnit::millimetre, rail_unit = LengthUnit::millimetre;
  ProfilePairParameters parameters;
};

// contact_name empty: the only contact with geometry = "profiles" (an error
// lists them if there are several or none).
ProfileContactSpec read_profile_contact(const std::string& scene_path,
                                        const std::string& contact_name);

// Reads both files and places the pair.
ProfilePair load_profile_pair(const ProfileContactSpec& spec);

}  // namespace railstab
