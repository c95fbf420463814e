#include <railstab/report/parameter_titles.hpp>

#include <algorithm>
#include <array>
#include <sstream>
#include <string_view>

namespace railstab {

namespace {

// Unit words as scene keys spell them, and how a title writes each.
constexpr std::array<std::pair<std::string_view, std::string_view>, 26> kUnitWords = {{
    {"m", "m"},     {"mm", "mm"},   {"km", "km"},   {"kg", "kg"},   {"t", "t"},
    {"s", "s"},     {"ms", "ms"},   {"N", "N"},     {"kN", "kN"},   {"Nm", "N m"},
    {"rad", "rad"}, {"mrad", "mrad"}, {"deg", "deg"}, {"Hz", "Hz"}, {"m2", "m^2"},
    {"m3", "m^3"},  {"s2", "s^2"},  {"Pa", "Pa"},   {"MPa", "MPa"}, {"GPa", "GPa"},
    {"per", "/"},   {"kgm2", "kg m^2"}, {"m4", "m^4"}, {"W", "W"}, {"J", "J"}, {"Ns", "N s"}}};

const std::string_view* unit_text(std::string_view word) {
  for (const auto& [w, text] : kUnitWords)
    if (w == word) return &text;
  return nullptr;
}

std::string spaced(std::string_view name) {
  std::string s(name);
  std::replace(s.begin(), s.end(), '_', ' ');
  return s;
}

// Four significant digits, the exponent without '+' and leading zeros:
// 4.5e6, 1.2e-5, 250.
std::string short_number(double v) {
  std::ostringstream s;
  s.precision(4);
  s << v;
  std::string t = s.str();
  const size_t e = t.find('e');
  if (e == std::string::npos) return t;
  std::string mantissa = t.substr(0, e), exponent = t.substr(e + 1);
  const bool negative = !exponent.empty() && exponent[0] == '-';
  if (!exponent.empty() && (exponent[0] == '+' || exponent[0] == '-')) exponent.erase(0, 1);
  while (exponent.size() > 1 && exponent[0] == '0') exponent.erase(0, 1);
  return mantissa + "e" + (negative ? "-" : "") + exponent;
}

}  // namespace

std::string parameter_axis_title(const std::string& key) {
  // Linked keys ("K1,K2", study --vary): every key's title, as one value.
  if (const size_t comma = key.find(','); comma != std::string::npos)
    return parameter_axis_title(key.substr(0, comma)) + " = " + parameter_axis_title(key.substr(comma + 1));
  std::string path = key, component;
  // A vector component: [0] [1] [2] are x, y, z; others by number.
  if (const size_t open = path.rfind('['); open != std::string::npos && path.back() == ']') {
    const std::string index = path.substr(open + 1, path.size() - open - 2);
    component = index == "0" ? "x" : index == "1" ? "y" : index == "2" ? "z" : "component " + index;
    path.resize(open);
  }
  const size_t last_dot = path.rfind('.');
  const std::string leaf = last_dot == std::string::npos ? path : path.substr(last_dot + 1);
  std::string owner;
  if (last_dot != std::string::npos) {
    const std::string head = path.substr(0, last_dot);
    const size_t dot = head.rfind('.');
    owner = spaced(dot == std::string::npos ? head : head.substr(dot + 1));
  }
  std::vector<std::string_view> words;
  std::string_view rest(leaf);
  while (true) {
    const size_t u = rest.find('_');
    words.push_back(rest.substr(0, u));
    if (u == std::string_view::npos) break;
    rest.remove_prefix(u + 1);
  }
  // Trailing unit words (the first word always names the quantity).
  size_t first_unit = words.size();
  while (first_unit > 1 && unit_text(words[first_unit - 1])) --first_unit;
  if (first_unit < words.size() && words[first_unit] == "per") ++first_unit;  // "per" cannot lead
  std::string name, unit;
  for (size_t k = 0; k < first_unit; ++k) name += (k ? " " : "") + std::string(words[k]);
  for (size_t k = first_unit; k < words.size(); ++k) {
    const std::string_view text = *unit_text(words[k]);
    if (text == "/") {
      unit += "/";
    } else {
      if (!unit.empty() && unit.back() != '/') unit += " ";
      unit += text;
    }
  }
  std::string title = owner.empty() ? name : owner + ": " + name;
  if (!component.empty()) title += ", " + component;
  if (!unit.empty()) title += " [" + unit + "]";
  return title;
}

std::string gnuplot_value_tics(const std::vector<double>& values, size_t max_ticks) {
  const size_t n = values.size();
  const size_t every = n <= max_ticks || max_ticks < 2 ? 1 : (n - 1 + max_ticks - 2) / (max_ticks - 1);
  std::ostringstream s;
  s.precision(17);
  s << "(";
  bool first = true;
  for (size_t k = 0; k < n; ++k) {
    if (k % every != 0 && k + 1 != n) continue;
    s << (first ? "" : ", ") << "'" << short_number(values[k]) << "' " << values[k];
    first = false;
  }
  s << ")";
  return s.str();
}

const char* const kViridisPalette =
    "(0 '#440154', 1 '#472d7b', 2 '#3b528b', 3 '#2c728e', 4 '#21918c', 5 '#28ae80', "
    "6 '#5ec962', 7 '#addc30', 8 '#fde725')";

}  // namespace railstab
