#include <railstab/io/file_names.hpp>

#include <cmath>
#include <stdexcept>

namespace railstab {

namespace {

bool allowed(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '.' ||
         c == '_' || c == '-';
}

}  // namespace

std::string file_stem(std::string_view name) {
  std::string stem;
  for (char c : name) {
    if (stem.size() == kMaxFileStemLength) break;
    stem += allowed(c) ? c : '_';
  }
  if (stem.empty()) return "unnamed";
  if (stem.front() == '.') stem.front() = '_';
  return stem;
}

std::string scene_file_stem(std::string_view scene_path) {
  const std::string_view name = scene_path.substr(scene_path.find_last_of('/') + 1);  // npos + 1 = 0
  const size_t dot = name.rfind('.');
  // "a.toml" -> "a"; a name that is only an extension (".toml") keeps it.
  return file_stem(dot == std::string_view::npos || dot == 0 ? name : name.substr(0, dot));
}

std::string speed_file_tag(double speed_m_per_s) {
  if (!std::isfinite(speed_m_per_s) || std::abs(speed_m_per_s) > 1e6)
    throw std::invalid_argument("speed " + std::to_string(speed_m_per_s) +
                                " m/s: expected a finite speed to name the output files");
  // Two decimals, trailing zeros dropped: 30 -> "30mps", 36.9 -> "36.9mps",
  // 36.904 -> "36.9mps", 12.346 -> "12.35mps" (runs 0.01 m/s apart differ).
  const long hundredths = std::lround(speed_m_per_s * 100.0);
  std::string tag = std::to_string(hundredths / 100);
  const long frac = std::labs(hundredths % 100);
  if (frac != 0) {
    tag += "." + std::to_string(frac / 10);
    if (frac % 10 != 0) tag += std::to_string(frac % 10);
  }
  return tag + "mps";
}

bool is_safe_file_name(std::string_view file_name) {
  if (file_name.empty() || file_name.size() > 255 || file_name.front() == '.') return false;
  for (char c : file_name)
    if (!allowed(c)) return false;
  return true;
}

}  // namespace railstab
