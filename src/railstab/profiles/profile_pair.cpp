#include <railstab/profiles/profile_pair.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace railstab {
namespace {

void require_range(double value, double lo, double hi, const char* key, const char* unit) {
  if (!(value >= lo && value <= hi) || !std::isfinite(value)) {
    std::ostringstream msg;
    msg << key << ": expected a number in [" << lo << ", " << hi << "] " << unit << ", got "
        << value;
    throw ProfileError(msg.str());
  }
}

// Innermost crossing of the height z_level by the rail polyline, walking from
// the top towards negative y (the gauge side).
double gauge_point(const Profile& rail, size_t top, double z_level) {
  for (size_t i = top; i > 0; --i) {
    const double z0 = rail.z_m[i], z1 = rail.z_m[i - 1];
    if (z0 >= z_level && z1 < z_level) {
      const double w = (z0 - z_level) / (z0 - z1);
      return rail.y_m[i] + w * (rail.y_m[i - 1] - rail.y_m[i]);
    }
  }
  std::ostringstream msg;
  msg << rail.source << ": the rail profile does not reach the gauge measuring height ("
      << z_level << " m in the profile frame) on its gauge side (negative y); expected a "
      << "rail head whose gauge face extends at least gauge_measuring_height_m below its top";
  throw ProfileError(msg.str());
}

}  // namespace

ProfilePair make_profile_pair(Profile wheel, Profile rail, const ProfilePairParameters& p) {
  require_range(p.track_gauge_m, 0.5, 2.0, "track_gauge_m", "m");
  require_range(p.gauge_measuring_height_m, 0.0, 0.05, "gauge_measuring_height_m", "m");
  require_range(p.flange_back_distance_m, 0.4, p.track_gauge_m, "flange_back_distance_m",
                "m (below the track gauge)");
  require_range(p.nominal_rolling_radius_m, 0.1, 1.0, "nominal_rolling_radius_m", "m");
  require_range(p.rail_inclination_rad, -0.1, 0.1, "rail_inclination_rad", "rad");
  require_range(p.tape_circle_from_flange_back_m, 0.0, 0.2, "tape_circle_from_flange_back_m",
                "m");
  if (wheel.kind != ProfileKind::wheel || rail.kind != ProfileKind::rail)
    throw ProfileError("make_profile_pair: expected a wheel profile and a rail profile");

  if (p.rail_inclination_rad != 0.0) {
    const double c = std::cos(p.rail_inclination_rad), s = std::sin(p.rail_inclination_rad);
    for (size_t i = 0; i < rail.y_m.size(); ++i) {
      const double y = rail.y_m[i], z = rail.z_m[i];
      rail.y_m[i] = y * c - z * s;
      rail.z_m[i] = y * s + z * c;
    }
    for (size_t i = 1; i < rail.y_m.size(); ++i)
      if (!(rail.y_m[i] > rail.y_m[i - 1])) {
        std::ostringstream msg;
        msg << rail.source << ":" << rail.line[i] << ": after the rail inclination of "
            << p.rail_inclination_rad
            << " rad the rail profile is no longer a function z(y); expected near-vertical "
               "flanks to stay monotonic (trim the flanks of the profile)";
        throw ProfileError(msg.str());
      }
  }

  ProfilePair pair;
  pair.parameters = p;
  const size_t top = size_t(std::max_element(rail.z_m.begin(), rail.z_m.end()) - rail.z_m.begin());
  pair.rail_top_y_m = rail.y_m[top];
  pair.rail_top_z_m = rail.z_m[top];
  if (p.rail_gauge_point_y_m) {
    const double y = *p.rail_gauge_point_y_m;
    if (!(y >= rail.y_m.front() && y <= rail.y_m.back())) {
      std::ostringstream msg;
      msg << "rail_gauge_point_y_m: expected a y within the rail profile " << rail.source << " ("
          << rail.y_m.front() << " .. " << rail.y_m.back() << " m, after the inclination), got "
          << y;
      throw ProfileError(msg.str());
    }
    pair.gauge_point_y_m = y;
  } else {
    pair.gauge_point_y_m = gauge_point(rail, top, pair.rail_top_z_m - p.gauge_measuring_height_m);
  }
  pair.rail_offset_y_m = 0.5 * p.track_gauge_m - pair.gauge_point_y_m;
  pair.wheel_offset_y_m = 0.5 * p.flange_back_distance_m + p.tape_circle_from_flange_back_m;
  pair.wheel_z = CubicSpline(wheel.y_m, wheel.z_m);
  pair.rail_z = CubicSpline(rail.y_m, rail.z_m);
  pair.wheel = std::move(wheel);
  pair.rail = std::move(rail);
  return pair;
}

}  // namespace railstab
