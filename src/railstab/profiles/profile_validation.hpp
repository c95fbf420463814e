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

// Checks, in this order, with a ProfileError naming `source`, the line and
// what was expected: at least 4 points; finite numbers; sizes in the plausible
// range (unit); no self-intersection; y strictly monotonic (either way; the
// result is stored with y increasing); for a wheel, the flange side (inner
// end, negative y) lower than the field side; for a rail, the head top inside
// the profile (not at an end).
Profile make_profile(ProfileKind kind, const std::string& source,
                     std::vector<RawProfilePoint> points);

}  // namespace railstab
