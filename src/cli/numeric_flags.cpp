#include "cli/numeric_flags.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace railstab {

std::string range_text(const FlagRange& r) {
  std::ostringstream s;
  s << (r.low_open ? '(' : '[') << r.low << ", " << r.high << (r.high_open ? ')' : ']');
  if (!r.unit.empty()) s << ' ' << r.unit;
  return s.str();
}

CLI::Validator finite_in(const FlagRange& range) {
  const std::string expected = "expected a finite number in " + range_text(range);
  return CLI::Validator(
      [range, expected](std::string& text) -> std::string {
        const std::string got = ", got \"" + text + "\"";
        const char* begin = text.c_str();
        char* end = nullptr;
        errno = 0;
        const double v = std::strtod(begin, &end);
        const bool parsed = end != begin && *end == '\0';
        if (!parsed || !std::isfinite(v) || errno == ERANGE) return expected + got;
        const bool above_low = range.low_open ? v > range.low : v >= range.low;
        const bool below_high = range.high_open ? v < range.high : v <= range.high;
        if (!above_low || !below_high) return expected + got;
        return {};
      },
      "NUMBER in " + range_text(range));
}

void check_speed_grid(double from, double to, double step, const SpeedGridNames& n) {
  if (!(from < to)) {
    std::ostringstream msg;
    msg << n.from << " " << from << " m/s must be below " << n.to << " " << to << " m/s";
    throw std::invalid_argument(msg.str());
  }
  const double points = std::floor((to - from) / step) + 1.0;
  if (!(points <= kMaxSpeedGridPoints)) {
    std::ostringstream msg;
    msg << "the speed grid from " << n.from << " " << from << " to " << n.to << " " << to
        << " m/s with " << n.step << " " << step << " m/s would have " << points
        << " points; at most " << int(kMaxSpeedGridPoints) << " (raise " << n.step
        << " or narrow the range)";
    throw std::invalid_argument(msg.str());
  }
}

std::vector<std::string> colon_fields(const std::string& text) {
  std::vector<std::string> parts;
  std::stringstream ss(text);
  for (std::string p; std::getline(ss, p, ':');) parts.push_back(p);
  if (!text.empty() && text.back() == ':') parts.push_back("");
  return parts;
}

FieldNumber read_field_number(const std::string& field, double& value) {
  size_t used = 0;
  try {
    value = std::stod(field, &used);
  } catch (const std::exception&) {
    return FieldNumber::not_a_number;
  }
  return used == field.size() ? FieldNumber::ok : FieldNumber::trailing_text;
}

}  // namespace railstab
