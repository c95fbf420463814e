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

// The centred wheel on `side`, lowered onto its rail by the table's lowest
// gap, must touch at a true contact point (a local minimum of the gap): a
// pair that never meets, e.g. a wheel placed beside its rail, has none.
void require_centred_contact(const ProfileContactGeometry& g, int side) {
  const ProfilePair& pair = g.pair_for(side);
  const WheelPoseOf<double> centred = wheel_pose_in_rail_frame<double>(pair, side, 0.0, 0.0, 0.0);
  const double lowest = g.table_for(side).lowest_vertical_gap(centred);
  const std::vector<ContactPoint> direct = find_contact_points(
      pair, WheelPose{centred.lateral_m, centred.vertical_m - lowest, centred.roll_rad});
  if (direct.empty()) {
    std::ostringstream msg;
    msg << "wheel profile " << pair.wheel.source << " and rail profile " << pair.rail.source
        << (g.asymmetric() ? (side > 0 ? " (left)" : " (right)") : "")
        << ": no contact point with the wheelset centred (expected the wheel's tread over the "
           "rail head; check track_gauge_m, flange_back_distance_m and the profiles' frames)";
    throw ProfileError(msg.str());
  }
}

}  // namespace

std::shared_ptr<const ProfileContactGeometry> build_profile_contact_geometry(
    const ProfileSourceSpec& source, double nominal_rolling_radius_m) {
  Profile wheel = read_profile_file(source.wheel_profile_path, ProfileKind::wheel, source.wheel_unit);
  Profile rail = read_profile_file(source.rail_profile_path, ProfileKind::rail, source.rail_unit);
  ProfilePairParameters placement = source.placement;
  placement.nominal_rolling_radius_m = nominal_rolling_radius_m;
  auto g = std::make_shared<ProfileContactGeometry>();
  if (source.asymmetric()) {
    // The right wheel's pair: its own files, radius and gauge point where
    // given, the left's otherwise; placed as the mirror image (same gauge,
    // flange-back distance and tape-circle position).
    Profile right_wheel = source.right_wheel_profile_path.empty()
                              ? wheel
                              : read_profile_file(source.right_wheel_profile_path,
                                                  ProfileKind::wheel, source.right_wheel_unit);
    Profile right_rail = source.right_rail_profile_path.empty()
                             ? rail
                             : read_profile_file(source.right_rail_profile_path, ProfileKind::rail,
                                                 source.right_rail_unit);
    ProfilePairParameters right_placement = placement;
    if (source.right_nominal_rolling_radius_m)
      right_placement.nominal_rolling_radius_m = *source.right_nominal_rolling_radius_m;
    if (source.right_rail_gauge_point_y_m)
      right_placement.rail_gauge_point_y_m = *source.right_rail_gauge_point_y_m;
    else if (!source.right_rail_profile_path.empty() && placement.rail_gauge_point_y_m)
      throw ProfileError(
          "right_rail_gauge_point_y_m: expected the right rail file's gauge point (the right "
          "rail is another file than the left, whose rail_gauge_point_y_m is given), got none");
    try {
      g->right_pair = make_profile_pair(std::move(right_wheel), std::move(right_rail),
                                        right_placement);
    } catch (const ProfileError& e) {
      throw ProfileError(std::string("right wheel: ") + e.what());
    }
  }
  g->pair = make_profile_pair(std::move(wheel), std::move(rail), placement);
  g->table = make_contact_table(g->pair, source.table);
  // The right wheel's table: its slot borders from its own pair (where its
  // contact jumps along the wheel when both wheels have its profile).
  if (g->right_pair) g->right_table = make_contact_table(*g->right_pair, source.table);
  g->flange_angle_rad = flange_face_angle(g->pair);
  if (g->right_pair)
    g->flange_angle_rad = std::min(g->flange_angle_rad, flange_face_angle(*g->right_pair));
  require_centred_contact(*g, +1);
  if (g->asymmetric()) require_centred_contact(*g, -1);
  return g;
}

double nadal_limit(double flange_angle_rad, double friction_coefficient) {
  const double t = std::tan(flange_angle_rad);
  return (t - friction_coefficient) / (1.0 + friction_coefficient * t);
}

}  // namespace railstab
