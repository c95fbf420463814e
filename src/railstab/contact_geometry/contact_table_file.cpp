#include <railstab/contact_geometry/contact_table_file.hpp>

#include <railstab/contact_geometry/characteristic_functions.hpp>

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <optional>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace railstab {

namespace {

// The columns of each quantity: its value and its node derivatives d/dq,
// d/droll and d2/dq droll, each named with its unit (docs/outputs.md,
// "Naming convention").
constexpr const char* kColumnNames[kTableQuantities][4] = {
    {"gap0_m", "gap0_dq", "gap0_droll_m_per_rad", "gap0_dq_droll_per_rad"},
    {"wheel_u_m", "wheel_u_dq", "wheel_u_droll_m_per_rad", "wheel_u_dq_droll_per_rad"},
    {"rail_y_m", "rail_y_dq", "rail_y_droll_m_per_rad", "rail_y_dq_droll_per_rad"},
    {"contact_angle_rad", "contact_angle_dq_rad_per_m", "contact_angle_droll",
     "contact_angle_dq_droll_per_m"},
    {"rolling_radius_m", "rolling_radius_dq", "rolling_radius_droll_m_per_rad",
     "rolling_radius_dq_droll_per_rad"},
    {"curvature_a_per_m", "curvature_a_dq_per_m2", "curvature_a_droll_per_m_per_rad",
     "curvature_a_dq_droll_per_m2_per_rad"},
    {"curvature_b_per_m", "curvature_b_dq_per_m2", "curvature_b_droll_per_m_per_rad",
     "curvature_b_dq_droll_per_m2_per_rad"},
    {"on_border", "on_border_dq_per_m", "on_border_droll_per_rad", "on_border_dq_droll_per_m_per_rad"},
    {"barrier_to_next_gap0_m", "barrier_to_next_gap0_dq", "barrier_to_next_gap0_droll_m_per_rad",
     "barrier_to_next_gap0_dq_droll_per_rad"}};

// The shortest text that reads back to the same double.
std::string exact(double v) {
  char buffer[32];
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, v);
  return std::string(buffer, r.ptr);
}

std::string column_header() {
  std::string h = "slot,i,j";
  for (const auto& quantity : kColumnNames)
    for (const char* column : quantity) h += std::string(",") + column;
  return h;
}

// The numeric keys and where each lives in a geometry.
struct NumberKey {
  const char* key;
  std::function<double&(ProfileContactGeometry&)> at;
};

const std::vector<NumberKey>& number_keys() {
  static const std::vector<NumberKey> keys = {
      {"nominal_rolling_radius_m",
       [](ProfileContactGeometry& g) -> double& { return g.pair.parameters.nominal_rolling_radius_m; }},
      {"wheel_offset_y_m", [](ProfileContactGeometry& g) -> double& { return g.pair.wheel_offset_y_m; }},
      {"rail_offset_y_m", [](ProfileContactGeometry& g) -> double& { return g.pair.rail_offset_y_m; }},
      {"rail_top_y_m", [](ProfileContactGeometry& g) -> double& { return g.pair.rail_top_y_m; }},
      {"rail_top_z_m", [](ProfileContactGeometry& g) -> double& { return g.pair.rail_top_z_m; }},
      {"gauge_point_y_m", [](ProfileContactGeometry& g) -> double& { return g.pair.gauge_point_y_m; }},
      {"track_gauge_m", [](ProfileContactGeometry& g) -> double& { return g.pair.parameters.track_gauge_m; }},
      {"gauge_measuring_height_m",
       [](ProfileContactGeometry& g) -> double& { return g.pair.parameters.gauge_measuring_height_m; }},
      {"flange_back_distance_m",
       [](ProfileContactGeometry& g) -> double& { return g.pair.parameters.flange_back_distance_m; }},
      {"rail_inclination_rad",
       [](ProfileContactGeometry& g) -> double& { return g.pair.parameters.rail_inclination_rad; }},
      {"tape_circle_from_flange_back_m",
       [](ProfileContactGeometry& g) -> double& { return g.pair.parameters.tape_circle_from_flange_back_m; }},
      {"flange_angle_rad", [](ProfileContactGeometry& g) -> double& { return g.flange_angle_rad; }},
  };
  return keys;
}

constexpr size_t kMostContactTableNodes = 2000000;

constexpr const char* kGridKeys[4] = {"table_lateral_half_range_m", "table_lateral_step_m",
                                      "table_roll_half_range_rad", "table_roll_step_rad"};

std::string trimmed(std::string_view t) {
  const auto first = t.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = t.find_last_not_of(" \t\r");
  return std::string(t.substr(first, last - first + 1));
}

// Up to 60 characters of a line for a message, bytes that are not
// printable ASCII shown as '?' (a binary file read by mistake).
std::string shown(const std::string& text) {
  std::string out = text.substr(0, 60);
  for (char& c : out)
    if (c < 0x20 || c > 0x7e) c = '?';
  return out + (text.size() > 60 ? "..." : "");
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, ',')) out.push_back(trimmed(field));
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

class Reader {
 public:
  explicit Reader(std::string path) : path_(std::move(path)) {}
  [[noreturn]] void fail(int line, const std::string& what) const {
    throw ContactTableFileError(path_ + (line > 0 ? ":" + std::to_string(line) : "") + ": " + what);
  }
  double number(int line, const std::string& where, const std::string& text) const {
    double v = 0.0;
    const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
    if (text.empty() || r.ec != std::errc() || r.ptr != text.data() + text.size() || !std::isfinite(v))
      fail(line, where + ": expected a finite number, got '" + shown(text) + "'");
    return v;
  }
  int whole(int line, const std::string& where, const std::string& text) const {
    const double v = number(line, where, text);
    if (!(v >= 0 && v <= 1e6 && v == std::floor(v)))
      fail(line, where + ": expected a whole number >= 0, got '" + shown(text) + "'");
    return int(v);
  }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

}  // namespace

void write_contact_table_file(std::ostream& out, const ProfileContactGeometry& g,
                              const std::string& source) {
  if (g.asymmetric())
    throw std::invalid_argument(
        "contact table file: expected a symmetric wheelset (the file holds one wheel's table, "
        "mirrored for the other), got an asymmetric one");
  const ContactTable& t = g.table;
  std::optional<double> flange_shift = g.flange_contact_shift_m;
  if (!flange_shift && g.has_profiles()) {
    // A pair whose rigid contact ends before any flange contact (a wheel
    // narrower than the search) states none.
    try {
      const FlangeContact f = find_flange_contact(g.pair);
      if (f.found) flange_shift = f.lateral_shift_m;
    } catch (const ContactGeometryError&) {
    }
  }
  out << "key,value\n"
         "# railstab contact table: the elastic contact model's table of one wheel on its rail\n"
         "# (docs/contact_tables.md), for a contact with geometry = \"table\". SI units; every\n"
         "# number reads back to the same double. Node rows: slot, lateral node i, roll node j,\n"
         "# then per quantity its value, d/dq, d/droll and d2/dq droll (q: the wheel's lateral\n"
         "# displacement from nominal_lateral_m, roll: relative to the rail).\n";
  out << "format," << kContactTableFormatTag << "\n";
  std::string one_line = source;
  for (char& c : one_line)
    if (c == '\n' || c == '\r') c = ' ';
  out << "written_from," << one_line << "\n";
  ProfileContactGeometry numbers;  // the placement numbers and flange angle (no table)
  numbers.pair = g.pair;
  numbers.flange_angle_rad = g.flange_angle_rad;
  for (const NumberKey& k : number_keys()) out << k.key << "," << exact(k.at(numbers)) << "\n";
  out << "nominal_lateral_m," << exact(t.nominal_lateral_m()) << "\n";
  out << "flange_contact_shift_m," << (flange_shift ? exact(*flange_shift) : std::string("none"))
      << "\n";
  const ContactTableOptions& o = t.options();
  const double grid[4] = {o.lateral_half_range_m, o.lateral_step_m, o.roll_half_range_rad,
                          o.roll_step_rad};
  for (int k = 0; k < 4; ++k) out << kGridKeys[k] << "," << exact(grid[k]) << "\n";
  out << "slots," << t.slots() << "\n";
  out << "slot_borders_m";
  for (double b : t.slot_borders_m()) out << "," << exact(b);
  out << "\n" << column_header() << "\n";
  for (int slot = 0; slot < t.slots(); ++slot)
    for (int i = 0; i < t.lateral_nodes(); ++i)
      for (int j = 0; j < t.roll_nodes(); ++j) {
        out << slot << "," << i << "," << j;
        for (int q = 0; q < kTableQuantities; ++q) {
          const ContactTable::Node& n = t.node_data(slot, TableQuantity(q), i, j);
          out << "," << exact(n.f) << "," << exact(n.fq) << "," << exact(n.ft) << ","
              << exact(n.fqt);
        }
        out << "\n";
      }
}

std::shared_ptr<const ProfileContactGeometry> read_contact_table_file(const std::string& path) {
  const Reader r(path);
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
    r.fail(0, "contact table file not found; expected an existing file written by railstab "
              "contact-geometry (<stem>_contact_table.csv)");
  if (std::filesystem::is_directory(path, ec))
    r.fail(0, "is a directory; expected a contact table file");
  std::ifstream in(path);
  if (!in) r.fail(0, "cannot open the contact table file for reading");

  auto g = std::make_shared<ProfileContactGeometry>();
  g->table_source = path;
  std::map<std::string, std::string> values;  // key -> value text
  std::map<std::string, int> lines;           // key -> line
  std::string line;
  int number = 0;
  bool header_seen = false, format_seen = false, columns_seen = false;
  // The header: format first, then key,value lines up to the column header.
  while (std::getline(in, line)) {
    ++number;
    const std::string t = trimmed(line);
    if (t.empty() || t[0] == '#') continue;
    const size_t comma = t.find(',');
    const std::string key = trimmed(t.substr(0, comma));
    const std::string value = comma == std::string::npos ? "" : trimmed(t.substr(comma + 1));
    if (!header_seen) {
      if (t != "key,value")
        r.fail(number, "expected the first line 'key,value' (a contact table written by railstab "
                       "contact-geometry), got '" + shown(t) + "'");
      header_seen = true;
      continue;
    }
    if (!format_seen) {
      if (key != "format" || value != kContactTableFormatTag)
        r.fail(number, "expected the line 'format," + std::string(kContactTableFormatTag) +
                           "' after 'key,value', got '" + shown(t) + "'");
      format_seen = true;
      continue;
    }
    if (key == "slot") {
      if (t != column_header())
        r.fail(number, "expected the column header '" + column_header().substr(0, 60) +
                           "...' (slot, i, j and four columns per quantity), got '" +
                           shown(t) + "'");
      columns_seen = true;
      break;
    }
    bool known = key == "written_from" || key == "nominal_lateral_m" || key == "flange_contact_shift_m" ||
                 key == "slots" || key == "slot_borders_m";
    for (const NumberKey& k : number_keys()) known = known || key == k.key;
    for (const char* k : kGridKeys) known = known || key == k;
    if (!known)
      r.fail(number, "key '" + shown(key) + "': expected one of the table's keys (docs/contact_tables.md)");
    if (values.count(key)) r.fail(number, "key '" + shown(key) + "' appears twice; expected it once");
    values[key] = value;
    lines[key] = number;
  }
  if (!format_seen)
    r.fail(number, "expected 'key,value' and 'format," + std::string(kContactTableFormatTag) +
                       "', got the end of the file");
  if (!columns_seen)
    r.fail(number, "expected the column header line 'slot,i,j,...' and the node rows, got the end of the file");
  const int header_line = number;
  auto required = [&](const std::string& key) -> const std::string& {
    const auto it = values.find(key);
    if (it == values.end())
      r.fail(header_line, "key '" + key + "': expected it before the column header, got none");
    return it->second;
  };
  auto number_of = [&](const std::string& key) {
    return r.number(lines[key], "key '" + key + "'", required(key));
  };
  g->table_source = path;
  for (const NumberKey& k : number_keys()) k.at(*g) = number_of(k.key);
  const double r0 = g->pair.parameters.nominal_rolling_radius_m;
  if (!(r0 >= 0.1 && r0 <= 1.0))
    r.fail(lines["nominal_rolling_radius_m"],
           "key 'nominal_rolling_radius_m': expected a number in [0.1, 1] m, got " + exact(r0));
  const double nominal_lateral = number_of("nominal_lateral_m");
  required("written_from");
  const std::string& flange = required("flange_contact_shift_m");
  if (flange != "none")
    g->flange_contact_shift_m = r.number(lines["flange_contact_shift_m"],
                                         "key 'flange_contact_shift_m' (a number or none)", flange);
  ContactTableOptions o;
  o.lateral_half_range_m = number_of(kGridKeys[0]);
  o.lateral_step_m = number_of(kGridKeys[1]);
  o.roll_half_range_rad = number_of(kGridKeys[2]);
  o.roll_step_rad = number_of(kGridKeys[3]);
  if (!(o.lateral_step_m > 0 && o.lateral_half_range_m >= 2 * o.lateral_step_m &&
        o.lateral_half_range_m <= 0.05 && o.roll_step_rad > 0 &&
        o.roll_half_range_rad >= o.roll_step_rad && o.roll_half_range_rad <= 0.2 &&
        o.lateral_half_range_m / o.lateral_step_m <= 5000 &&
        o.roll_half_range_rad / o.roll_step_rad <= 500))
    r.fail(lines[kGridKeys[0]], "keys table_*: expected positive steps, a lateral half range of at "
                                "least two steps (at most 50 mm, 5000 steps) and a roll half range "
                                "of at least one step (at most 0.2 rad, 500 steps)");
  const int slots = r.whole(lines["slots"], "key 'slots'", required("slots"));
  if (slots < 1 || slots > 20)
    r.fail(lines["slots"], "key 'slots': expected 1 to 20 slots, got " + std::to_string(slots));
  std::vector<double> borders;
  {
    const std::vector<std::string> f = split(required("slot_borders_m"));
    for (const std::string& b : f)
      if (!b.empty() || f.size() > 1)
        borders.push_back(r.number(lines["slot_borders_m"], "key 'slot_borders_m'", b));
    if (int(borders.size()) != slots - 1)
      r.fail(lines["slot_borders_m"], "key 'slot_borders_m': expected " + std::to_string(slots - 1) +
                                          " numbers (one fewer than the slots), got " +
                                          std::to_string(borders.size()));
    for (size_t k = 1; k < borders.size(); ++k)
      if (!(borders[k] < borders[k - 1]))
        r.fail(lines["slot_borders_m"], "key 'slot_borders_m': expected decreasing borders (from "
                                        "the field side to the flange), got " + exact(borders[k - 1]) +
                                            " then " + exact(borders[k]));
  }
  const int nq = 2 * int(std::lround(o.lateral_half_range_m / o.lateral_step_m)) + 1;
  const int nt = 2 * int(std::lround(o.roll_half_range_rad / o.roll_step_rad)) + 1;
  const size_t nodes = size_t(nq) * size_t(nt);
  // A bound before allocating: the default grid has 2169 nodes per slot; a
  // grid of more than 2e6 nodes over all slots (2 GB of text) is a mistake.
  if (nodes * size_t(slots) > kMostContactTableNodes)
    r.fail(lines[kGridKeys[0]], "keys table_* and slots: expected at most " +
                                    std::to_string(kMostContactTableNodes) +
                                    " nodes over all slots, got " + std::to_string(slots) +
                                    " slots x " + std::to_string(nq) + " x " + std::to_string(nt));
  ContactTable::NodeData data(static_cast<size_t>(slots));
  for (auto& quantities : data)
    for (auto& v : quantities) v.resize(nodes);
  const size_t columns = 3 + 4 * size_t(kTableQuantities);
  const std::vector<std::string> column_names = split(column_header());
  std::vector<std::string> f;
  for (int slot = 0; slot < slots; ++slot)
    for (int i = 0; i < nq; ++i)
      for (int j = 0; j < nt; ++j) {
        do {
          if (!std::getline(in, line))
            r.fail(number, "expected " + std::to_string(size_t(slots) * nodes) +
                               " node rows (slots x lateral nodes " + std::to_string(nq) +
                               " x roll nodes " + std::to_string(nt) + "), got the end of the file "
                               "at slot " + std::to_string(slot) + ", i " + std::to_string(i) +
                               ", j " + std::to_string(j));
          ++number;
        } while (trimmed(line).empty() || trimmed(line)[0] == '#');
        f = split(trimmed(line));
        if (f.size() != columns)
          r.fail(number, "expected " + std::to_string(columns) + " values (as the column header), got " +
                             std::to_string(f.size()));
        const int expect[3] = {slot, i, j};
        for (int c = 0; c < 3; ++c)
          if (r.whole(number, "column " + column_names[size_t(c)], f[size_t(c)]) != expect[c])
            r.fail(number, "column " + column_names[size_t(c)] + ": expected " +
                               std::to_string(expect[c]) + " (rows run slot by slot, i by i, j by j), got " +
                               f[size_t(c)]);
        for (int q = 0; q < kTableQuantities; ++q) {
          double v[4];
          for (int d = 0; d < 4; ++d) {
            const size_t c = 3 + 4 * size_t(q) + size_t(d);
            v[d] = r.number(number, "column " + column_names[c], f[c]);
          }
          data[size_t(slot)][size_t(q)][size_t(i * nt + j)] = ContactTable::Node{v[0], v[1], v[2], v[3]};
        }
      }
  while (std::getline(in, line)) {
    ++number;
    const std::string t = trimmed(line);
    if (!t.empty() && t[0] != '#')
      r.fail(number, "expected the end of the file after the last node row, got '" +
                         shown(t) + "'");
  }
  g->table = ContactTable::from_nodes(o, nominal_lateral, std::move(borders), std::move(data));
  return g;
}

}  // namespace railstab
