#pragma once
// Reading wheel and rail profiles from files into the profile frame of
// profile.hpp (metres, y outward, z up). Every error is a ProfileError naming
// the file, the line where one applies, and what was expected.
#include <railstab/profiles/profile.hpp>

namespace railstab {

// Plain text: one point per line, two numbers "y z" (separated by blanks, a
// comma or a semicolon) in `unit`, already in the profile frame. Blank lines
// and lines starting with '#', '!' or '%' are skipped.
Profile read_plain_profile(const std::string& path, ProfileKind kind, LengthUnit unit);

// SIMPACK .prw (wheel, header type = 1) or .prr (rail, type = 0). Honours
// units.len.f, shift.y/z, bound.y/z (when min < max), mirror.y/z and
// inversion in SIMPACK's order; rotate must be 0 (rejected otherwise); a third
// point column (spline weight) and approx.smooth are read and ignored: the
// profile is interpolated, not smoothed. SIMPACK's z points down and is negated.
Profile read_simpack_profile(const std::string& path, ProfileKind kind);

// By file extension: .prw/.prr -> SIMPACK (unit from the header); anything
// else -> plain text in `plain_unit`.
Profile read_profile_file(const std::string& path, ProfileKind kind, LengthUnit plain_unit);

}  // namespace railstab
