#include <railstab/contact_geometry/profile_contact_geometry.hpp>

#include <railstab/profiles/profile_readers.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace railstab {

namespace {

// Steepest slope angle of the wheel profile between its flange tip (the
// largest radius: lowest z) and the tape circle (y = 0).
double flange_face_angle(const ProfilePair& pair) {
  const Profile& w = pair.wheel;
  const size_t tip = size_t(std::min_element(w.z_m.begin(), w.z_m.end()) - w.z_m.begin());
  double steepest = 0.0;
  const double y0 = w.y_m[tip], y1 = std::min(0.0, w.y_m.back());
  const int samples = 2000;
  for (int i = 0; i <= samples; ++i) {
    const double y = y0 + (y1 - y0) * i / samples;
    steepest = std::max(steepest, std::atan(pair.wheel_z.evaluate(y).df));
  }
  return steepest;
}

}  // namespace

std::shared_ptr<const ProfileContactGeometry> build_profile_contact_geometry(
    const ProfileSourceSpec& source, double nominal_rolling_radius_m) {
  Profile wheel = read_profile_file(source.wheel_profile_path, ProfileKind::wheel, source.wheel_unit);
  Profile rail = read_profile_file(source.rail_profile_path, ProfileKind::rail, source.rail_unit);
  ProfilePairParameters placement = source.placement;
  placement.nominal_rolling_radius_m = nominal_rolling_radius_m;
  auto g = std::make_shared<ProfileContactGeometry>();
  g->pair = make_profile_pair(std::move(wheel), std::move(rail), placement);
  g->table = make_contact_table(g->pair, source.table);
  g->flange_angle_rad = flange_face_angle(g->pair);
  // The centred wheelset, lowered onto its rail by the table's lowest gap,
  // must touch at a true contact point (a local minimum of the gap): a pair
  // that never meets, e.g. a wheel placed beside its rail, has none.
  const WheelPoseOf<double> centred =
      wheel_pose_in_rail_frame<double>(g->pair, +1, 0.0, 0.0, 0.0);
  const double lowest = g->table.lowest_vertical_gap(centred);
  const std::vector<ContactPoint> direct = find_contact_points(
      g->pair, WheelPose{centred.lateral_m, centred.vertical_m - lowest, centred.roll_rad});
  if (direct.empty()) {
    std::ostringstream msg;
    msg << "wheel profile " << g->pair.wheel.source << " and rail profile " << g->pair.rail.source
        << ": no contact point with the wheelset centred (expected the wheel's tread over the "
           "rail head; check track_gauge_m, flange_back_distance_m and the profiles' frames)";
    throw ProfileError(msg.str());
  }
  return g;
}

double nadal_limit(double flange_angle_rad, double friction_coefficient) {
  const double t = std::tan(flange_angle_rad);
  return (t - friction_coefficient) / (1.0 + friction_coefficient * t);
}

}  // namespace railstab
