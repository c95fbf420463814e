#include <railstab/setup/initial_offsets.hpp>

#include <railstab/scene/physical_ranges.hpp>
#include <railstab/scene_reading/coordinate_keys.hpp>
#include <railstab/scene_reading/scene_error.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>

namespace railstab {

namespace {

std::string known_coordinate_keys() {
  std::string keys;
  for (const scene_reading::CoordinateKey& k : scene_reading::kOffsetKeys)
    keys += (keys.empty() ? "" : ", ") + std::string(k.key);
  return keys;
}

[[noreturn]] void fail_form(const std::string& text, const std::string& expected) {
  throw std::invalid_argument("--offset '" + text + "': expected " + expected);
}

std::string number_text(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

}  // namespace

OffsetSetting parse_offset_setting(const std::string& text) {
  const std::string form = "BODY.COORDINATE=VALUE, e.g. wheelset1.y_m=0.005";
  const size_t equals = text.find('=');
  if (equals == std::string::npos) fail_form(text, form + " (no '=')");
  const std::string key = text.substr(0, equals), value_text = text.substr(equals + 1);
  const size_t dot = key.rfind('.');
  if (dot == std::string::npos || dot == 0) fail_form(text, form + " (no body name before '.')");
  OffsetSetting s;
  s.text = text;
  s.body = key.substr(0, dot);
  const std::string coordinate = key.substr(dot + 1);
  s.coordinate = -1;
  for (int c = 0; c < 6; ++c)
    if (scene_reading::kOffsetKeys[size_t(c)].key == coordinate) s.coordinate = c;
  if (s.coordinate < 0)
    fail_form(text, "a coordinate key of initial_offset (" + known_coordinate_keys() + "), got '" +
                        coordinate + "'");
  const char* first = value_text.data();
  const char* last = first + value_text.size();
  const auto parsed = std::from_chars(first, last, s.value);
  if (value_text.empty() || parsed.ec != std::errc{} || parsed.ptr != last || !std::isfinite(s.value))
    fail_form(text, "a finite number after '=' (m or rad), got '" + value_text + "'");
  return s;
}

std::vector<int> bodies_moved_by(const SceneSpec& spec, const OffsetSetting& setting) {
  int named = -1;
  for (size_t b = 0; b < spec.bodies.size(); ++b)
    if (spec.bodies[b].name == setting.body) named = int(b);
  if (named < 0) {
    std::string names;
    for (const BodySpec& b : spec.bodies) names += (names.empty() ? "" : ", ") + b.name;
    throw SceneError(spec.source_path + ": --offset '" + setting.text + "': no body named '" +
                     setting.body + "' (the scene's bodies: " + names + ")");
  }
  std::vector<int> moved{named};
  if (spec.bodies[size_t(named)].is_wheelset) return moved;
  // A bogie frame: the wheelsets joined to it by a force element.
  for (const ElementSpec& element : spec.elements) {
    const ElementEnds& ends = ends_of(element);
    for (const auto& [frame, other] : {std::pair{ends.body1_name, ends.body2_name},
                                       std::pair{ends.body2_name, ends.body1_name}}) {
      if (frame != setting.body) continue;
      for (size_t b = 0; b < spec.bodies.size(); ++b)
        if (spec.bodies[b].name == other && spec.bodies[b].is_wheelset &&
            std::find(moved.begin(), moved.end(), int(b)) == moved.end())
          moved.push_back(int(b));
    }
  }
  return moved;
}

void apply_offset_settings(SceneSpec& spec, const std::vector<OffsetSetting>& settings) {
  for (const OffsetSetting& s : settings) {
    const bool angle = s.coordinate >= 3;
    const PhysicalRange& range = angle ? physical_ranges::offset_rad : physical_ranges::offset_m;
    if (!range.contains(s.value))
      throw SceneError(spec.source_path + ": --offset '" + s.text + "': expected " +
                       std::string(range.noun) + " in [" + number_text(range.low) + ", " +
                       number_text(range.high) + "] " + std::string(range.unit) + ", got " +
                       number_text(s.value));
    for (int b : bodies_moved_by(spec, s)) spec.bodies[size_t(b)].initial_offset[size_t(s.coordinate)] = s.value;
  }
}

}  // namespace railstab
