#include <railstab/profiles/profile_readers.hpp>

#include <railstab/profiles/profile_validation.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace railstab {
namespace {

std::string where(const std::string& path, int line) { return path + ":" + std::to_string(line); }

std::ifstream open_profile(const std::string& path, ProfileKind kind) {
  const std::string what = std::string(profile_kind_name(kind)) + " profile file";
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
    throw ProfileError(path + ": " + what + " not found; expected an existing file");
  if (std::filesystem::is_directory(path, ec))
    throw ProfileError(path + ": is a directory; expected a " + what);
  std::ifstream in(path);
  if (!in) throw ProfileError(path + ": cannot open the " + what + " for reading");
  return in;
}

std::string trim(const std::string& s) {
  size_t b = 0, e = s.size();
  while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
  while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
  return s.substr(b, e - b);
}

// Parses all numbers of a line (separators: blanks, ',', ';'); false if a
// token is not a number.
bool parse_numbers(std::string text, std::vector<double>& out) {
  for (char& c : text)
    if (c == ',' || c == ';' || c == '\t') c = ' ';
  std::istringstream tokens(text);
  std::string token;
  out.clear();
  while (tokens >> token) {
    size_t used = 0;
    double v;
    try {
      v = std::stod(token, &used);
    } catch (const std::exception&) {
      return false;
    }
    if (used != token.size()) return false;
    out.push_back(v);
  }
  return true;
}

bool is_comment(const std::string& t) {
  return t.empty() || t[0] == '#' || t[0] == '!' || t[0] == '%';
}

}  // namespace

Profile read_plain_profile(const std::string& path, ProfileKind kind, LengthUnit unit) {
  std::ifstream in = open_profile(path, kind);
  const double to_m = unit == LengthUnit::millimetre ? 1e-3 : 1.0;
  const char* unit_name = unit == LengthUnit::millimetre ? "mm" : "m";
  std::vector<RawProfilePoint> points;
  std::string line;
  std::vector<double> numbers;
  for (int number = 1; std::getline(in, line); ++number) {
    const std::string t = trim(line);
    if (is_comment(t)) continue;
    if (!parse_numbers(t, numbers) || numbers.size() != 2)
      throw ProfileError(where(path, number) + ": expected two numbers (y z in " + unit_name +
                         "), got '" + t + "'");
    points.push_back({numbers[0] * to_m, numbers[1] * to_m, number});
  }
  if (in.bad()) throw ProfileError(path + ": read error");
  return make_profile(kind, path, std::move(points));
}

Profile read_simpack_profile(const std::string& path, ProfileKind kind) {
  std::ifstream in = open_profile(path, kind);
  enum class Section { none, header, spline, points };
  Section section = Section::none;
  bool seen_points = false, seen_spline_end = false;
  std::map<std::string, double> values;   // numeric keys of header and spline
  std::map<std::string, int> value_line;
  std::vector<RawProfilePoint> raw;       // in file units, SIMPACK frame
  std::string line;
  std::vector<double> numbers;
  int number = 0;
  auto fail_nesting = [&](const std::string& keyword) {
    throw ProfileError(where(path, number) + ": '" + keyword +
                       "' out of place; expected header.begin/end, then spline.begin, "
                       "point.begin ... point.end, spline.end");
  };
  while (std::getline(in, line)) {
    ++number;
    std::string t = trim(line);
    const size_t bang = t.find('!');
    if (bang != std::string::npos) t = trim(t.substr(0, bang));
    if (t.empty()) continue;
    if (t == "header.begin") {
      if (section != Section::none) fail_nesting(t);
      section = Section::header;
    } else if (t == "header.end") {
      if (section != Section::header) fail_nesting(t);
      section = Section::none;
    } else if (t == "spline.begin") {
      if (section != Section::none) fail_nesting(t);
      section = Section::spline;
    } else if (t == "spline.end") {
      if (section != Section::spline) fail_nesting(t);
      section = Section::none;
      seen_spline_end = true;
    } else if (t == "point.begin") {
      if (section != Section::spline) fail_nesting(t);
      section = Section::points;
      seen_points = true;
    } else if (t == "point.end") {
      if (section != Section::points) fail_nesting(t);
      section = Section::spline;
    } else if (section == Section::points) {
      if (!parse_numbers(t, numbers) || numbers.size() < 2 || numbers.size() > 3)
        throw ProfileError(where(path, number) +
                           ": expected a profile point 'y z [weight]' (numbers in the header's "
                           "length unit), got '" + t + "'");
      raw.push_back({numbers[0], numbers[1], number});
    } else if (section == Section::header || section == Section::spline) {
      const size_t eq = t.find('=');
      if (eq == std::string::npos)
        throw ProfileError(where(path, number) + ": expected 'key = value', got '" + t + "'");
      const std::string key = trim(t.substr(0, eq));
      const std::string value = trim(t.substr(eq + 1));
      if (!value.empty() && value[0] == '\'') continue;  // strings: file, comment
      if (!parse_numbers(value, numbers) || numbers.size() != 1)
        throw ProfileError(where(path, number) + ": key '" + key + "': expected a number, got '" +
                           value + "'");
      const std::string full = (section == Section::header ? "header." : "") + key;
      values[full] = numbers[0];
      value_line[full] = number;
    } else {
      throw ProfileError(where(path, number) + ": unexpected text outside the sections: '" + t +
                         "'");
    }
  }
  if (in.bad()) throw ProfileError(path + ": read error");
  if (!seen_points || !seen_spline_end || section != Section::none)
    throw ProfileError(path + ": incomplete SIMPACK profile; expected a spline section with "
                              "point.begin ... point.end and spline.end");

  auto get = [&](const std::string& key, double fallback) {
    const auto it = values.find(key);
    return it == values.end() ? fallback : it->second;
  };
  auto line_of = [&](const std::string& key) {
    const auto it = value_line.find(key);
    return it == value_line.end() ? 0 : it->second;
  };
  const int expected_type = kind == ProfileKind::wheel ? 1 : 0;
  if (values.count("header.type") && int(get("header.type", -1)) != expected_type)
    throw ProfileError(where(path, line_of("header.type")) + ": header type = " +
                       std::to_string(int(get("header.type", -1))) + "; expected " +
                       std::to_string(expected_type) + " for a " + profile_kind_name(kind) +
                       " profile (0 = rail .prr, 1 = wheel .prw)");
  const double units_per_metre = get("units.len.f", 1.0);
  if (!(units_per_metre > 0.0))
    throw ProfileError(where(path, line_of("units.len.f")) +
                       ": units.len.f must be a positive length unit per metre (1000 for mm)");
  const double angle_units_per_rad = get("units.ang.f", 1.0);
  if (get("rotate", 0.0) / angle_units_per_rad != 0.0)
    throw ProfileError(where(path, line_of("rotate")) +
                       ": rotate is not supported; expected 0 (give the rail inclination as "
                       "rail_inclination_rad instead)");

  // SIMPACK order: shift, bounds, mirror, inversion; then the unit.
  const double shift_y = get("shift.y", 0.0), shift_z = get("shift.z", 0.0);
  for (RawProfilePoint& p : raw) p.y_m += shift_y, p.z_m += shift_z;
  const double by0 = get("bound.y.min", 1.0), by1 = get("bound.y.max", 0.0);
  if (by0 < by1)
    raw.erase(std::remove_if(raw.begin(), raw.end(),
                             [&](const RawProfilePoint& p) { return p.y_m < by0 || p.y_m > by1; }),
              raw.end());
  const double bz0 = get("bound.z.min", 1.0), bz1 = get("bound.z.max", 0.0);
  if (bz0 < bz1)
    for (RawProfilePoint& p : raw) p.z_m = std::clamp(p.z_m, bz0, bz1);
  const bool mirror_y = get("mirror.y", 0.0) == 1.0, mirror_z = get("mirror.z", 0.0) == 1.0;
  for (RawProfilePoint& p : raw) {
    if (mirror_y) p.y_m = -p.y_m;
    if (mirror_z) p.z_m = -p.z_m;
    // to metres, and z from SIMPACK's downward axis to railstab's upward one
    p.y_m /= units_per_metre;
    p.z_m = -p.z_m / units_per_metre;
  }
  if (get("inversion", 0.0) == 1.0) std::reverse(raw.begin(), raw.end());
  return make_profile(kind, path, std::move(raw));
}

Profile read_profile_file(const std::string& path, ProfileKind kind, LengthUnit plain_unit) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".prw" || ext == ".prr") return read_simpack_profile(path, kind);
  return read_plain_profile(path, kind, plain_unit);
}

}  // namespace railstab
