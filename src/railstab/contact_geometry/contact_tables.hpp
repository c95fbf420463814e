#pragma once
// Precomputed contact tables of one wheel on its rail for the elastic
// (penetration) contact model, evaluated inside the multibody right-hand side.
//
// Table variables (the wheel's pose in its rail frame, wheelset_pose.hpp):
//   q     = lateral - nominal_wheel_lateral: the wheel's lateral displacement
//           relative to its rail from the centred position (outward +);
//   theta = roll of the wheel profile relative to the rail (s * phi).
// The vertical pose enters exactly: the vertical gap of a contact is
// g0(q, theta) + vertical (the search for the minimum of the vertical gap
// does not depend on the vertical position).
//
// Slots: the wheel profile is split into parts at the borders where the rigid
// contact jumps along the wheel (contact_jump_borders in
// characteristic_functions.hpp: the part of the wheel between a jump's ends
// never carries a rigid contact); slot k holds the lowest point of the gap
// over part k, from the field side (slot 0) inwards to the flange (last
// slot). A cone has one slot; S1002 on UIC60 1:40 has five (borders at
// u ~ 16, -3, -23 and -36 mm: a field-side jump, the near-conformal tread
// jump at y ~ 0.2 mm, the jump to the flange root at ~4.8 mm and onto the
// flange face at 6.25 mm; test ContactTables.BenchmarkPairHasTreadAndFlangeSlots).
// Each slot is one contact with its own Hertz ellipse, so tread and flange
// (and the two tread contacts of a near-conformal pair) act together. A
// slot's lowest point may lie on its border (the part has no local minimum):
// the gap stays continuous there, the contact position kinks; such a
// "border" contact is reported (on_border > 0.5); overlap at a border contact
// double-counts its neighbour's, so the force law should ignore it (the
// measured extent is ContactTableStats in the tests).
//
// Interpolation: bicubic Hermite in (q, theta) with node derivatives (and the
// cross derivative) by Akima's rule along the grid lines: C1 over
// the whole table (value and both first derivatives continuous across cells),
// so Newton and AD see consistent derivatives. The data themselves are only
// C0 where a slot's lowest point leaves its border or a local minimum
// vanishes (a fold); Akima's local slopes confine the rounding of such a kink
// to the cells next to it (a global spline would ring over several cells). The resolution error (table
// against direct evaluation at cell centres) is measured by
// measure_table_resolution and stated in contact_tables.cpp / the tests.
//
// Outside the table range evaluate() throws std::domain_error (a wheel more
// than the half range off its rail is derailed, not a contact state).
#include <railstab/contact_geometry/contact_table_options.hpp>
#include <railstab/contact_geometry/wheel_contact_points.hpp>
#include <railstab/contact_geometry/wheelset_pose.hpp>

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>
#include <vector>

namespace railstab {


// The tabulated quantities of one slot, in this order.
enum class TableQuantity : int {
  gap0_m = 0,          // vertical gap at vertical pose 0
  wheel_u_m,           // contact position on the wheel profile
  rail_y_m,            // contact position on the rail profile
  contact_angle_rad,   // gamma (in the rail frame)
  rolling_radius_m,
  A_per_m,             // Hertz relative curvatures
  B_per_m,
  on_border,           // 1 where the slot's lowest point is on its border
  // The highest gap0 on the wheel between this slot's lowest point and the
  // next slot's (slot k and k + 1; the last slot: its own gap0, unused): the
  // saddle of a connected overlap of the two (wheel_rail.hpp, "Shared
  // overlap").
  barrier_to_next_gap0_m,
  count
};
inline constexpr int kTableQuantities = int(TableQuantity::count);

template <class T> struct TableContact {
  T vertical_gap_m;     // g0 + vertical (< 0: overlap)
  T normal_gap_m;       // vertical_gap cos(gamma); penetration = -normal_gap
  T wheel_u_m, rail_y_m, contact_angle_rad, rolling_radius_m, A_per_m, B_per_m;
  T wheel_slope_rad;    // gamma - theta: the contact normal's angle in the axle frame
  // smoothstep(1 - on_border) in [0, 1]: the weight of the slot's contact in
  // the force law (0 where its lowest point sits on its border: no contact
  // of its own there). Differentiated, C1: it fades a contact in over a cell.
  T interior_weight;
  double on_border;     // diagnostics
};

namespace contact_table_detail {
// Cubic Hermite basis on [0, 1] and its use with the cell widths.
template <class T> struct Basis {
  T h00, h10, h01, h11;
};
template <class T> Basis<T> hermite(const T& t) {
  const T t2 = t * t, t3 = t2 * t;
  return {2.0 * t3 - 3.0 * t2 + 1.0, t3 - 2.0 * t2 + t, -2.0 * t3 + 3.0 * t2, t3 - t2};
}
}  // namespace contact_table_detail

class ContactTable {
 public:
  int slots() const { return int(slot_data_.size()); }
  // Wheel coordinate range of slot k: [u_max of slot k+1, u_max of slot k).
  const std::vector<double>& slot_borders_m() const { return borders_m_; }
  void slot_range(int slot, double& u_min_m, double& u_max_m) const;
  double nominal_lateral_m() const { return nominal_lateral_m_; }
  const ContactTableOptions& options() const { return options_; }
  int lateral_nodes() const { return nq_; }
  int roll_nodes() const { return nt_; }

  // Contact of `slot` for the wheel pose (wheelset_pose.hpp), any scalar T
  // (double or AdScalar): cell found from value_of(), Hermite basis in T.
  template <class T> TableContact<T> evaluate(int slot, const WheelPoseOf<T>& pose) const;
  // The vertical gap alone (g0 + vertical), the cheap test for contact.
  template <class T> T vertical_gap(int slot, const WheelPoseOf<T>& pose) const;
  // What the shared overlap (wheel_rail.hpp) needs of slot j = slot +- 1 at
  // a pose, from one cell lookup: j's vertical gap; where j overlaps, the
  // vertical gap of the saddle between the lowest points of the two
  // (barrier_to_next_gap0_m of the lower slot + vertical; < 0: their
  // overlaps join) and j's interior weight (TableContact::interior_weight).
  template <class T> struct Neighbour {
    T vertical_gap_m, saddle_gap_m, interior_weight;
    bool overlaps;  // vertical_gap_m < 0; the other two are set only then
  };
  template <class T> Neighbour<T> neighbour(int slot, int j, const WheelPoseOf<T>& pose) const;
  // The lowest vertical gap over all slots (< 0: the wheel overlaps its rail).
  double lowest_vertical_gap(const WheelPoseOf<double>& pose) const {
    double lowest = vertical_gap<double>(0, pose);
    for (int k = 1; k < slots(); ++k) lowest = std::min(lowest, vertical_gap<double>(k, pose));
    return lowest;
  }

  // The raw node value (for tests and plots).
  double node(int slot, TableQuantity q, int i, int j) const {
    return slot_data_[size_t(slot)][size_t(int(q))][size_t(i * nt_ + j)].f;
  }
  double lateral_at(int i) const { return q0_ + i * dq_; }
  double roll_at(int j) const { return t0_ + j * dt_; }

  // A one-slot table on `grid` whose every quantity is a plane in the table
  // variables (q, theta), about the point (q_c, theta_c):
  //   f(q, theta) = f_c + df_dq (q - q_c) + df_dtheta (theta - theta_c),
  // which the Hermite interpolation reproduces exactly (node slopes are the
  // plane's, cross derivative 0). The quasi-linear contact's table
  // (quasi_linear_contact.hpp). Same range check as every table.
  struct Plane {
    double at_centre = 0, d_dq = 0, d_dtheta = 0;
  };
  static ContactTable plane_table(const ContactTableOptions& grid, double nominal_lateral_m,
                                  double q_c, double theta_c,
                                  const std::array<Plane, kTableQuantities>& planes);

  // A node: the value, d/dq, d/dtheta and d2/dq dtheta.
  struct Node {
    double f, fq, ft, fqt;
  };
  // Node values [slot][quantity][i * roll_nodes + j] on `grid`.
  using NodeValues = std::vector<std::array<std::vector<double>, kTableQuantities>>;
  // A table from its node values alone: the node derivatives by Akima's
  // rule, as make_contact_table (which builds its table this way). `borders_m`
  // (decreasing, one fewer than the slots) only names the slots' parts of
  // the wheel. Throws std::invalid_argument on sizes that do not fit the grid.
  static ContactTable from_node_values(const ContactTableOptions& grid, double nominal_lateral_m,
                                       std::vector<double> borders_m, const NodeValues& values);
  // A table from complete nodes (values and derivatives), e.g. as written to
  // a file (contact_table_file.hpp): evaluates bit for bit as the table they
  // came from. Same size checks.
  using NodeData = std::vector<std::array<std::vector<Node>, kTableQuantities>>;
  static ContactTable from_nodes(const ContactTableOptions& grid, double nominal_lateral_m,
                                 std::vector<double> borders_m, NodeData nodes);
  const Node& node_data(int slot, TableQuantity q, int i, int j) const {
    return slot_data_[size_t(slot)][size_t(int(q))][size_t(i * nt_ + j)];
  }

 private:
  friend ContactTable make_contact_table(const ProfilePair&, const ContactTableOptions&);
  // The grid of `o` (node counts, spacing, first nodes) set on `t`.
  static void set_grid(ContactTable& t, const ContactTableOptions& o, const char* who);
  // The cell of a pose and the Hermite basis in it.
  template <class T> struct Cell {
    int i, j;
    contact_table_detail::Basis<T> Ba, Bb;
  };
  template <class T> Cell<T> locate(int slot, const WheelPoseOf<T>& pose) const;
  template <class T> T interpolate(int slot, TableQuantity which, const Cell<T>& c) const;
  ContactTableOptions options_;
  std::vector<double> borders_m_;  // decreasing
  double nominal_lateral_m_ = 0;
  double q0_ = 0, dq_ = 1, t0_ = 0, dt_ = 1;
  int nq_ = 0, nt_ = 0;
  // [slot][quantity][i * nt + j]
  std::vector<std::array<std::vector<Node>, kTableQuantities>> slot_data_;
};

// Builds the table of a placed pair (both sides share it: the right side is
// the mirror image). Cost: (nodes) x (slots) profile scans; ~0.1 s for the
// default grid on S1002/UIC60.
ContactTable make_contact_table(const ProfilePair& pair, const ContactTableOptions& options = {});

// Direct (untabulated) slot contact for a pose: what the table interpolates.
ContactPoint direct_slot_contact(const ProfilePair& pair, const ContactTable& table, int slot,
                                 const WheelPose& pose);

// Maximum |table - direct| at the cell centres (the points farthest from the
// nodes), per quantity, over cells whose four corner nodes are all interior
// (not on_border) and all within `near_gap_m` of contact (gap0 minus the
// lowest gap0 of the pose over all slots <= near_gap_m), separately for cells
// whose corners lie on one smooth branch (corners' wheel_u within
// branch_jump_m; a smooth branch moves along the wheel by 1/(2B) per radian
// of roll, ~1.5 mm per 5 mrad step for B ~ 1.7 1/m) and cells across a jump
// of the lowest point.
struct TableResolution {
  std::array<double, kTableQuantities> smooth{}, across_jump{};
  int smooth_cells = 0, jump_cells = 0;
};
TableResolution measure_table_resolution(const ProfilePair& pair, const ContactTable& table,
                                         double near_gap_m = 1e-3, double branch_jump_m = 2.5e-3);

// ----- implementation of the template -----



template <class T>
ContactTable::Cell<T> ContactTable::locate(int slot, const WheelPoseOf<T>& pose) const {
  using contact_table_detail::hermite;
  if (slot < 0 || slot >= slots())
    throw std::invalid_argument("ContactTable::evaluate: slot " + std::to_string(slot) +
                                " out of range (table has " + std::to_string(slots()) + ")");
  const T q = pose.lateral_m - nominal_lateral_m_;
  const T& th = pose.roll_rad;
  const double qv = value_of(q), tv = value_of(th);
  const double q_end = q0_ + (nq_ - 1) * dq_, t_end = t0_ + (nt_ - 1) * dt_;
  if (!(qv >= q0_ - 1e-12 && qv <= q_end + 1e-12 && tv >= t0_ - 1e-12 && tv <= t_end + 1e-12))
    throw std::domain_error("contact table: wheel lateral displacement " + std::to_string(qv) +
                            " m / roll " + std::to_string(tv) + " rad outside the table (" +
                            std::to_string(q0_) + " .. " + std::to_string(q_end) + " m, " +
                            std::to_string(t0_) + " .. " + std::to_string(t_end) + " rad)");
  Cell<T> c;
  c.i = std::min(std::max(int((qv - q0_) / dq_), 0), nq_ - 2);
  c.j = std::min(std::max(int((tv - t0_) / dt_), 0), nt_ - 2);
  c.Ba = hermite(T((q - (q0_ + c.i * dq_)) / dq_));
  c.Bb = hermite(T((th - (t0_ + c.j * dt_)) / dt_));
  return c;
}

template <class T>
T ContactTable::interpolate(int slot, TableQuantity which, const Cell<T>& c) const {
  const std::vector<Node>& n = slot_data_[size_t(slot)][size_t(int(which))];
  const int i = c.i, j = c.j;
  const Node& n00 = n[size_t(i * nt_ + j)];
  const Node& n10 = n[size_t((i + 1) * nt_ + j)];
  const Node& n01 = n[size_t(i * nt_ + j + 1)];
  const Node& n11 = n[size_t((i + 1) * nt_ + j + 1)];
  // Tensor Hermite: sum over corners of value, d/dq, d/dtheta, d2/dq dtheta.
  auto along_q = [&](const Node& lo, const Node& hi, double Node::*f, double Node::*fq) -> T {
    return c.Ba.h00 * (lo.*f) + c.Ba.h10 * (dq_ * (lo.*fq)) + c.Ba.h01 * (hi.*f) +
           c.Ba.h11 * (dq_ * (hi.*fq));
  };
  const T v0 = along_q(n00, n10, &Node::f, &Node::fq);     // at theta_j
  const T v1 = along_q(n01, n11, &Node::f, &Node::fq);     // at theta_j+1
  const T s0 = along_q(n00, n10, &Node::ft, &Node::fqt);   // d/dtheta at theta_j
  const T s1 = along_q(n01, n11, &Node::ft, &Node::fqt);
  return c.Bb.h00 * v0 + c.Bb.h10 * (dt_ * s0) + c.Bb.h01 * v1 + c.Bb.h11 * (dt_ * s1);
}

template <class T> T ContactTable::vertical_gap(int slot, const WheelPoseOf<T>& pose) const {
  return interpolate(slot, TableQuantity::gap0_m, locate(slot, pose)) + pose.vertical_m;
}

namespace contact_table_detail {
// Smoothstep of 1 - on_border, u -> 3u^2 - 2u^3 on [0, 1], constant outside:
// C1 also where the interpolant leaves [0, 1] (a plain clamp would kink).
template <class T> T interior_weight_of(const T& border) {
  const double b = value_of(border);
  if (b <= 0.0) return T(1);
  if (b >= 1.0) return T(0);
  const T u = 1.0 - border;
  return u * u * (3.0 - 2.0 * u);
}
}  // namespace contact_table_detail

template <class T>
ContactTable::Neighbour<T> ContactTable::neighbour(int slot, int j, const WheelPoseOf<T>& pose) const {
  const Cell<T> cell = locate(j, pose);
  Neighbour<T> n;
  n.vertical_gap_m = interpolate(j, TableQuantity::gap0_m, cell) + pose.vertical_m;
  n.overlaps = value_of(n.vertical_gap_m) < 0.0;
  if (!n.overlaps) return n;
  n.saddle_gap_m =
      interpolate(std::min(slot, j), TableQuantity::barrier_to_next_gap0_m, cell) + pose.vertical_m;
  n.interior_weight =
      contact_table_detail::interior_weight_of(interpolate(j, TableQuantity::on_border, cell));
  return n;
}

template <class T>
TableContact<T> ContactTable::evaluate(int slot, const WheelPoseOf<T>& pose) const {
  using std::cos;
  const Cell<T> cell = locate(slot, pose);
  TableContact<T> c;
  c.vertical_gap_m = interpolate(slot, TableQuantity::gap0_m, cell) + pose.vertical_m;
  c.wheel_u_m = interpolate(slot, TableQuantity::wheel_u_m, cell);
  c.rail_y_m = interpolate(slot, TableQuantity::rail_y_m, cell);
  c.contact_angle_rad = interpolate(slot, TableQuantity::contact_angle_rad, cell);
  c.rolling_radius_m = interpolate(slot, TableQuantity::rolling_radius_m, cell);
  c.A_per_m = interpolate(slot, TableQuantity::A_per_m, cell);
  c.B_per_m = interpolate(slot, TableQuantity::B_per_m, cell);
  c.normal_gap_m = c.vertical_gap_m * cos(c.contact_angle_rad);
  c.wheel_slope_rad = c.contact_angle_rad - pose.roll_rad;
  const T border = interpolate(slot, TableQuantity::on_border, cell);
  c.on_border = value_of(border);
  c.interior_weight = contact_table_detail::interior_weight_of(border);
  return c;
}

}  // namespace railstab
