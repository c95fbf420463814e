#pragma once
// Turning raw profile points into a checked Profile (profile.hpp frame).
#include <railstab/profiles/profile.hpp>

namespace railstab {

struct RawProfilePoint {
  double y_m, z_m;
  int line;  // line in the source file (0: none)
};

// Points closer than this to their predecessor are dropped (measured and CAD
// profiles repeat points at near-vertical ends; SIMPACK's point.dist.min
// default is of the same order).
inline constexpr double kMinimumProfilePointSpacing_m = 1e-6;

// Plausible sizes, to catch a wrong unit (metres read as millimetres gives
// extents of ~1e-4 m; millimetres read as metres ~10 m).
inline constexpr double kMinimumProfileWidth_m = 0.01;
inline constexpr double kMaximumProfileWidth_m = 0.4;
inline constexpr double kMaximumProfileCoordinate_m = 0.5;
// A wheel profile's flange is the part more than this from the tape-circle
// height (S1002: 28 mm; EN 15313's smallest admissible flange height 27.5 mm,
// tram flanges ~ 18 mm). A tread's chamfer or a hollow tread stays within a
// few mm, a cone of 1:10 over 60 mm within 6 mm: they are not flanges.
inline constexpr double kWheelFlangeMinimumHeight_m = 0.010;

// Checks, in this order, with a ProfileError naming `source`, the line and
// what was expected: at least 4 points; finite numbers; sizes in the plausible
// range (unit); no self-intersection; y strictly monotonic (either way; the
// result is stored with y increasing); for a wheel, the flange side (inner
// end, negative y) lower than the field side and its flange pointing down at
// negative y (not rotated by 180 degrees, not mirrored: check_wheel_flange in
// the .cpp); for a rail, the head top inside the profile (not at an end: an
// upside-down rail has its highest points at the ends).
Profile make_profile(ProfileKind kind, const std::string& source,
                     std::vector<RawProfilePoint> points);

}  // namespace railstab
