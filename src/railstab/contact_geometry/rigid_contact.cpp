#include <railstab/contact_geometry/rigid_contact.hpp>

#include <railstab/core/bracketed_root.hpp>
#include <railstab/contact_geometry/wheelset_pose.hpp>

#include <cmath>
#include <sstream>

namespace railstab {
namespace {

struct SideGaps {
  std::vector<ContactPoint> points;
  double lowest;  // lowest gap at z = 0 (offset by the pose's vertical)
};

SideGaps side_gaps(const WheelsetProfilePairs& pairs, int side, double y, double roll) {
  const ProfilePair& pair = pairs.side(side);
  const WheelPoseOf<double> p = wheel_pose_in_rail_frame<double>(pair, side, y, 0.0, roll);
  SideGaps s;
  s.points = find_contact_points(pair, WheelPose{p.lateral_m, p.vertical_m, p.roll_rad});
  if (s.points.empty()) {
    std::ostringstream msg;
    msg << "no contact point between the " << (side > 0 ? "left" : "right") << " wheel ("
        << pair.wheel.source << ") and its rail (" << pair.rail.source
        << ") at a wheelset centre shift of " << y * 1e3 << " mm and roll " << roll
        << " rad; expected the wheel tread above the rail head (check the gauge, the "
           "flange-back distance and the profile frames)";
    throw ContactGeometryError(msg.str());
  }
  s.lowest = s.points.front().vertical_gap_m;
  return s;
}

double mismatch(const WheelsetProfilePairs& pairs, double y_c, double roll) {
  return side_gaps(pairs, +1, y_c, roll).lowest - side_gaps(pairs, -1, y_c, roll).lowest;
}

// The wheelset centre's shift for a shift y in `reference` at roll phi.
double centre_shift(const WheelsetProfilePairs& pairs, double y, double roll,
                    LateralShiftReference reference) {
  if (reference == LateralShiftReference::wheelset_centre) return y;
  return y - pairs.mean_nominal_rolling_radius_m() * std::sin(roll);
}

}  // namespace

int RigidContactSolution::contacts_left() const {
  int n = 0;
  for (const ContactPoint& p : left) n += p.vertical_gap_m <= kSecondContactGapTolerance_m;
  return n;
}
int RigidContactSolution::contacts_right() const {
  int n = 0;
  for (const ContactPoint& p : right) n += p.vertical_gap_m <= kSecondContactGapTolerance_m;
  return n;
}

RigidContactSolution solve_rigid_contact(const WheelsetProfilePairs& pairs, double y,
                                         double roll_guess, LateralShiftReference reference) {
  // Bracket the root of f(phi) around the guess.
  const BracketedRoot root = bracketed_root(
      [&](double roll) { return mismatch(pairs, centre_shift(pairs, y, roll, reference), roll); },
      roll_guess);
  if (!root.bracketed) {
    std::ostringstream msg;
    msg << "rigid contact: no roll angle within +-" << root.half_width
        << " rad makes both wheels touch at lateral shift " << y * 1e3 << " mm ("
        << pairs.left.wheel.source << " on " << pairs.left.rail.source << ")";
    throw ContactGeometryError(msg.str());
  }
  const double roll = root.x;
  const double y_c = centre_shift(pairs, y, roll, reference);
  RigidContactSolution s;
  s.lateral_m = y;
  s.centre_lateral_m = y_c;
  s.roll_rad = roll;
  SideGaps left = side_gaps(pairs, +1, y_c, roll), right = side_gaps(pairs, -1, y_c, roll);
  // Height: the left wheel's lowest gap vanishes; shift both sides' gaps.
  s.vertical_m = -left.lowest;
  for (ContactPoint& p : left.points) {
    p.vertical_gap_m -= left.lowest;
    p.normal_gap_m = p.vertical_gap_m * std::cos(p.contact_angle_rad);
  }
  for (ContactPoint& p : right.points) {
    p.vertical_gap_m -= left.lowest;
    p.normal_gap_m = p.vertical_gap_m * std::cos(p.contact_angle_rad);
  }
  s.left = std::move(left.points);
  s.right = std::move(right.points);
  return s;
}

void require_contact_at_nominal_position(const ProfilePair& pair) {
  require_contact_at_nominal_position(WheelsetProfilePairs{pair, pair});
}

void require_contact_at_nominal_position(const WheelsetProfilePairs& pairs) {
  RigidContactSolution s;
  try {
    s = solve_rigid_contact(pairs, 0.0, 0.0, LateralShiftReference::wheelset_centre);
  } catch (const ContactGeometryError& e) {
    throw ContactGeometryError(std::string("wheel profile ") + pairs.left.wheel.source +
                               " and rail profile " + pairs.left.rail.source +
                               " have no contact at the nominal position (wheelset centred): " +
                               e.what());
  }
  for (int side : {+1, -1}) {
    const ProfilePair& pair = pairs.side(side);
    const ContactPoint& c = side > 0 ? s.left.front() : s.right.front();
    const double margin = 1e-3;  // the contact must lie 1 mm inside both profiles
    if (c.rail_y_m < pair.rail.y_m.front() + margin || c.rail_y_m > pair.rail.y_m.back() - margin ||
        c.wheel_u_m < pair.wheel.y_m.front() + margin ||
        c.wheel_u_m > pair.wheel.y_m.back() - margin) {
      std::ostringstream msg;
      msg << "wheel profile " << pair.wheel.source << " and rail profile " << pair.rail.source
          << " have no proper contact at the nominal position: the centred wheelset touches at "
          << c.wheel_u_m * 1e3 << " mm on the wheel and " << c.rail_y_m * 1e3
          << " mm on the rail, within 1 mm of a profile end; expected a contact inside both "
             "profiles (check track_gauge_m, flange_back_distance_m and the profile frames)";
      throw ContactGeometryError(msg.str());
    }
  }
}

}  // namespace railstab
