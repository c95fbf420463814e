#include <railstab/contact_geometry/quasi_linear_contact.hpp>

#include <railstab/contact_geometry/characteristic_functions.hpp>
#include <railstab/contact_geometry/harmonic_linearisation.hpp>
#include <railstab/contact_geometry/rigid_contact.hpp>
#include <railstab/contact_geometry/wheelset_pose.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace railstab {
namespace {

// The table quantity a rigid function becomes (count: none).
TableQuantity table_quantity_of(RigidFunction f) {
  switch (f) {
    case RigidFunction::gap0_m: return TableQuantity::gap0_m;
    case RigidFunction::wheel_u_m: return TableQuantity::wheel_u_m;
    case RigidFunction::rail_y_m: return TableQuantity::rail_y_m;
    case RigidFunction::contact_angle_rad: return TableQuantity::contact_angle_rad;
    case RigidFunction::rolling_radius_m: return TableQuantity::rolling_radius_m;
    case RigidFunction::A_per_m: return TableQuantity::A_per_m;
    case RigidFunction::B_per_m: return TableQuantity::B_per_m;
    default: return TableQuantity::count;
  }
}

double table_value(const ContactTable& t, int slot, TableQuantity q, const WheelPoseOf<double>& p) {
  if (q == TableQuantity::gap0_m) return t.vertical_gap<double>(slot, {p.lateral_m, 0.0, p.roll_rad});
  const TableContact<double> c = t.evaluate<double>(slot, p);
  switch (q) {
    case TableQuantity::wheel_u_m: return c.wheel_u_m;
    case TableQuantity::rail_y_m: return c.rail_y_m;
    case TableQuantity::contact_angle_rad: return c.contact_angle_rad;
    case TableQuantity::rolling_radius_m: return c.rolling_radius_m;
    case TableQuantity::A_per_m: return c.A_per_m;
    case TableQuantity::B_per_m: return c.B_per_m;
    default: return 0.0;
  }
}

}  // namespace

QuasiLinearContact::QuasiLinearContact(std::shared_ptr<const ProfileContactGeometry> geometry,
                                       double sample_step_m)
    : geometry_(std::move(geometry)) {
  if (!geometry_) throw std::invalid_argument("QuasiLinearContact: no profile contact geometry");
  if (!(sample_step_m > 0.0))
    throw std::invalid_argument("QuasiLinearContact: expected a positive sample step");
  if (geometry_->asymmetric())
    throw std::invalid_argument(
        "quasi-linear contact: expected a symmetric wheelset (its rigid-contact functions are "
        "taken as odd in y), got an asymmetric one (right_wheel_profile, right_rail_profile, "
        "right_nominal_rolling_radius_m or right_rail_gauge_point_y_m in the contact)");
  const ProfilePair& pair = geometry_->pair;
  const ContactTable& table = geometry_->table;
  const double reach = table.options().lateral_half_range_m - 1e-3;
  const int n = int(std::floor(reach / sample_step_m));
  // Outwards from the centre both ways (roll continued from sample to
  // sample); the range ends where the rigid contact has no solution.
  auto side = [&](int dir) {
    std::vector<RigidContactSolution> out;
    double roll = 0.0;
    for (int i = 0; i <= n; ++i) {
      try {
        out.push_back(solve_rigid_contact(pair, dir * i * sample_step_m, roll));
      } catch (const ContactGeometryError&) {
        break;
      }
      roll = out.back().roll_rad;
    }
    return out;
  };
  const std::vector<RigidContactSolution> plus = side(+1), minus = side(-1);
  const size_t m = std::min(plus.size(), minus.size());
  if (m < 3) {
    std::ostringstream msg;
    msg << "quasi-linear contact of " << pair.wheel.source << " on " << pair.rail.source
        << ": the rigid contact has no solution within " << 2 * sample_step_m * 1e3
        << " mm of the centred wheelset (expected a pair that touches)";
    throw ContactGeometryError(msg.str());
  }
  const double nominal = table.nominal_lateral_m();
  auto record = [&](const RigidContactSolution& s) {
    const WheelPoseOf<double> p =
        wheel_pose_in_rail_frame<double>(pair, +1, s.lateral_m, s.vertical_m, s.roll_rad);
    const ContactPoint& c = s.left.front();
    y_m_.push_back(s.lateral_m);
    const double values[kRigidFunctions] = {p.lateral_m - nominal, p.roll_rad,   -p.vertical_m,
                                            c.wheel_u_m,           c.rail_y_m,   c.contact_angle_rad,
                                            c.rolling_radius_m,    c.A_per_m,    c.B_per_m};
    for (int k = 0; k < kRigidFunctions; ++k) f_[size_t(k)].push_back(values[k]);
  };
  for (size_t i = m; i-- > 1;) record(minus[i]);
  for (size_t i = 0; i < m; ++i) record(plus[i]);
  for (size_t i = 0; i < m; ++i)
    if (plus[i].left.front().contact_angle_rad > kFlangeContactAngle_rad) {
      flange_contact_m_ = plus[i].lateral_m;
      break;
    }
}

double QuasiLinearContact::function(RigidFunction f, double y) const {
  if (!(y >= y_m_.front() && y <= y_m_.back())) {
    std::ostringstream msg;
    msg << "quasi-linear contact: wheelset shift " << y * 1e3 << " mm outside the sampled "
        << y_m_.front() * 1e3 << " .. " << y_m_.back() * 1e3 << " mm";
    throw std::invalid_argument(msg.str());
  }
  const std::vector<double>& v = f_[size_t(int(f))];
  const size_t i = std::clamp(size_t(std::upper_bound(y_m_.begin(), y_m_.end(), y) - y_m_.begin()),
                              size_t(1), y_m_.size() - 1);
  const double w = (y - y_m_[i - 1]) / (y_m_[i] - y_m_[i - 1]);
  return v[i - 1] + w * (v[i] - v[i - 1]);
}

QuasiLinearGains QuasiLinearContact::gains(double centre_m, double amplitude_m) const {
  if (!(amplitude_m > 0.0) || !std::isfinite(amplitude_m) || !std::isfinite(centre_m) ||
      std::abs(centre_m) + amplitude_m > half_range_m()) {
    std::ostringstream msg;
    msg << "quasi-linear contact: amplitude " << amplitude_m * 1e3 << " mm about the steady shift "
        << centre_m * 1e3 << " mm: expected 0 < amplitude and |shift| + amplitude <= "
        << half_range_m() * 1e3 << " mm (the contact table's lateral range less 1 mm)";
    throw std::invalid_argument(msg.str());
  }
  QuasiLinearGains g;
  g.centre_m = centre_m;
  g.amplitude_m = amplitude_m;
  // The samples between c - A and c + A are the breakpoints of the
  // interpolated functions.
  const auto lo = std::lower_bound(y_m_.begin(), y_m_.end(), centre_m - amplitude_m);
  const auto hi = std::upper_bound(y_m_.begin(), y_m_.end(), centre_m + amplitude_m);
  const std::vector<double> breaks(lo, hi);
  for (int k = 0; k < kRigidFunctions; ++k) {
    const RigidFunction f = RigidFunction(k);
    const HarmonicLinearisation h = harmonic_linearisation(
        [&](double y) { return function(f, y); }, centre_m, amplitude_m, breaks);
    g.at_centre[size_t(k)] = function(f, centre_m);
    g.gain[size_t(k)] = h.gain;
    g.bias[size_t(k)] = h.bias;
  }
  // delta r(y) = r_L(y) - r_L(-y): about y_c, the second term is the left
  // wheel's radius about -y_c, traversed backwards (gain unchanged in sign:
  // d/dy of -r_L(-y) is +r_L'(-y)).
  double right_gain = g.gain[size_t(int(RigidFunction::rolling_radius_m))];
  if (centre_m != 0.0) {
    const auto lo2 = std::lower_bound(y_m_.begin(), y_m_.end(), -centre_m - amplitude_m);
    const auto hi2 = std::upper_bound(y_m_.begin(), y_m_.end(), -centre_m + amplitude_m);
    right_gain = harmonic_linearisation(
                     [&](double y) { return function(RigidFunction::rolling_radius_m, y); },
                     -centre_m, amplitude_m, std::vector<double>(lo2, hi2))
                     .gain;
  }
  g.equivalent_conicity = 0.5 * (g.gain[size_t(int(RigidFunction::rolling_radius_m))] + right_gain);
  return g;
}

ContactTable QuasiLinearContact::equivalent_table(double centre_m, double amplitude_m) const {
  const ContactTable& table = geometry_->table;
  const QuasiLinearGains g = gains(centre_m, amplitude_m);
  auto at = [&](RigidFunction f) { return g.at_centre[size_t(int(f))]; };
  auto gain = [&](RigidFunction f) { return g.gain[size_t(int(f))]; };
  const double q_c = at(RigidFunction::lateral_q_m), theta_c = at(RigidFunction::roll_theta_rad);
  const double N_q = gain(RigidFunction::lateral_q_m), N_theta = gain(RigidFunction::roll_theta_rad);
  if (!(std::abs(N_q) > 1e-6)) {
    std::ostringstream msg;
    msg << "quasi-linear contact: the wheel's lateral displacement does not follow the wheelset's "
           "(gain "
        << N_q << ") at amplitude " << amplitude_m * 1e3 << " mm";
    throw ContactGeometryError(msg.str());
  }
  // The loaded slot of the profile table at the rigid pose: the lowest gap
  // among the slots whose lowest point is interior.
  const WheelPoseOf<double> pose{table.nominal_lateral_m() + q_c, 0.0, theta_c};
  int slot = -1;
  double lowest = std::numeric_limits<double>::infinity();
  for (int k = 0; k < table.slots(); ++k) {
    const TableContact<double> c = table.evaluate<double>(k, pose);
    if (c.on_border < 0.5 && c.vertical_gap_m < lowest) lowest = c.vertical_gap_m, slot = k;
  }
  if (slot < 0) slot = 0;
  // d/dtheta at fixed q by central differences on the C1 table
  // (h = 1e-5 rad, 1/500 of a roll cell).
  const double h = 1e-5;
  const WheelPoseOf<double> up{pose.lateral_m, 0.0, theta_c + h}, down{pose.lateral_m, 0.0, theta_c - h};
  std::array<ContactTable::Plane, kTableQuantities> planes{};
  for (int k = 0; k < kRigidFunctions; ++k) {
    const RigidFunction f = RigidFunction(k);
    const TableQuantity q = table_quantity_of(f);
    if (q == TableQuantity::count) continue;
    const double b = (table_value(table, slot, q, up) - table_value(table, slot, q, down)) / (2 * h);
    ContactTable::Plane& p = planes[size_t(int(q))];
    p.at_centre = at(f);
    p.d_dtheta = b;
    p.d_dq = (gain(f) - b * N_theta) / N_q;
  }
  // on_border: 0 (the one contact point is a true contact everywhere).
  return ContactTable::plane_table(table.options(), table.nominal_lateral_m(), q_c, theta_c, planes);
}

std::shared_ptr<const ProfileContactGeometry> QuasiLinearContact::equivalent_geometry(
    double centre_m, double amplitude_m) const {
  auto g = std::make_shared<ProfileContactGeometry>();
  g->pair = geometry_->pair;
  g->flange_angle_rad = geometry_->flange_angle_rad;
  g->table = equivalent_table(centre_m, amplitude_m);
  if (centre_m != 0.0) g->right_table = equivalent_table(-centre_m, amplitude_m);
  return g;
}

}  // namespace railstab
