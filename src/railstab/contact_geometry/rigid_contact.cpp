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

SideGaps side_gaps(const ProfilePair& pair, int side, double y, double roll) {
  const WheelPoseOf<double> p = wheel_pose_in_rail_frame<double>(pair, side, y, 0.0, roll);
  SideGaps s;
  s.points = find_contact_points(pair, WheelPose{p.lateral_m, p.vertical_m, p.roll_rad});
  if (s.points.empty()) {
    std::ostringstream msg;
    msg << "no contact point between the " << (side > 0 ? "left" : "right") << " wheel ("
        << pair.wheel.source << ") and its rail (" << pair.rail.source
        << ") at a wheelset lateral shift of " << y * 1e3 << " mm and roll " << roll
        << " rad; expected the wheel tread above the rail head (check the gauge, the "
           "flange-back distance and the profile frames)";
    throw ContactGeometryError(msg.str());
  }
  s.lowest = s.points.front().vertical_gap_m;
  return s;
}

double mismatch(const ProfilePair& pair, double y, double roll) {
  return side_gaps(pair, +1, y, roll).lowest - side_gaps(pair, -1, y, roll).lowest;
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

RigidContactSolution solve_rigid_contact(const ProfilePair& pair, double y, double roll_guess) {
  // Bracket the root of f(phi) around the guess.
  const BracketedRoot root =
      bracketed_root([&](double roll) { return mismatch(pair, y, roll); }, roll_guess);
  if (!root.bracketed) {
    std::ostringstream msg;
    msg << "rigid contact: no roll angle within +-" << root.half_width
        << " rad makes both wheels touch at lateral shift " << y * 1e3 << " mm ("
        << pair.wheel.source << " on " << pair.rail.source << ")";
    throw ContactGeometryError(msg.str());
  }
  const double roll = root.x;
  RigidContactSolution s;
  s.lateral_m = y;
  s.roll_rad = roll;
  SideGaps left = side_gaps(pair, +1, y, roll), right = side_gaps(pair, -1, y, roll);
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
  RigidContactSolution s;
  try {
    s = solve_rigid_contact(pair, 0.0);
  } catch (const ContactGeometryError& e) {
    throw ContactGeometryError(std::string("wheel profile ") + pair.wheel.source +
                               " and rail profile " + pair.rail.source +
                               " have no contact at the nominal position (wheelset centred): " +
                               e.what());
  }
  const ContactPoint& c = s.left.front();
  const double margin = 1e-3;  // the contact must lie 1 mm inside both profiles
  if (c.rail_y_m < pair.rail.y_m.front() + margin || c.rail_y_m > pair.rail.y_m.back() - margin ||
      c.wheel_u_m < pair.wheel.y_m.front() + margin || c.wheel_u_m > pair.wheel.y_m.back() - margin) {
    std::ostringstream msg;
    msg << "wheel profile " << pair.wheel.source << " and rail profile " << pair.rail.source
        << " have no proper contact at the nominal position: the centred wheelset touches at "
        << c.wheel_u_m * 1e3 << " mm on the wheel and " << c.rail_y_m * 1e3
        << " mm on the rail, within 1 mm of a profile end; expected a contact inside both "
           "profiles (check track_gauge_m, flange_back_distance_m and the profile frames)";
    throw ContactGeometryError(msg.str());
  }
}

}  // namespace railstab
