#pragma once
// Wheel and rail profiles: the frames and sign conventions, in one place.
//
// PROFILE FRAME (both profiles; every length in metres)
//   y  lateral, positive from the track centre OUTWARD (towards the field side)
//   z  vertical, positive UP
//   A profile is a curve z(y), single-valued in y, stored with y increasing.
//   The same frame serves the left and the right side: the right wheel and
//   rail are the mirror images (y_track -> -y_track) of the left ones.
//
//   Wheel profile: the curve of the wheel's running surface seen in a plane
//   through the axle (the lower generator of the surface of revolution).
//   Origin at the tape (measuring) circle: y = 0 is the tape-circle plane,
//   z = 0 the nominal rolling circle, so the wheel radius at y is
//     r(y) = r0 - z(y)            (r0 = nominal_rolling_radius_m).
//   The flange lies at negative y and reaches down (negative z): S1002's
//   flange tip is at y ~ -55 mm, z ~ -28 mm. The flange back (inner face of
//   the wheel) is at y = -tape_circle_from_flange_back_m (70 mm for EN 13715
//   profiles such as S1002).
//
//   Rail profile: the rail head cross-section, gauge face at negative y, as
//   given by the file (a rail given upright is inclined by
//   rail_inclination_rad when the pair is placed, see profile_pair.hpp).
//
// TRACK FRAME T (as everywhere in railstab): x along the track, y to the
// LEFT, z up, origin on the track centre line in the plane of the rail tops.
// The left rail/wheel profile frame maps to T by y_T = +(offset + y),
// the right one by y_T = -(offset + y); z is shared up to an offset
// (profile_pair.hpp states the offsets).
//
// FILES
//   plain text: two columns y z (in the unit the caller names: mm or m), in
//     this frame (y outward, z up), either order of y. Lines starting with
//     '#', '!' or '%' and blank lines are comments.
//   SIMPACK .prw/.prr: y and z in the header's length unit (units.len.f =
//     length unit per metre) with z pointing DOWN; shift.y/z, bound.*,
//     mirror.y/z and inversion are applied in SIMPACK's order, then z is
//     negated. After mirror.y the SIMPACK y already points outward (checked:
//     a wheel's flange must end up at negative y).
#include <stdexcept>
#include <string>
#include <vector>

namespace railstab {

enum class ProfileKind { wheel, rail };
const char* profile_kind_name(ProfileKind kind);

enum class LengthUnit { millimetre, metre };

// Every error about a profile file: the message names the file, the line
// where one applies, and what was expected.
struct ProfileError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

struct Profile {
  ProfileKind kind = ProfileKind::rail;
  std::string source;          // file name (or a description) for messages
  std::vector<double> y_m;     // strictly increasing
  std::vector<double> z_m;
  std::vector<int> line;       // file line of each point (0: not from a file)
};

}  // namespace railstab
