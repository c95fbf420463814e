#include <railstab/contact/rsgeo_table.hpp>

#include <railstab/contact/hertz.hpp>
#include <railstab/contact_geometry/characteristic_functions.hpp>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <ostream>
#include <sstream>

namespace railstab {

namespace {

constexpr const char* kColumnNames[kRsgeoColumns] = {
    "y", "normal force", "contact angle", "a", "b", "wheel contact lateral position",
    "rolling radius", "C11", "C22", "C23", "rail contact height", "penetration",
    "rail contact lateral position"};

std::string where(const std::string& path, int line) {
  return path + (line > 0 ? ":" + std::to_string(line) : "");
}

std::vector<std::string> tokens(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream in(line);
  std::string t;
  while (in >> t) out.push_back(t);
  return out;
}

// Up to 40 characters of a field for a message, bytes that are not
// printable ASCII shown as '?' (a binary file read by mistake).
std::string shown(const std::string& text) {
  std::string out = text.substr(0, 40);
  for (char& c : out)
    if (c < 0x20 || c > 0x7e) c = '?';
  return out + (text.size() > 40 ? "..." : "");
}

bool blank(const std::string& line) { return line.find_first_not_of(" \t\r") == std::string::npos; }

// Linear interpolation of column `c` of rows sorted by column 0.
double at_y(const RsgeoTable& t, RsgeoColumn c, double y) {
  const auto& rows = t.rows;
  auto it = std::lower_bound(rows.begin(), rows.end(), y,
                             [](const auto& row, double v) { return row[0] < v; });
  size_t k = size_t(it - rows.begin());
  if (k == 0) k = 1;
  if (k >= rows.size()) k = rows.size() - 1;
  const auto& a = rows[k - 1];
  const auto& b = rows[k];
  const double w = (y - a[0]) / (b[0] - a[0]);
  return a[size_t(c)] + w * (b[size_t(c)] - a[size_t(c)]);
}

// B such that Hertz's a/b for (A, B) is `a_over_b` (a/b grows with B/A):
// bisection in log(B/A) over [1e-4, 1e4].
double transverse_curvature_for(double A, double a_over_b) {
  double lo = std::log(1e-4), hi = std::log(1e4);
  for (int it = 0; it < 80; ++it) {
    const double mid = 0.5 * (lo + hi);
    const double ratio = hertz_shape<double>(A, A * std::exp(mid), 1.0).a_over_b;
    (ratio < a_over_b ? lo : hi) = mid;
  }
  return A * std::exp(0.5 * (lo + hi));
}

// The rigid state of the left wheel at wheelset shift y, in the table's
// variables and quantities.
struct RigidRow {
  double q, roll, gap0, dgap_droll;
  double wheel_u, rail_y, wheel_angle, rolling_radius, A, B;
};

}  // namespace

RsgeoTable read_rsgeo_table(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
    throw ContactTableFileError(path + ": RSGEO file not found; expected an existing file");
  if (std::filesystem::is_directory(path, ec))
    throw ContactTableFileError(path + ": is a directory; expected an RSGEO file");
  std::ifstream in(path);
  if (!in) throw ContactTableFileError(path + ": cannot open the RSGEO file for reading");
  RsgeoTable t;
  t.path = path;
  std::string line;
  int number = 0;
  bool delimiter = false;
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line[0] == '#') {
      delimiter = true;
      break;
    }
  }
  if (!delimiter)
    throw ContactTableFileError(where(path, number) +
                                ": expected a line starting with '#' before the table (RSGEO "
                                "layout: '#', the column names, the rows), got none");
  if (!std::getline(in, line))
    throw ContactTableFileError(where(path, number + 1) +
                                ": expected the line of column names after '#', got the end of "
                                "the file");
  ++number;
  const std::vector<std::string> header = tokens(line);
  if (int(header.size()) != kRsgeoColumns)
    throw ContactTableFileError(
        where(path, number) + ": expected " + std::to_string(kRsgeoColumns) +
        " column names (y, normal force, contact angle, a, b, wheel contact lateral position, "
        "rolling radius, C11, C22, C23, rail contact height, penetration, rail contact lateral "
        "position), got " + std::to_string(header.size()));
  while (std::getline(in, line)) {
    ++number;
    if (blank(line)) continue;
    if (line[0] == '#')
      throw ContactTableFileError(where(path, number) +
                                  ": expected one table per file (railstab reads one wheel "
                                  "profile pair), got a second '#' block");
    const std::vector<std::string> f = tokens(line);
    if (int(f.size()) != kRsgeoColumns)
      throw ContactTableFileError(where(path, number) + ": expected " +
                                  std::to_string(kRsgeoColumns) + " numbers (as the column "
                                  "names), got " + std::to_string(f.size()));
    std::array<double, kRsgeoColumns> row{};
    for (int c = 0; c < kRsgeoColumns; ++c) {
      std::string s = f[size_t(c)];
      for (char& ch : s)
        if (ch == 'D' || ch == 'd') ch = 'e';  // Fortran's double exponent
      double v = 0.0;
      const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
      if (r.ec != std::errc() || r.ptr != s.data() + s.size() || !std::isfinite(v))
        throw ContactTableFileError(where(path, number) + ": column " + std::to_string(c + 1) +
                                    " (" + kColumnNames[c] + "): expected a finite number, got '" +
                                    shown(f[size_t(c)]) + "'");
      row[size_t(c)] = v;
    }
    auto require = [&](RsgeoColumn c, bool ok, const std::string& expected) {
      if (!ok)
        throw ContactTableFileError(where(path, number) + ": column " +
                                    std::to_string(int(c) + 1) + " (" + kColumnNames[int(c)] +
                                    "): expected " + expected + ", got " + shown(f[size_t(int(c))]));
    };
    require(RsgeoColumn::y_m, std::abs(row[0]) <= 0.05, "|y| <= 0.05 m");
    if (!t.rows.empty())
      require(RsgeoColumn::y_m, row[0] > t.rows.back()[0],
              "y increasing down the file (the previous row has " +
                  std::to_string(t.rows.back()[0]) + ")");
    require(RsgeoColumn::contact_angle_rad, std::abs(row[2]) < 1.5, "|contact angle| < 1.5 rad");
    require(RsgeoColumn::semi_axis_a_m, row[3] > 0, "a > 0 m");
    require(RsgeoColumn::semi_axis_b_m, row[4] > 0, "b > 0 m");
    require(RsgeoColumn::wheel_lateral_m, row[5] > 0.2 && row[5] < 1.5,
            "a wheel contact 0.2 to 1.5 m from the wheelset centre");
    require(RsgeoColumn::rolling_radius_m, row[6] > 0.1 && row[6] < 1.0,
            "a rolling radius in (0.1, 1) m");
    require(RsgeoColumn::rail_height_m, std::abs(row[10]) < 0.05, "|rail contact height| < 0.05 m");
    t.rows.push_back(row);
    t.line.push_back(number);
  }
  if (in.bad()) throw ContactTableFileError(path + ": read error");
  if (t.rows.size() < 5)
    throw ContactTableFileError(where(path, number) + ": expected at least 5 rows of the table, got " +
                                std::to_string(t.rows.size()));
  return t;
}

std::shared_ptr<const ProfileContactGeometry> rsgeo_contact_geometry(
    const RsgeoTable& t, const ContactTableOptions& grid, double r0) {
  const std::string& path = t.path;
  if (t.rows.size() < 5) throw ContactTableFileError(path + ": expected at least 5 rows");
  const double y_lo = t.rows.front()[0], y_hi = t.rows.back()[0];
  if (!(y_lo < 0 && y_hi > 0))
    throw ContactTableFileError(path + ": column 1 (y): expected shifts on both sides of 0 (the "
                                "right wheel is looked up at -y), got " + std::to_string(y_lo) +
                                " .. " + std::to_string(y_hi) + " m");
  const double y_max = std::min(-y_lo, y_hi);  // both wheels in the table
  const double D = at_y(t, RsgeoColumn::wheel_lateral_m, 0.0);
  auto g = std::make_shared<ProfileContactGeometry>();
  g->table_source = path + " (RSGEO)";
  ProfilePair& pair = g->pair;
  pair.parameters.nominal_rolling_radius_m = r0;
  pair.wheel_offset_y_m = D;
  pair.rail_offset_y_m = D;
  pair.rail_top_y_m = pair.rail_top_z_m = pair.gauge_point_y_m = 0.0;
  pair.wheel.source = pair.rail.source = g->table_source;

  // The rigid state at every row with its mirror in the table.
  std::vector<RigidRow> rigid;
  for (size_t k = 0; k < t.rows.size(); ++k) {
    const auto& L = t.rows[k];
    const double y = L[0];
    if (std::abs(y) > y_max + 1e-12) continue;
    using C = RsgeoColumn;
    const double aL = L[size_t(C::wheel_lateral_m)], rL = L[size_t(C::rolling_radius_m)];
    const double zL = L[size_t(C::rail_height_m)];
    const double aR = at_y(t, C::wheel_lateral_m, -y), rR = at_y(t, C::rolling_radius_m, -y);
    const double zR = at_y(t, C::rail_height_m, -y);
    // (aL + aR) sin(phi) - (rL - rR) cos(phi) = zL - zR.
    const double S = aL + aR, Dr = rL - rR, Dz = zL - zR;
    const double R = std::hypot(S, Dr);
    const double phi = std::atan2(Dr, S) + std::asin(std::clamp(Dz / R, -1.0, 1.0));
    const double z = zL - aL * std::sin(phi) + rL * std::cos(phi);  // wheelset centre height
    RigidRow row;
    row.roll = phi;
    row.q = y - D + D * std::cos(phi) + r0 * std::sin(phi);
    const double vertical = z + D * std::sin(phi) - r0 * std::cos(phi);
    row.gap0 = -vertical;
    row.wheel_u = aL - D;
    const double zw = r0 - rL;
    row.rail_y = y + aL * std::cos(phi) + rL * std::sin(phi) - D;
    row.wheel_angle = L[size_t(C::contact_angle_rad)];
    const double gamma = row.wheel_angle + phi;
    row.dgap_droll = row.wheel_u * std::cos(phi) - zw * std::sin(phi) +
                     std::tan(gamma) * (row.wheel_u * std::sin(phi) + zw * std::cos(phi));
    row.rolling_radius = rL;
    row.A = std::cos(row.wheel_angle) / (2.0 * rL);
    row.B = transverse_curvature_for(row.A, L[size_t(C::semi_axis_a_m)] / L[size_t(C::semi_axis_b_m)]);
    if (!rigid.empty() && !(row.q > rigid.back().q))
      throw ContactTableFileError(
          where(path, t.line[k]) + ": the wheel's rigid lateral displacement q = y - D + D cos(phi) "
          "+ r0 sin(phi) does not increase with y here (roll " + std::to_string(phi) +
          " rad); expected rolling radii that do not fall towards the flange");
    rigid.push_back(row);
  }
  if (rigid.size() < 5)
    throw ContactTableFileError(path + ": expected at least 5 rows with y and -y in the table");

  // Resample on the grid.
  ContactTable grid_only = ContactTable::plane_table(grid, 0.0, 0.0, 0.0, {});
  const int nq = grid_only.lateral_nodes(), nt = grid_only.roll_nodes();
  const double q_first = grid_only.lateral_at(0), q_last = grid_only.lateral_at(nq - 1);
  if (q_first < rigid.front().q || q_last > rigid.back().q) {
    std::ostringstream msg;
    msg << path << ": table_lateral_half_range_m = " << grid.lateral_half_range_m
        << ": expected a lateral half range the file covers: the rigid contact's lateral "
           "displacement runs from "
        << rigid.front().q << " to " << rigid.back().q << " m (y within +-" << y_max << " m)";
    throw ContactTableFileError(msg.str());
  }
  ContactTable::NodeValues values(1);
  for (auto& v : values[0]) v.assign(size_t(nq) * size_t(nt), 0.0);
  size_t k = 1;
  for (int i = 0; i < nq; ++i) {
    const double q = grid_only.lateral_at(i);
    while (k + 1 < rigid.size() && rigid[k].q < q) ++k;
    const RigidRow& a = rigid[k - 1];
    const RigidRow& b = rigid[k];
    const double w = std::clamp((q - a.q) / (b.q - a.q), 0.0, 1.0);
    auto lerp = [&](double RigidRow::*f) { return a.*f + w * (b.*f - a.*f); };
    const double roll = lerp(&RigidRow::roll), gap0 = lerp(&RigidRow::gap0);
    const double G = lerp(&RigidRow::dgap_droll), delta = lerp(&RigidRow::wheel_angle);
    for (int j = 0; j < nt; ++j) {
      const double theta = grid_only.roll_at(j);
      const size_t n = size_t(i * nt + j);
      auto& v = values[0];
      v[size_t(TableQuantity::gap0_m)][n] = gap0 + G * (theta - roll);
      v[size_t(TableQuantity::wheel_u_m)][n] = lerp(&RigidRow::wheel_u);
      v[size_t(TableQuantity::rail_y_m)][n] = lerp(&RigidRow::rail_y);
      v[size_t(TableQuantity::contact_angle_rad)][n] = delta + theta;
      v[size_t(TableQuantity::rolling_radius_m)][n] = lerp(&RigidRow::rolling_radius);
      v[size_t(TableQuantity::A_per_m)][n] = lerp(&RigidRow::A);
      v[size_t(TableQuantity::B_per_m)][n] = lerp(&RigidRow::B);
      v[size_t(TableQuantity::on_border)][n] = 0.0;
      // One slot: no next slot to share an overlap with (unused).
      v[size_t(TableQuantity::barrier_to_next_gap0_m)][n] = v[size_t(TableQuantity::gap0_m)][n];
    }
  }
  g->table = ContactTable::from_node_values(grid, 0.0, {}, values);

  // Flange: the steepest contact angle; the first shift y > 0 beyond 45 degrees.
  for (const auto& row : t.rows)
    g->flange_angle_rad = std::max(g->flange_angle_rad, row[size_t(RsgeoColumn::contact_angle_rad)]);
  for (size_t r = 1; r < t.rows.size(); ++r) {
    const auto& a = t.rows[r - 1];
    const auto& b = t.rows[r];
    const double da = a[2] - kFlangeContactAngle_rad, db = b[2] - kFlangeContactAngle_rad;
    if (b[0] > 0 && da <= 0 && db > 0) {
      g->flange_contact_shift_m = a[0] + (b[0] - a[0]) * (-da) / (db - da);
      break;
    }
  }
  return g;
}

void write_rsgeo_table(std::ostream& out, const std::vector<std::array<double, kRsgeoColumns>>& rows) {
  out << "#\n\"rh(51)\"\t\"Normalforce\"\t\"DATAN(TANDJA(1,1))\"\t\"a(1,1)\"\t\"b(1,1)\"\t"
         "\"BJA(2,1,1)+0,75\"\t\"R0J(1,1)\"\t\"c11\"\t\"c22\"\t\"c23\"\t\"BJA(3,1,1)\"\t"
         "\"Penetration\"\t\"BJA(2,1,1)+0.75+rh(51)\"\n";
  out << std::scientific << std::setprecision(15);
  for (const auto& row : rows) {
    for (int c = 0; c < kRsgeoColumns; ++c) out << (c ? " " : "") << row[size_t(c)];
    out << "\n";
  }
}

}  // namespace railstab
