#include <railstab/io/csv.hpp>

#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace railstab {

std::string csv_field(std::string_view text) {
  bool plain = true;
  for (unsigned char c : text)
    if (c < 0x20 || c == 0x7F || c == ',' || c == '"') plain = false;
  if (plain) return std::string(text);
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + '"';
}

void throw_non_finite(double value, std::string_view what) {
  std::ostringstream msg;
  msg << "non-finite value " << value << " for " << what << "; refusing to write it";
  throw std::runtime_error(msg.str());
}

std::string csv_number(double value, std::string_view what, int precision) {
  if (!std::isfinite(value)) throw_non_finite(value, what);
  std::ostringstream s;
  s << std::setprecision(precision) << value;
  return s.str();
}

int csv_physical_lines(std::string_view text) {
  int lines = 1;
  for (char c : text)
    if (c == '\n') ++lines;
  return lines;
}

}  // namespace railstab
