#include <railstab/profiles/profile_validation.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace railstab {

const char* profile_kind_name(ProfileKind kind) {
  return kind == ProfileKind::wheel ? "wheel" : "rail";
}

namespace {

std::string at_line(const std::string& source, int line) {
  return line > 0 ? source + ":" + std::to_string(line) : source;
}

[[noreturn]] void fail(const std::string& where, const std::string& what) {
  throw ProfileError(where + ": " + what);
}

// Proper crossing of segments p1-p2 and p3-p4 (orientation tests); touching
// end points of neighbours are not crossings.
bool segments_cross(const RawProfilePoint& p1, const RawProfilePoint& p2,
                    const RawProfilePoint& p3, const RawProfilePoint& p4) {
  auto orient = [](const RawProfilePoint& a, const RawProfilePoint& b, const RawProfilePoint& c) {
    return (b.y_m - a.y_m) * (c.z_m - a.z_m) - (b.z_m - a.z_m) * (c.y_m - a.y_m);
  };
  const double d1 = orient(p3, p4, p1), d2 = orient(p3, p4, p2);
  const double d3 = orient(p1, p2, p3), d4 = orient(p1, p2, p4);
  return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

void check_self_intersection(const std::string& source, const std::vector<RawProfilePoint>& p) {
  const size_t n = p.size();
  for (size_t i = 0; i + 1 < n; ++i) {
    const double ylo = std::min(p[i].y_m, p[i + 1].y_m), yhi = std::max(p[i].y_m, p[i + 1].y_m);
    for (size_t j = i + 2; j + 1 < n; ++j) {
      if (std::max(p[j].y_m, p[j + 1].y_m) < ylo || std::min(p[j].y_m, p[j + 1].y_m) > yhi)
        continue;
      if (segments_cross(p[i], p[i + 1], p[j], p[j + 1])) {
        std::ostringstream msg;
        msg << "the profile intersects itself: the segment between lines " << p[i].line << " and "
            << p[i + 1].line << " crosses the segment between lines " << p[j].line << " and "
            << p[j + 1].line << "; expected a simple curve";
        fail(at_line(source, p[j].line), msg.str());
      }
    }
  }
}

// Orientation of a wheel profile's flange (profile.hpp frame: y outward, z
// up, the flange at negative y reaching DOWN, i.e. to larger radius).
// The flange is the part of the profile more than
// kWheelFlangeMinimumHeight_m away from the tape-circle height z_tape (z at
// y = 0, or at the end nearest to it). Two mistakes keep the profile a valid
// function z(y) with its inner end lower than its field end, so the check
// before this one passes them:
//   - rotated by 180 degrees ((y, z) -> (-y, -z)) or z mirrored with the
//     order reversed: the flange points UP and out, an interior highest
//     point above z_tape (a correct tread's highest point is its field end,
//     at most a chamfer of a few mm above z_tape);
//   - a flange (lowest point below z_tape) on the field side y > 0.
// Flangeless profiles (a cone, a hollow tread) have no part that far from
// z_tape inside the profile and pass.
void check_wheel_flange(const Profile& profile) {
  const std::vector<double>& y = profile.y_m;
  const std::vector<double>& z = profile.z_m;
  double z_tape = y.front() > 0.0 ? z.front() : z.back();
  for (size_t i = 1; i < y.size(); ++i)
    if (y[i - 1] <= 0.0 && y[i] >= 0.0) {
      z_tape = z[i - 1] + (z[i] - z[i - 1]) * (0.0 - y[i - 1]) / (y[i] - y[i - 1]);
      break;
    }
  const size_t top = size_t(std::max_element(z.begin(), z.end()) - z.begin());
  const size_t low = size_t(std::min_element(z.begin(), z.end()) - z.begin());
  const double h = kWheelFlangeMinimumHeight_m;
  if (top + 1 < z.size() && z[top] - z_tape > h) {
    std::ostringstream msg;
    msg << "the wheel profile rises to z = " << z[top] << " m at y = " << y[top]
        << " m, " << z[top] - z_tape << " m above the tape circle (z = " << z_tape
        << " m at y = 0), inside the profile: its flange points up (expected the flange at "
           "negative y reaching down, z up: r = r0 - z); is the profile rotated by 180 "
           "degrees or z mirrored (SIMPACK z points down)?";
    fail(at_line(profile.source, profile.line[top]), msg.str());
  }
  if (z_tape - z[low] > h && y[low] > 0.0) {
    std::ostringstream msg;
    msg << "the wheel profile's flange (its lowest point, z = " << z[low] << " m, "
        << z_tape - z[low] << " m below the tape circle) is at y = " << y[low]
        << " m, on the field side; expected the flange at negative y (y points outward): is "
           "y mirrored (SIMPACK mirror.y)?";
    fail(at_line(profile.source, profile.line[low]), msg.str());
  }
}

}  // namespace

Profile make_profile(ProfileKind kind, const std::string& source,
                     std::vector<RawProfilePoint> points) {
  const std::string what = profile_kind_name(kind);
  if (points.empty())
    fail(source, "contains no profile points; expected at least 4 lines of two numbers (y z)");
  for (const RawProfilePoint& p : points)
    if (!std::isfinite(p.y_m) || !std::isfinite(p.z_m))
      fail(at_line(source, p.line), "non-finite coordinate; expected finite numbers");

  // Drop points (almost) repeating their predecessor.
  std::vector<RawProfilePoint> kept{points.front()};
  for (size_t i = 1; i < points.size(); ++i) {
    const RawProfilePoint& q = kept.back();
    if (std::hypot(points[i].y_m - q.y_m, points[i].z_m - q.z_m) >= kMinimumProfilePointSpacing_m)
      kept.push_back(points[i]);
  }
  points.swap(kept);
  if (points.size() < 4) {
    std::ostringstream msg;
    msg << "has " << points.size() << " distinct profile point(s); expected at least 4";
    fail(source, msg.str());
  }

  // Size (unit) check.
  double ymin = points[0].y_m, ymax = ymin, abs_max = 0.0;
  int far_line = points[0].line;
  for (const RawProfilePoint& p : points) {
    ymin = std::min(ymin, p.y_m);
    ymax = std::max(ymax, p.y_m);
    const double a = std::max(std::abs(p.y_m), std::abs(p.z_m));
    if (a > abs_max) abs_max = a, far_line = p.line;
  }
  const double width = ymax - ymin;
  if (abs_max > kMaximumProfileCoordinate_m) {
    std::ostringstream msg;
    msg << "coordinate of magnitude " << abs_max << " m; expected |y|, |z| <= "
        << kMaximumProfileCoordinate_m << " m for a " << what
        << " profile: is the length unit right (millimetres read as metres?)";
    fail(at_line(source, far_line), msg.str());
  }
  if (width < kMinimumProfileWidth_m || width > kMaximumProfileWidth_m) {
    std::ostringstream msg;
    msg << "lateral extent of the " << what << " profile is " << width << " m; expected "
        << kMinimumProfileWidth_m << " .. " << kMaximumProfileWidth_m
        << " m: is the length unit right (metres read as millimetres?)";
    fail(source, msg.str());
  }

  check_self_intersection(source, points);

  // y strictly monotonic, in the direction set by the end points.
  const bool increasing = points.back().y_m > points.front().y_m;
  for (size_t i = 1; i < points.size(); ++i) {
    const double step = points[i].y_m - points[i - 1].y_m;
    if (increasing ? !(step > 0.0) : !(step < 0.0)) {
      std::ostringstream msg;
      msg << "lateral coordinate y = " << points[i].y_m << " m does not continue the "
          << (increasing ? "increasing" : "decreasing") << " order of the previous point (y = "
          << points[i - 1].y_m << " m, line " << points[i - 1].line
          << "); expected y strictly monotonic (the " << what
          << " profile must be a function z(y); trim overhanging parts)";
      fail(at_line(source, points[i].line), msg.str());
    }
  }
  if (!increasing) std::reverse(points.begin(), points.end());

  Profile profile;
  profile.kind = kind;
  profile.source = source;
  for (const RawProfilePoint& p : points) {
    profile.y_m.push_back(p.y_m);
    profile.z_m.push_back(p.z_m);
    profile.line.push_back(p.line);
  }

  if (kind == ProfileKind::wheel) {
    if (!(profile.z_m.front() < profile.z_m.back())) {
      std::ostringstream msg;
      msg << "the wheel profile is higher at its inner end (y = " << profile.y_m.front()
          << " m, z = " << profile.z_m.front() << " m) than at its field end (y = "
          << profile.y_m.back() << " m, z = " << profile.z_m.back()
          << " m); expected the flange at negative y (y points outward, z up): "
             "is the profile mirrored (SIMPACK mirror.y / mirror.z)?";
      fail(source, msg.str());
    }
    check_wheel_flange(profile);
  } else {
    const auto top = std::max_element(profile.z_m.begin(), profile.z_m.end());
    if (top == profile.z_m.begin() || top == profile.z_m.end() - 1) {
      fail(source,
           "the highest point of the rail profile is at an end of the profile; expected the "
           "rail head top inside the profile (z up): is z mirrored (SIMPACK z points down)?");
    }
  }
  return profile;
}

}  // namespace railstab
