#include <railstab/contact_geometry/table_rigid_contact.hpp>

#include <railstab/core/bracketed_root.hpp>
#include <railstab/contact_geometry/rigid_contact.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace railstab {

namespace {

struct SideGap {
  double lowest;
  int slot;
};

SideGap side_gap(const ProfileContactGeometry& g, int side, double y, double roll) {
  const WheelPoseOf<double> pose =
      wheel_pose_in_rail_frame<double>(g.pair_for(side), side, y, 0.0, roll);
  const ContactTable& t = g.table_for(side);
  SideGap s{t.vertical_gap<double>(0, pose), 0};
  for (int k = 1; k < t.slots(); ++k) {
    const double gap = t.vertical_gap<double>(k, pose);
    if (gap < s.lowest) s = {gap, k};
  }
  return s;
}

double mismatch(const ProfileContactGeometry& g, double y, double roll) {
  try {
    return side_gap(g, +1, y, roll).lowest - side_gap(g, -1, y, roll).lowest;
  } catch (const std::domain_error& e) {
    std::ostringstream msg;
    msg << "rigid contact on the contact table: lateral shift " << y * 1e3 << " mm, roll " << roll
        << " rad: " << e.what();
    throw ContactGeometryError(msg.str());
  }
}

TableWheelContact wheel_contact(const ProfileContactGeometry& g, int side, double y, double roll) {
  const SideGap s = side_gap(g, side, y, roll);
  const WheelPoseOf<double> pose =
      wheel_pose_in_rail_frame<double>(g.pair_for(side), side, y, 0.0, roll);
  const TableContact<double> c = g.table_for(side).evaluate<double>(s.slot, pose);
  TableWheelContact w;
  w.slot = s.slot;
  w.wheel_u_m = c.wheel_u_m;
  w.rail_y_m = c.rail_y_m;
  w.contact_angle_rad = c.contact_angle_rad;
  w.rolling_radius_m = c.rolling_radius_m;
  return w;
}

}  // namespace

TableRigidRow table_rigid_contact(const ProfileContactGeometry& g, double y, double roll_guess,
                                  LateralShiftReference reference) {
  // The centre's shift y_c for y in `reference` (rigid_contact.hpp).
  const double r0 = g.pairs().mean_nominal_rolling_radius_m();
  auto centre = [&](double roll) {
    return reference == LateralShiftReference::wheelset_centre ? y : y - r0 * std::sin(roll);
  };
  const BracketedRoot root =
      bracketed_root([&](double roll) { return mismatch(g, centre(roll), roll); }, roll_guess);
  if (!root.bracketed) {
    std::ostringstream msg;
    msg << "rigid contact on the contact table: no roll angle within +-" << root.half_width
        << " rad makes both wheels touch at lateral shift " << y * 1e3 << " mm";
    throw ContactGeometryError(msg.str());
  }
  const double roll = root.x;
  TableRigidRow r;
  r.lateral_m = y;
  r.centre_lateral_m = centre(roll);
  r.roll_rad = roll;
  r.left = wheel_contact(g, +1, r.centre_lateral_m, roll);
  r.right = wheel_contact(g, -1, r.centre_lateral_m, roll);
  return r;
}

std::vector<TableRigidRow> table_characteristic_functions(const ProfileContactGeometry& g,
                                                          double y_min_m, double y_max_m,
                                                          double step_m) {
  const int n = int(std::lround((y_max_m - y_min_m) / step_m));
  std::vector<TableRigidRow> rows(size_t(n + 1));
  const int first = std::clamp(int(std::lround(-y_min_m / step_m)), 0, n);
  double roll = 0.0;
  for (int i = first; i <= n; ++i) {
    rows[size_t(i)] = table_rigid_contact(g, y_min_m + i * step_m, roll);
    roll = rows[size_t(i)].roll_rad;
  }
  roll = rows[size_t(first)].roll_rad;
  for (int i = first - 1; i >= 0; --i) {
    rows[size_t(i)] = table_rigid_contact(g, y_min_m + i * step_m, roll);
    roll = rows[size_t(i)].roll_rad;
  }
  return rows;
}

}  // namespace railstab
