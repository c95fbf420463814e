#pragma once
// The wheel-rail contact of a scene with geometry = "profiles": the placed
// profile pair and its contact table, built once when the scene is read and
// shared (immutable) by every model built from it (a table costs ~0.1-0.2 s;
// the twins of the preload and curve set-up reuse it).
#include <railstab/contact_geometry/contact_tables.hpp>
#include <railstab/contact_geometry/profile_source.hpp>
#include <railstab/contact_geometry/rigid_contact.hpp>
#include <railstab/profiles/profile_pair.hpp>

#include <memory>
#include <optional>
#include <string>

namespace railstab {

struct ProfileContactGeometry {
  ProfilePair pair;  // the left wheel's (and the right's unless right_pair)
  ContactTable table;
  // An asymmetric wheelset (right_wheel_profile, right_rail_profile or
  // right_nominal_rolling_radius_m in the scene): the right wheel's own
  // placed pair, and right_table built from it. Empty: the right wheel is
  // the left's mirror image.
  std::optional<ProfilePair> right_pair;
  const ProfilePair& pair_for(int side) const {
    return side < 0 && right_pair ? *right_pair : pair;
  }
  bool asymmetric() const { return right_pair.has_value(); }
  WheelsetProfilePairs pairs() const { return WheelsetProfilePairs{pair, pair_for(-1)}; }
  // The right wheel's table where it differs from the left's (an
  // asymmetric wheelset: from right_pair; a quasi-linear contact about a
  // wheelset centre y_c != 0: quasi_linear_contact.hpp); empty: the right wheel is the left's mirror image on the same table.
  std::optional<ContactTable> right_table;
  const ContactTable& table_for(int side) const {
    return side < 0 && right_table ? *right_table : table;
  }
  // The steepest angle of the wheel's flange face (between the flange tip
  // and the tape circle), the angle of Nadal's derailment limit
  //   Y/Q = (tan(beta) - mu) / (1 + mu tan(beta)).
  double flange_angle_rad = 0.0;
  // Read from a table file (geometry = "table", contact_table_file.hpp): the
  // file, and `pair` holds only the placement numbers (wheel and rail
  // offsets, top of rail, r0; no profiles). Empty: built from profiles.
  std::string table_source;
  bool has_profiles() const { return table_source.empty(); }
  // The wheelset's lateral shift at which the rigid contact jumps onto the
  // flange (find_flange_contact), as the table file states it; for a
  // geometry built from profiles it is computed from them when needed.
  std::optional<double> flange_contact_shift_m;
};

// Reads both profile files, places the pair with `nominal_rolling_radius_m`
// and builds the table. Throws ProfileError naming the file (and line) or
// the placement key, and what was expected; also when the centred wheelset
// has no contact on either slot's table (profiles that do not touch).
std::shared_ptr<const ProfileContactGeometry> build_profile_contact_geometry(
    const ProfileSourceSpec& source, double nominal_rolling_radius_m);

// Nadal's limit for a flange angle and friction coefficient.
double nadal_limit(double flange_angle_rad, double friction_coefficient);

}  // namespace railstab
