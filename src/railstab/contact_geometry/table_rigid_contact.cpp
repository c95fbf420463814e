#include <railstab/contact_geometry/table_rigid_contact.hpp>

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
  const WheelPoseOf<double> pose = wheel_pose_in_rail_frame<double>(g.pair, side, y, 0.0, roll);
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
  const WheelPoseOf<double> pose = wheel_pose_in_rail_frame<double>(g.pair, side, y, 0.0, roll);
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

TableRigidRow table_rigid_contact(const ProfileContactGeometry& g, double y, double roll_guess) {
  double a = roll_guess - 1e-3, b = roll_guess + 1e-3;
  double fa = mismatch(g, y, a), fb = mismatch(g, y, b);
  for (int expand = 0; fa * fb > 0.0; ++expand) {
    if (expand > 12) {
      std::ostringstream msg;
      msg << "rigid contact on the contact table: no roll angle within +-" << b - roll_guess
          << " rad makes both wheels touch at lateral shift " << y * 1e3 << " mm";
      throw ContactGeometryError(msg.str());
    }
    const double w = b - a;
    if (std::abs(fa) < std::abs(fb)) a -= w, fa = mismatch(g, y, a);
    else b += w, fb = mismatch(g, y, b);
  }
  int side = 0;
  double roll = a;
  for (int it = 0; it < 100; ++it) {  // Illinois variant of regula falsi
    roll = (a * fb - b * fa) / (fb - fa);
    if (!(roll > a && roll < b)) roll = 0.5 * (a + b);
    const double fr = mismatch(g, y, roll);
    if (fr == 0.0 || b - a < 1e-14) break;
    if (fr * fb > 0.0) {
      b = roll, fb = fr;
      if (side == -1) fa *= 0.5;
      side = -1;
    } else {
      a = roll, fa = fr;
      if (side == +1) fb *= 0.5;
      side = +1;
    }
    if (std::abs(fr) < 1e-14) break;
  }
  TableRigidRow r;
  r.lateral_m = y;
  r.roll_rad = roll;
  r.left = wheel_contact(g, +1, y, roll);
  r.right = wheel_contact(g, -1, y, roll);
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
