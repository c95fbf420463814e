#include <railstab/contact_geometry/contact_tables.hpp>

#include <railstab/contact_geometry/characteristic_functions.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace railstab {
namespace {

// Node slopes of data f on a uniform grid of spacing h by Akima's rule: the
// slope at node i weights the neighbouring secants d_{i-1}, d_i by the
// change of the secants on the far sides,
//   f'_i = (w1 d_{i-1} + w2 d_i) / (w1 + w2),
//   w1 = |d_{i+1} - d_i|,  w2 = |d_{i-1} - d_{i-2}|,
// (the plain mean where both weights vanish), with two secants extrapolated
// linearly beyond each end. A kink in the data then disturbs only the cells
// next to it, where a global spline would ring over several cells; the
// Hermite interpolant through these slopes is C1.
std::vector<double> akima_slopes(const std::vector<double>& f, double h) {
  const int n = int(f.size());
  std::vector<double> d(size_t(n + 3));  // d[k + 2] = secant k (k = -2 .. n)
  for (int k = 0; k + 1 < n; ++k) d[size_t(k + 2)] = (f[size_t(k + 1)] - f[size_t(k)]) / h;
  if (n == 2) {
    d[0] = d[1] = d[3] = d[4] = d[2];
  } else {
    d[1] = 2 * d[2] - d[3];
    d[0] = 2 * d[1] - d[2];
    d[size_t(n + 1)] = 2 * d[size_t(n)] - d[size_t(n - 1)];
    d[size_t(n + 2)] = 2 * d[size_t(n + 1)] - d[size_t(n)];
  }
  std::vector<double> slope(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) {
    const double dm2 = d[size_t(i)], dm1 = d[size_t(i + 1)], d0 = d[size_t(i + 2)],
                 dp1 = d[size_t(i + 3)];
    const double w1 = std::abs(dp1 - d0), w2 = std::abs(dm1 - dm2);
    const double scale = 1e-12 * (std::abs(dm1) + std::abs(d0)) + 1e-300;
    slope[size_t(i)] = (w1 + w2 > scale) ? (w1 * dm1 + w2 * d0) / (w1 + w2) : 0.5 * (dm1 + d0);
  }
  return slope;
}

double quantity_of(const ContactPoint& c, TableQuantity q) {
  switch (q) {
    case TableQuantity::gap0_m: return c.vertical_gap_m;
    case TableQuantity::wheel_u_m: return c.wheel_u_m;
    case TableQuantity::rail_y_m: return c.rail_y_m;
    case TableQuantity::contact_angle_rad: return c.contact_angle_rad;
    case TableQuantity::rolling_radius_m: return c.rolling_radius_m;
    case TableQuantity::A_per_m: return c.A_per_m;
    case TableQuantity::B_per_m: return c.B_per_m;
    case TableQuantity::on_border: return c.interior ? 0.0 : 1.0;
    // Pairwise: filled in by make_contact_table (the slot's own gap0 until then).
    case TableQuantity::barrier_to_next_gap0_m: return c.vertical_gap_m;
    case TableQuantity::count: break;
  }
  return 0.0;
}

}  // namespace

void ContactTable::slot_range(int slot, double& u_min, double& u_max) const {
  const double inf = std::numeric_limits<double>::infinity();
  u_max = slot == 0 ? inf : borders_m_[size_t(slot - 1)];
  u_min = slot == slots() - 1 ? -inf : borders_m_[size_t(slot)];
}

ContactPoint direct_slot_contact(const ProfilePair& pair, const ContactTable& table, int slot,
                                 const WheelPose& pose) {
  double u_min, u_max;
  table.slot_range(slot, u_min, u_max);
  return minimum_gap_in_wheel_range(pair, pose, u_min, u_max);
}

namespace {

// The grid a table is sampled on: positive steps, at least two lateral steps
// and one roll step to each side of the centre.
void check_table_grid(const ContactTableOptions& o, const char* who) {
  if (!(o.lateral_step_m > 0 && o.lateral_half_range_m >= 2 * o.lateral_step_m &&
        o.roll_step_rad > 0 && o.roll_half_range_rad >= o.roll_step_rad))
    throw std::invalid_argument(std::string(who) +
                                ": expected positive steps and half ranges of at least two "
                                "lateral steps and one roll step");
}

}  // namespace

void ContactTable::set_grid(ContactTable& t, const ContactTableOptions& o, const char* who) {
  check_table_grid(o, who);
  t.options_ = o;
  t.nq_ = 2 * int(std::lround(o.lateral_half_range_m / o.lateral_step_m)) + 1;
  t.nt_ = 2 * int(std::lround(o.roll_half_range_rad / o.roll_step_rad)) + 1;
  t.dq_ = 2 * o.lateral_half_range_m / (t.nq_ - 1);
  t.dt_ = 2 * o.roll_half_range_rad / (t.nt_ - 1);
  t.q0_ = -o.lateral_half_range_m;
  t.t0_ = -o.roll_half_range_rad;
}

namespace {

void check_slot_count(size_t slots, size_t borders, const char* who) {
  if (slots == 0 || borders + 1 != slots)
    throw std::invalid_argument(std::string(who) + ": expected one slot border fewer than the " +
                                std::to_string(slots) + " slots, got " + std::to_string(borders));
}

void check_node_count(size_t got, size_t expected, const char* who) {
  if (got != expected)
    throw std::invalid_argument(std::string(who) + ": expected " + std::to_string(expected) +
                                " nodes per slot and quantity (the grid's), got " +
                                std::to_string(got));
}

}  // namespace

ContactTable ContactTable::from_node_values(const ContactTableOptions& o, double nominal_lateral_m,
                                            std::vector<double> borders_m,
                                            const NodeValues& values) {
  const char* who = "ContactTable::from_node_values";
  ContactTable t;
  set_grid(t, o, who);
  check_slot_count(values.size(), borders_m.size(), who);
  t.nominal_lateral_m_ = nominal_lateral_m;
  t.borders_m_ = std::move(borders_m);
  const size_t nodes = size_t(t.nq_) * size_t(t.nt_);
  t.slot_data_.resize(values.size());
  for (size_t slot = 0; slot < values.size(); ++slot) {
    auto& data = t.slot_data_[slot];
    for (int q = 0; q < kTableQuantities; ++q) {
      const std::vector<double>& v = values[slot][size_t(q)];
      check_node_count(v.size(), nodes, who);
      data[size_t(q)].resize(nodes);
      for (size_t k = 0; k < nodes; ++k) data[size_t(q)][k] = Node{v[k], 0, 0, 0};
    }
    // Node derivatives by Akima's rule along the grid lines.
    std::vector<double> line;
    for (auto& n : data) {
      for (int j = 0; j < t.nt_; ++j) {  // d/dq along each roll row
        line.resize(size_t(t.nq_));
        for (int i = 0; i < t.nq_; ++i) line[size_t(i)] = n[size_t(i * t.nt_ + j)].f;
        const std::vector<double> d = akima_slopes(line, t.dq_);
        for (int i = 0; i < t.nq_; ++i) n[size_t(i * t.nt_ + j)].fq = d[size_t(i)];
      }
      for (int i = 0; i < t.nq_; ++i) {  // d/dtheta and d2/dq dtheta along each column
        line.resize(size_t(t.nt_));
        for (int j = 0; j < t.nt_; ++j) line[size_t(j)] = n[size_t(i * t.nt_ + j)].f;
        const std::vector<double> dt = akima_slopes(line, t.dt_);
        for (int j = 0; j < t.nt_; ++j) line[size_t(j)] = n[size_t(i * t.nt_ + j)].fq;
        const std::vector<double> dqt = akima_slopes(line, t.dt_);
        for (int j = 0; j < t.nt_; ++j) {
          n[size_t(i * t.nt_ + j)].ft = dt[size_t(j)];
          n[size_t(i * t.nt_ + j)].fqt = dqt[size_t(j)];
        }
      }
    }
  }
  return t;
}

ContactTable ContactTable::from_nodes(const ContactTableOptions& o, double nominal_lateral_m,
                                      std::vector<double> borders_m, NodeData nodes) {
  const char* who = "ContactTable::from_nodes";
  ContactTable t;
  set_grid(t, o, who);
  check_slot_count(nodes.size(), borders_m.size(), who);
  for (const auto& quantities : nodes)
    for (const auto& v : quantities) check_node_count(v.size(), size_t(t.nq_) * size_t(t.nt_), who);
  t.nominal_lateral_m_ = nominal_lateral_m;
  t.borders_m_ = std::move(borders_m);
  t.slot_data_ = std::move(nodes);
  return t;
}

ContactTable make_contact_table(const ProfilePair& pair, const ContactTableOptions& o) {
  check_table_grid(o, "make_contact_table");
  // The slots' parts of the wheel and the grid, then the direct contact at
  // every node.
  std::vector<double> borders = contact_jump_borders(pair, o.lateral_half_range_m);
  ContactTable grid;
  ContactTable::set_grid(grid, o, "make_contact_table");
  grid.nominal_lateral_m_ = pair.nominal_wheel_lateral_m();
  grid.borders_m_ = borders;
  const int slots = int(borders.size()) + 1;
  grid.slot_data_.resize(size_t(slots));  // (slot_range counts the slots)
  const size_t nodes = size_t(grid.nq_) * size_t(grid.nt_);
  ContactTable::NodeValues values(static_cast<size_t>(slots));
  for (auto& quantities : values)
    for (auto& v : quantities) v.assign(nodes, 0.0);
  const auto at = [&](int slot, TableQuantity q, size_t node) -> double& {
    return values[size_t(slot)][size_t(int(q))][node];
  };
  for (int i = 0; i < grid.nq_; ++i)
    for (int j = 0; j < grid.nt_; ++j) {
      const WheelPose pose{grid.nominal_lateral_m_ + grid.lateral_at(i), 0.0, grid.roll_at(j)};
      const size_t node = size_t(i * grid.nt_ + j);
      for (int slot = 0; slot < slots; ++slot) {
        const ContactPoint c = direct_slot_contact(pair, grid, slot, pose);
        for (int q = 0; q < kTableQuantities; ++q) at(slot, TableQuantity(q), node) = quantity_of(c, TableQuantity(q));
      }
      // The saddle between each slot's lowest point and the next one's. It
      // matters only where both overlap the rail together: where either
      // lowest point is more than kSaddleReach_m above the node's lowest
      // (no wheel penetrates that far: a static Hertz overlap is ~0.06 mm),
      // the higher of the two minima stands in for it (a lower bound of the
      // saddle), which saves scans of the wheel where they cannot matter.
      constexpr double kSaddleReach_m = 5e-4;
      double lowest = at(0, TableQuantity::gap0_m, node);
      for (int slot = 1; slot < slots; ++slot)
        lowest = std::min(lowest, at(slot, TableQuantity::gap0_m, node));
      for (int slot = 0; slot + 1 < slots; ++slot) {
        const double g = at(slot, TableQuantity::gap0_m, node),
                     g_next = at(slot + 1, TableQuantity::gap0_m, node);
        at(slot, TableQuantity::barrier_to_next_gap0_m, node) =
            std::max(g, g_next) - lowest > kSaddleReach_m
                ? std::max(g, g_next)
                : maximum_gap_between(pair, pose, at(slot, TableQuantity::wheel_u_m, node),
                                      at(slot + 1, TableQuantity::wheel_u_m, node));
      }
    }
  return ContactTable::from_node_values(o, grid.nominal_lateral_m_, std::move(borders), values);
}

ContactTable ContactTable::plane_table(const ContactTableOptions& o, double nominal_lateral_m,
                                       double q_c, double theta_c,
                                       const std::array<Plane, kTableQuantities>& planes) {
  ContactTable t;
  set_grid(t, o, "ContactTable::plane_table");
  t.nominal_lateral_m_ = nominal_lateral_m;
  t.slot_data_.resize(1);
  for (int q = 0; q < kTableQuantities; ++q) {
    const Plane& p = planes[size_t(q)];
    std::vector<Node>& n = t.slot_data_[0][size_t(q)];
    n.resize(size_t(t.nq_) * size_t(t.nt_));
    for (int i = 0; i < t.nq_; ++i)
      for (int j = 0; j < t.nt_; ++j)
        n[size_t(i * t.nt_ + j)] = Node{
            p.at_centre + p.d_dq * (t.lateral_at(i) - q_c) + p.d_dtheta * (t.roll_at(j) - theta_c),
            p.d_dq, p.d_dtheta, 0.0};
  }
  return t;
}

TableResolution measure_table_resolution(const ProfilePair& pair, const ContactTable& table,
                                         double near_gap_m, double branch_jump_m) {
  TableResolution r;
  for (int slot = 0; slot < table.slots(); ++slot)
    for (int i = 0; i + 1 < table.lateral_nodes(); ++i)
      for (int j = 0; j + 1 < table.roll_nodes(); ++j) {
        bool eligible = true;
        double u_lo = std::numeric_limits<double>::infinity(), u_hi = -u_lo;
        for (int di = 0; di < 2; ++di)
          for (int dj = 0; dj < 2; ++dj) {
            const int a = i + di, b = j + dj;
            double lowest = std::numeric_limits<double>::infinity();
            for (int k = 0; k < table.slots(); ++k)
              lowest = std::min(lowest, table.node(k, TableQuantity::gap0_m, a, b));
            if (table.node(slot, TableQuantity::on_border, a, b) > 0.5) eligible = false;
            if (table.node(slot, TableQuantity::gap0_m, a, b) - lowest > near_gap_m) eligible = false;
            const double u = table.node(slot, TableQuantity::wheel_u_m, a, b);
            u_lo = std::min(u_lo, u), u_hi = std::max(u_hi, u);
          }
        if (!eligible) continue;
        const bool jump = u_hi - u_lo > branch_jump_m;
        const double q = 0.5 * (table.lateral_at(i) + table.lateral_at(i + 1));
        const double th = 0.5 * (table.roll_at(j) + table.roll_at(j + 1));
        const WheelPose pose{table.nominal_lateral_m() + q, 0.0, th};
        const ContactPoint direct = direct_slot_contact(pair, table, slot, pose);
        const TableContact<double> tab =
            table.evaluate<double>(slot, WheelPoseOf<double>{pose.lateral_m, 0.0, th});
        const double values[kTableQuantities] = {tab.vertical_gap_m, tab.wheel_u_m, tab.rail_y_m,
                                                 tab.contact_angle_rad, tab.rolling_radius_m,
                                                 tab.A_per_m, tab.B_per_m, tab.on_border, 0.0};
        auto& worst = jump ? r.across_jump : r.smooth;
        (jump ? r.jump_cells : r.smooth_cells) += 1;
        // (The saddle is a pair's, not the slot's: not measured here.)
        for (int k = 0; k < int(TableQuantity::barrier_to_next_gap0_m); ++k)
          worst[size_t(k)] = std::max(worst[size_t(k)],
                                      std::abs(values[k] - quantity_of(direct, TableQuantity(k))));
      }
  return r;
}

}  // namespace railstab
