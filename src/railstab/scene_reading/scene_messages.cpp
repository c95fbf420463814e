#include <railstab/scene_reading/scene_messages.hpp>

#include <charconv>
#include <cstdio>

namespace railstab::scene_reading {

std::string format_number(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

std::string format_vector(const Eigen::Vector3d& v) {
  return "[" + format_number(v.x()) + ", " + format_number(v.y()) + ", " + format_number(v.z()) +
         "]";
}

std::string quoted(std::string_view text) { return "'" + std::string(text) + "'"; }

std::string comma_separated(const std::vector<std::string>& items) {
  if (items.empty()) return "none";
  std::string text;
  for (const std::string& item : items) text += (text.empty() ? "" : ", ") + item;
  return text;
}

std::string child_path(std::string_view parent, std::string_view key) {
  if (parent.empty()) return std::string(key);
  return std::string(parent) + "." + std::string(key);
}

std::string indexed_path(std::string_view array_path, size_t index) {
  return std::string(array_path) + "[" + std::to_string(index) + "]";
}

SceneError scene_error(std::string_view source, std::string_view key_path,
                       std::string_view message) {
  return SceneError(std::string(source) + ": " + std::string(key_path) + ": " +
                    std::string(message));
}

void fail_expectation(std::string_view source, std::string_view key_path,
                      std::string_view expected, std::string_view found) {
  throw scene_error(source, key_path,
                    "expected " + std::string(expected) + ", got " + std::string(found));
}

std::string range_text(const PhysicalRange& range) {
  return std::string(range.noun) + " in " + (range.low_open ? "(" : "[") +
         format_number(range.low) + ", " + format_number(range.high) + "]" +
         (range.unit.empty() ? "" : " " + std::string(range.unit));
}

// Names end up in messages on a terminal, CSV headers, JSON, Markdown and
// gnuplot titles. Every format escapes them (io/csv.hpp, io/json_writer.hpp),
// but a control character (ESC, CR, a C1 code) in a message printed to a
// terminal is a terminal command, and no engineer means a tab or a newline
// in a body name: such names are refused here, as are names longer than
// kMaxNameBytes (a 4000-character name made file names too long). Any other
// UTF-8 text is allowed ("Drehgestell 1", "w,1" and quotes are escaped).
std::optional<std::string> name_problem(std::string_view name, size_t max_bytes) {
  if (name.empty()) return "an empty name";
  if (name.size() > max_bytes)
    return "a name of " + std::to_string(name.size()) + " bytes";
  for (size_t i = 0; i < name.size(); ++i) {
    const unsigned char u = static_cast<unsigned char>(name[i]);
    const bool c1 = u == 0xC2 && i + 1 < name.size() &&
                    static_cast<unsigned char>(name[i + 1]) >= 0x80 &&
                    static_cast<unsigned char>(name[i + 1]) <= 0x9F;
    if (u < 0x20 || u == 0x7F || c1) {
      char code[8];
      std::snprintf(code, sizeof code, "0x%02X", c1 ? unsigned(static_cast<unsigned char>(name[i + 1])) : unsigned(u));
      return "a control character (" + std::string(code) + ") at byte " + std::to_string(i);
    }
  }
  return std::nullopt;
}

const std::string& name_expectation() {
  static const std::string text = "a name of 1 to " +
                                  std::to_string(physical_ranges::kMaxNameBytes) +
                                  " bytes without control characters";
  return text;
}

}  // namespace railstab::scene_reading
