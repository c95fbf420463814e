// Scene files (TOML) -> SceneSpec, and the semantic checks on a SceneSpec.
//
// Sections of a scene file (complete, commented examples: cases/*.toml):
//   [scene]             name, speed_m_per_s, reference_arc_length_m,
//                       gravity_m_per_s2 (9.81), preload ("balance_gravity_at_nominal")
//   [track]             start_* (0), rail_contact_distance_m (1.5),
//   [[track.segments]]  type = tangent | clothoid | arc, length_m, end_cant_m
//                       (default: the cant the segment starts with); a clothoid
//                       takes end_radius_m + turn, or end_curvature_per_m
//   [contacts.<name>]   geometry, normal, tangential (+ their numbers)
//   [[bodies]]          name, type, mass_kg, inertia_kg_m2, position_m, ...
//   [[elements]]        name, type, body1, body2, points, stiffness, damping, ...
//   [simulation]        optional: t_end_s, output_interval_s, integrator, integrator_order,
//                       relative_tolerance, absolute_tolerance
//   [train]             optional: cars, car_spacing_m, [[train.couplers]] (elements
//                       between consecutive cars): N copies of the vehicle (scene/train.hpp)
//
// How this file is organised:
//   1. message helpers        every error reads "<file>: <key path>: expected ..., got ..."
//   2. key suggestions        "unknown key (did you mean 'mass_kg'?)"
//   3. TableReader            reads one typed key of one TOML table, with its key path
//   4. section readers        one function per part of the file
//   5. SceneChecker           validate_scene: the semantic checks
//   6. public API
#include <railstab/io/scene_loader.hpp>


#include <railstab/contact_geometry/profile_contact_geometry.hpp>
#include <railstab/io/regular_file.hpp>
#include <railstab/scene/physical_ranges.hpp>
#include <railstab/scene/train.hpp>

#include <toml++/toml.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <optional>
#include <sstream>
#include <string_view>
#include <utility>
#include <vector>

namespace railstab {
namespace {

// ============================================================================
// 1. Message helpers
// ============================================================================

// Shortest text that reads back as the same double: -3, 0.1, 2.1e+11.
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

// "a, b, c" (or "none" for an empty list).
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

// The uniform message: "<file>: <key path>: expected <expected>, got <found>".
[[noreturn]] void fail_expectation(std::string_view source, std::string_view key_path,
                                   std::string_view expected, std::string_view found) {
  throw scene_error(source, key_path,
                    "expected " + std::string(expected) + ", got " + std::string(found));
}

// What a TOML value is, for the "got ..." part of a message.
std::string describe_found(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::string:
      return "a string " + quoted(node.as_string()->get());
    case toml::node_type::integer:
      return std::to_string(node.as_integer()->get());
    case toml::node_type::floating_point:
      return format_number(node.as_floating_point()->get());
    case toml::node_type::boolean:
      return node.as_boolean()->get() ? "true" : "false";
    case toml::node_type::array: {
      const size_t size = node.as_array()->size();
      return "an array of " + std::to_string(size) + (size == 1 ? " element" : " elements");
    }
    case toml::node_type::table:
      return "a table";
    case toml::node_type::date:
    case toml::node_type::time:
    case toml::node_type::date_time:
      return "a date/time";
    default:
      return "nothing";
  }
}

const char* const kMissingKey = "nothing (the key is missing)";

// "a mass in [0.1, 1e6] kg" (scene/physical_ranges.hpp).
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
std::optional<std::string> name_problem(std::string_view name,
                                        size_t max_bytes = physical_ranges::kMaxNameBytes) {
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
const std::string kNameExpectation =
    "a name of 1 to " + std::to_string(physical_ranges::kMaxNameBytes) +
    " bytes without control characters";

// ============================================================================
// 2. Key suggestions
// ============================================================================

std::string lower_case(std::string_view text) {
  std::string lower(text);
  for (char& c : lower) c = char(std::tolower(static_cast<unsigned char>(c)));
  return lower;
}

bool is_unit_word(std::string_view word) {
  static const std::vector<std::string_view> kUnitWords = {
      "m",  "mm",  "cm",  "km",  "kg",  "g",   "s",    "ms",  "h",  "min", "n",  "kn",
      "pa", "kpa", "mpa", "gpa", "rad", "deg", "mrad", "per", "m2", "m3",  "s2", "hz"};
  return std::find(kUnitWords.begin(), kUnitWords.end(), lower_case(word)) != kUnitWords.end();
}

// The key without its unit suffix, lower case: "mass_kg" and "mass_g" -> "mass",
// "speed_m_per_s" -> "speed", "f23_N_m" -> "f23". The first word always stays.
std::string unit_stripped_stem(std::string_view key) {
  std::vector<std::string_view> words;
  size_t start = 0;
  while (start <= key.size()) {
    const size_t end = std::min(key.find('_', start), key.size());
    words.push_back(key.substr(start, end - start));
    start = end + 1;
  }
  while (words.size() > 1 && is_unit_word(words.back())) words.pop_back();
  std::string stem;
  for (std::string_view word : words) stem += (stem.empty() ? "" : "_") + std::string(word);
  return lower_case(stem);
}

// Levenshtein distance (insertions, deletions, substitutions), case-insensitive.
size_t edit_distance(std::string_view a_text, std::string_view b_text) {
  const std::string a = lower_case(a_text), b = lower_case(b_text);
  std::vector<size_t> previous(b.size() + 1), current(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) previous[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
    }
    std::swap(previous, current);
  }
  return previous[b.size()];
}

// The candidate the user most likely meant: one with the same stem before the
// unit suffix, else the nearest within a small edit distance; none if nothing fits.
std::optional<std::string> closest_name(std::string_view name,
                                        const std::vector<std::string_view>& candidates) {
  const std::string stem = unit_stripped_stem(name);
  for (std::string_view candidate : candidates)
    if (unit_stripped_stem(candidate) == stem) return std::string(candidate);
  const size_t allowed = name.size() <= 2 ? 0 : name.size() <= 5 ? 1 : 2;
  std::optional<std::string> best;
  size_t best_distance = allowed + 1;
  for (std::string_view candidate : candidates) {
    const size_t distance = edit_distance(name, candidate);
    if (distance < best_distance) {
      best = std::string(candidate);
      best_distance = distance;
    }
  }
  return best;
}

std::string did_you_mean(std::string_view name, const std::vector<std::string_view>& candidates) {
  const std::optional<std::string> suggestion = closest_name(name, candidates);
  return suggestion ? " (did you mean " + quoted(*suggestion) + "?)" : "";
}

// ============================================================================
// 3. Reading typed values with their key path
// ============================================================================

// Scene-file spellings of an enumeration, e.g. {"tangent", TrackSegmentKind::tangent}.
template <class Value>
using Choices = std::vector<std::pair<std::string_view, Value>>;

// " (kg)", or nothing for a plain ratio.
std::string unit_suffix(std::string_view unit) {
  return unit.empty() ? "" : " (" + std::string(unit) + ")";
}

std::string number_description(std::string_view unit) { return "a number" + unit_suffix(unit); }

// A finite number; integers are accepted where a float is expected.
double number_from(const toml::node& node, std::string_view source, std::string_view path,
                   std::string_view unit) {
  if (!node.is_number())
    fail_expectation(source, path, number_description(unit), describe_found(node));
  const double value = *node.value<double>();
  if (!std::isfinite(value))
    fail_expectation(source, path, "a finite number" + unit_suffix(unit), describe_found(node));
  return value;
}

std::string text_from(const toml::node& node, std::string_view source, std::string_view path) {
  if (!node.is_string()) fail_expectation(source, path, "a string", describe_found(node));
  return node.as_string()->get();
}

template <class Value>
Value choice_from(const toml::node& node, std::string_view source, std::string_view path,
                  const Choices<Value>& choices) {
  std::vector<std::string_view> spellings;
  std::string expected = "one of ";
  for (const auto& [spelling, value] : choices) {
    expected += (spellings.empty() ? "" : ", ") + quoted(spelling);
    spellings.push_back(spelling);
  }
  if (!node.is_string()) fail_expectation(source, path, expected, describe_found(node));
  const std::string& text = node.as_string()->get();
  for (const auto& [spelling, value] : choices)
    if (text == spelling) return value;
  fail_expectation(source, path, expected, quoted(text) + did_you_mean(text, spellings));
}

// One TOML table plus where it sits in the file. It knows the keys the table
// may hold (declared up front, so a misspelt key is reported as such instead
// of as a missing one) and reads each key as one type, with uniform messages.
class TableReader {
 public:
  TableReader(const toml::table& table, std::string key_path, std::string source,
              std::vector<std::string_view> known_keys, std::string owner = "")
      : table_(table),
        key_path_(std::move(key_path)),
        source_(std::move(source)),
        known_keys_(known_keys),
        owner_(std::move(owner)) {
    reject_unknown_keys();
  }

  // The same table read with a narrower set of keys (e.g. once an element's
  // type is known); `owner` names what the keys belong to in messages.
  TableReader with_keys(std::vector<std::string_view> known_keys, std::string owner) const {
    return TableReader(table_, key_path_, source_, std::move(known_keys), std::move(owner));
  }

  const std::string& source() const { return source_; }
  const std::string& key_path() const { return key_path_; }
  std::string path_of(std::string_view key) const { return child_path(key_path_, key); }
  bool has(std::string_view key) const { return find(key) != nullptr; }

  [[noreturn]] void fail(std::string_view key, std::string_view expected,
                         std::string_view found) const {
    fail_expectation(source_, path_of(key), expected, found);
  }
  // An error about the table as a whole (e.g. a combination of keys).
  [[noreturn]] void fail_here(std::string_view expected, std::string_view found) const {
    fail_expectation(source_, key_path_, expected, found);
  }
  [[noreturn]] void fail_missing(std::string_view key, std::string_view expected) const {
    fail(key, expected, kMissingKey);
  }

  double number(std::string_view key, std::string_view unit) const {
    return number_from(required(key, number_description(unit)), source_, path_of(key), unit);
  }
  double number_or(std::string_view key, std::string_view unit, double fallback) const {
    return has(key) ? number(key, unit) : fallback;
  }

  std::string text(std::string_view key) const {
    return text_from(required(key, "a string"), source_, path_of(key));
  }

  bool flag_or(std::string_view key, bool fallback) const {
    const toml::node* node = find(key);
    if (!node) return fallback;
    if (!node->is_boolean()) fail(key, "true or false", describe_found(*node));
    return node->as_boolean()->get();
  }

  // An array of exactly three numbers, e.g. [0.0, 1.0, -0.6075].
  Eigen::Vector3d vector3(std::string_view key, std::string_view unit) const {
    const std::string expected = "an array of 3 numbers" + unit_suffix(unit);
    const toml::node& node = required(key, expected);
    const toml::array* array = node.as_array();
    if (!array || array->size() != 3) fail(key, expected, describe_found(node));
    Eigen::Vector3d vector;
    for (size_t i = 0; i < 3; ++i)
      vector(Eigen::Index(i)) =
          number_from(*array->get(i), source_, indexed_path(path_of(key), i), unit);
    return vector;
  }
  Eigen::Vector3d vector3_or(std::string_view key, std::string_view unit,
                             const Eigen::Vector3d& fallback) const {
    return has(key) ? vector3(key, unit) : fallback;
  }

  template <class Value>
  Value choice(std::string_view key, const Choices<Value>& choices) const {
    return choice_from(required(key, "a string"), source_, path_of(key), choices);
  }
  template <class Value>
  Value choice_or(std::string_view key, const Choices<Value>& choices, Value fallback) const {
    return has(key) ? choice(key, choices) : fallback;
  }

  const toml::array& array(std::string_view key, std::string_view expected) const {
    const toml::node& node = required(key, expected);
    if (!node.is_array()) fail(key, expected, describe_found(node));
    return *node.as_array();
  }

  // A sub-table ([track], initial_offset = {...}) or nothing if the key is absent.
  const toml::table* raw_table_or_null(std::string_view key) const {
    const toml::node* node = find(key);
    if (!node) return nullptr;
    if (!node->is_table()) fail(key, "a table", describe_found(*node));
    return node->as_table();
  }
  std::optional<TableReader> optional_table(std::string_view key,
                                            const std::vector<std::string_view>& known_keys) const {
    const toml::table* table = raw_table_or_null(key);
    if (!table) return std::nullopt;
    return TableReader(*table, path_of(key), source_, known_keys);
  }
  TableReader table(std::string_view key, const std::vector<std::string_view>& known_keys) const {
    if (!has(key)) fail_missing(key, "a table [" + path_of(key) + "]");
    return *optional_table(key, known_keys);
  }

  // [[bodies]] and the like: one reader per table, key paths "bodies[i]".
  std::vector<TableReader> tables_in_array(std::string_view key,
                                           const std::vector<std::string_view>& known_keys) const {
    const toml::array& tables = array(key, "an array of tables [[" + path_of(key) + "]]");
    std::vector<TableReader> readers;
    for (size_t i = 0; i < tables.size(); ++i) {
      const toml::node& element = *tables.get(i);
      const std::string path = indexed_path(path_of(key), i);
      if (!element.is_table()) fail_expectation(source_, path, "a table", describe_found(element));
      readers.emplace_back(*element.as_table(), path, source_, known_keys);
    }
    return readers;
  }
  std::vector<TableReader> tables_in_array_or_none(
      std::string_view key, const std::vector<std::string_view>& known_keys) const {
    return has(key) ? tables_in_array(key, known_keys) : std::vector<TableReader>{};
  }

  // For keys that are known but do not belong with the other values given
  // (e.g. end_radius_m on a tangent segment): an error if present.
  void reject_if_present(std::string_view key, std::string_view expected) const {
    if (const toml::node* node = find(key)) fail(key, expected, describe_found(*node));
  }

 private:
  const toml::node* find(std::string_view key) const {
    if (std::find(known_keys_.begin(), known_keys_.end(), key) == known_keys_.end())
      throw std::logic_error("scene_loader: key '" + std::string(key) +
                             "' is read but not declared for " + key_path_);
    return table_.get(key);
  }

  const toml::node& required(std::string_view key, std::string_view expected) const {
    const toml::node* node = find(key);
    if (!node) fail_missing(key, expected);
    return *node;
  }

  void reject_unknown_keys() const {
    for (const auto& [key, value] : table_) {
      const std::string_view name = key.str();
      if (std::find(known_keys_.begin(), known_keys_.end(), name) != known_keys_.end()) continue;
      throw scene_error(source_, path_of(name),
                        (owner_.empty() ? "unknown key" : "no such key on " + owner_) +
                            did_you_mean(name, known_keys_));
    }
  }

  const toml::table& table_;
  std::string key_path_;
  std::string source_;
  std::vector<std::string_view> known_keys_;
  std::string owner_;
};

// ============================================================================
// 4. Section readers
// ============================================================================

const Choices<PreloadMode> kPreloadModes = {
    {"balance_gravity_at_nominal", PreloadMode::balance_gravity_at_nominal},
    {"none", PreloadMode::none}};
const Choices<TrackSegmentKind> kSegmentKinds = {{"tangent", TrackSegmentKind::tangent},
                                                 {"clothoid", TrackSegmentKind::clothoid},
                                                 {"arc", TrackSegmentKind::arc}};
const Choices<double> kTurnSigns = {{"left", +1.0}, {"right", -1.0}};
const Choices<ContactGeometryKind> kContactGeometries = {
    {"knife_edge_cone", ContactGeometryKind::knife_edge_cone},
    {"linear_conicity", ContactGeometryKind::linear_conicity},
    {"profiles", ContactGeometryKind::profiles}};
const Choices<NormalForceKind> kNormalForces = {{"hertz", NormalForceKind::hertz},
                                                {"prescribed", NormalForceKind::prescribed}};
const Choices<TangentialForceKind> kTangentialForces = {
    {"kalker_hertz", TangentialForceKind::kalker_hertz},
    {"constant", TangentialForceKind::constant},
    {"none", TangentialForceKind::none}};
const Choices<bool> kBodyIsWheelset = {{"wheelset", true}, {"rigid_body", false}};

// --- [scene] -------------------------------------------------------------------
void read_scene_section(const TableReader& section, SceneSpec& scene) {
  scene.name = section.text("name");
  scene.speed_m_per_s = section.number("speed_m_per_s", "m/s");
  scene.gravity_m_per_s2 = section.number_or("gravity_m_per_s2", "m/s2", scene.gravity_m_per_s2);
  scene.reference_arc_length_m = section.number("reference_arc_length_m", "m");
  scene.preload = section.choice_or("preload", kPreloadModes, scene.preload);
}

// --- [track] ---------------------------------------------------------------------
double read_clothoid_end_curvature(const TableReader& segment) {
  const bool by_radius = segment.has("end_radius_m");
  const bool by_curvature = segment.has("end_curvature_per_m");
  if (by_radius == by_curvature)
    segment.fail_here(
        "exactly one of end_radius_m (with turn) and end_curvature_per_m for a clothoid",
        by_radius ? "both" : "neither");
  if (by_curvature) {
    segment.reject_if_present(
        "turn", "no turn with end_curvature_per_m (its sign is the direction: > 0 turns left)");
    return segment.number("end_curvature_per_m", "1/m");
  }
  const double radius = segment.number("end_radius_m", "m");
  if (!physical_ranges::curve_radius_m.contains(radius))
    segment.fail("end_radius_m",
                 range_text(physical_ranges::curve_radius_m) +
                     " (end_curvature_per_m = 0 ends a curve)",
                 format_number(radius));
  return segment.choice("turn", kTurnSigns) / radius;
}

void reject_clothoid_keys(const TableReader& segment, std::string_view kind) {
  for (std::string_view key : {"end_radius_m", "turn", "end_curvature_per_m"})
    segment.reject_if_present(
        key, "no " + std::string(key) + " on " + std::string(kind) +
                 " (only a clothoid sets its end curvature; an arc keeps the one it starts with)");
}

TrackSegmentSpec read_segment(const TableReader& segment, double start_curvature_per_m,
                              double start_cant_m) {
  TrackSegmentSpec spec;
  spec.kind = segment.choice("type", kSegmentKinds);
  spec.length_m = segment.number("length_m", "m");
  spec.end_cant_m = segment.number_or("end_cant_m", "m", start_cant_m);
  switch (spec.kind) {
    case TrackSegmentKind::tangent:
      reject_clothoid_keys(segment, "a tangent segment");
      spec.end_curvature_per_m = 0.0;
      break;
    case TrackSegmentKind::arc:
      reject_clothoid_keys(segment, "an arc segment");
      spec.end_curvature_per_m = start_curvature_per_m;
      break;
    case TrackSegmentKind::clothoid:
      spec.end_curvature_per_m = read_clothoid_end_curvature(segment);
      break;
  }
  return spec;
}

TrackSpec read_track(const TableReader& track) {
  TrackSpec spec;
  spec.start_x_m = track.number_or("start_x_m", "m", spec.start_x_m);
  spec.start_y_m = track.number_or("start_y_m", "m", spec.start_y_m);
  spec.start_z_m = track.number_or("start_z_m", "m", spec.start_z_m);
  spec.start_heading_rad = track.number_or("start_heading_rad", "rad", spec.start_heading_rad);
  spec.start_curvature_per_m =
      track.number_or("start_curvature_per_m", "1/m", spec.start_curvature_per_m);
  spec.start_cant_m = track.number_or("start_cant_m", "m", spec.start_cant_m);
  spec.rail_contact_distance_m =
      track.number_or("rail_contact_distance_m", "m", spec.rail_contact_distance_m);
  double curvature = spec.start_curvature_per_m;
  double cant = spec.start_cant_m;
  for (const TableReader& segment : track.tables_in_array(
           "segments",
           {"type", "length_m", "end_cant_m", "end_radius_m", "turn", "end_curvature_per_m"})) {
    spec.segments.push_back(read_segment(segment, curvature, cant));
    curvature = spec.segments.back().end_curvature_per_m;
    cant = spec.segments.back().end_cant_m;
  }
  return spec;
}

// --- [contacts.<name>] -------------------------------------------------------------
// A number with a default that becomes required for one choice of model
// (e.g. prescribed_wheel_load_N when normal = "prescribed").
double number_required_when(const TableReader& contact, bool required, std::string_view reason,
                            std::string_view key, std::string_view unit, double fallback) {
  if (required && !contact.has(key))
    contact.fail_missing(key, number_description(unit) + ", required " + std::string(reason));
  return contact.number_or(key, unit, fallback);
}

// The creep law of a contact: creep_law = "linear_kalker" (default),
// "shen_hedrick_elkins" or "polach", with friction_coefficient (default the
// law's: 0.4 SHE, 0.55 Polach's mu0), kalker_reduction_factor (1) and
// Polach's polach_limit_friction_ratio (A), polach_friction_decrease_s_per_m
// (B), polach_adhesion_reduction_factor (kA), polach_slip_reduction_factor (kS).
enum class CreepLawChoice { linear_kalker, shen_hedrick_elkins, polach };
const Choices<CreepLawChoice> kCreepLaws = {
    {"linear_kalker", CreepLawChoice::linear_kalker},
    {"shen_hedrick_elkins", CreepLawChoice::shen_hedrick_elkins},
    {"polach", CreepLawChoice::polach}};
const std::array<std::string_view, 5> kPolachKeys = {
    "polach_limit_friction_ratio", "polach_friction_decrease_s_per_m",
    "polach_adhesion_reduction_factor", "polach_slip_reduction_factor", ""};

CreepLawSpec read_creep_law(const TableReader& contact, const ContactSpec& spec) {
  const CreepLawChoice choice =
      contact.choice_or("creep_law", kCreepLaws, CreepLawChoice::linear_kalker);
  const double reduction = contact.number_or("kalker_reduction_factor", "", 1.0);
  if (!(reduction > 0.0 && reduction <= 1.0))
    contact.fail("kalker_reduction_factor", "a number in (0, 1]", format_number(reduction));
  if (choice != CreepLawChoice::polach)
    for (std::string_view key : kPolachKeys)
      if (!key.empty())
        contact.reject_if_present(key, "no " + std::string(key) +
                                           " unless creep_law = \"polach\"");
  auto friction = [&](double fallback) {
    const double mu = contact.number_or("friction_coefficient", "", fallback);
    if (!(mu > 0.0 && mu <= 2.0))
      contact.fail("friction_coefficient", "a number in (0, 2]", format_number(mu));
    return mu;
  };
  CreepLawSpec law;
  switch (choice) {
    case CreepLawChoice::linear_kalker: {
      contact.reject_if_present("friction_coefficient",
                                "no friction_coefficient with creep_law = \"linear_kalker\" (linear "
                                "creep never saturates; choose shen_hedrick_elkins or polach)");
      law = LinearKalkerCreep<double>{reduction};
      break;
    }
    case CreepLawChoice::shen_hedrick_elkins: {
      ShenHedrickElkinsCreep<double> she;
      she.friction_coefficient = friction(she.friction_coefficient);
      she.kalker_reduction_factor = reduction;
      law = she;
      break;
    }
    case CreepLawChoice::polach: {
      if (spec.tangential != TangentialForceKind::kalker_hertz)
        contact.fail("creep_law", "tangential = \"kalker_hertz\" for Polach's method (it needs the "
                                  "contact ellipse)",
                     "'polach' with another tangential model");
      PolachCreep<double> p;
      p.friction_coefficient = friction(p.friction_coefficient);
      p.kalker_reduction_factor = reduction;
      p.limit_friction_ratio = contact.number_or("polach_limit_friction_ratio", "", p.limit_friction_ratio);
      p.friction_decrease_rate_s_per_m =
          contact.number_or("polach_friction_decrease_s_per_m", "s/m", p.friction_decrease_rate_s_per_m);
      p.adhesion_reduction_factor =
          contact.number_or("polach_adhesion_reduction_factor", "", p.adhesion_reduction_factor);
      p.slip_reduction_factor =
          contact.number_or("polach_slip_reduction_factor", "", p.slip_reduction_factor);
      law = p;
      break;
    }
  }
  try {
    std::visit([](const auto& l) { l.validate(); }, law);
  } catch (const std::invalid_argument& e) {
    contact.fail("creep_law", "parameters a creep law accepts", e.what());
  }
  return law;
}

// geometry = "profiles": the keys of the profile files, their placement and
// the contact table's grid (contact_geometry/profile_contact_geometry.hpp).
const std::vector<std::string_view> kProfileKeys = {
    "wheel_profile", "wheel_profile_mm", "wheel_profile_m", "rail_profile", "rail_profile_mm",
    "rail_profile_m", "track_gauge_m", "gauge_measuring_height_m", "flange_back_distance_m",
    "rail_inclination_rad", "tape_circle_from_flange_back_m", "table_lateral_half_range_m",
    "table_lateral_step_m", "table_roll_half_range_rad", "table_roll_step_rad"};
// Keys of the flangeless models that the profiles replace.
const std::vector<std::string_view> kFlangelessKeys = {
    "cone_angle_rad", "conicity", "half_contact_distance_m", "rail_head_transverse_radius_m",
    "flange_clearance_m"};

// One of KEY (a SIMPACK .prw/.prr file, unit from its header), KEY_mm or
// KEY_m (plain two-column text in that unit); the path relative to the scene.
void read_profile_file_key(const TableReader& contact, const std::string& key, std::string& path,
                           LengthUnit& unit) {
  int found = 0;
  for (const auto& [suffix, u] : {std::pair<std::string, LengthUnit>{"", LengthUnit::millimetre},
                                  {"_mm", LengthUnit::millimetre},
                                  {"_m", LengthUnit::metre}}) {
    const std::string k = key + suffix;
    if (!contact.has(k)) continue;
    ++found;
    path = contact.text(k);
    unit = u;
    const auto ends_with = [&](const char* ext) {
      return path.size() >= 4 && path.compare(path.size() - 4, 4, ext) == 0;
    };
    if (suffix.empty() && !ends_with(".prw") && !ends_with(".prr"))
      contact.fail(k, "a SIMPACK .prw/.prr file (a plain-text profile names its unit: " + key +
                          "_mm or " + key + "_m)",
                   quoted(path));
  }
  if (found != 1)
    contact.fail(key, "exactly one of " + key + " (SIMPACK), " + key + "_mm or " + key +
                          "_m (plain text)",
                 found == 0 ? std::string(kMissingKey) : std::to_string(found) + " of them");
  path = path_relative_to_file(contact.source(), path);
}

ProfileSourceSpec read_profile_source(const TableReader& contact) {
  ProfileSourceSpec s;
  read_profile_file_key(contact, "wheel_profile", s.wheel_profile_path, s.wheel_unit);
  read_profile_file_key(contact, "rail_profile", s.rail_profile_path, s.rail_unit);
  ProfilePairParameters& p = s.placement;
  p.track_gauge_m = contact.number_or("track_gauge_m", "m", p.track_gauge_m);
  p.gauge_measuring_height_m =
      contact.number_or("gauge_measuring_height_m", "m", p.gauge_measuring_height_m);
  p.flange_back_distance_m =
      contact.number_or("flange_back_distance_m", "m", p.flange_back_distance_m);
  p.rail_inclination_rad = contact.number_or("rail_inclination_rad", "rad", p.rail_inclination_rad);
  p.tape_circle_from_flange_back_m =
      contact.number_or("tape_circle_from_flange_back_m", "m", p.tape_circle_from_flange_back_m);
  ContactTableOptions& t = s.table;
  auto in_range = [&](std::string_view key, std::string_view unit, double fallback, double lo,
                      double hi) {
    const double v = contact.number_or(key, unit, fallback);
    if (!(v >= lo && v <= hi))
      contact.fail(key, "a number in [" + format_number(lo) + ", " + format_number(hi) + "] " +
                            std::string(unit),
                   format_number(v));
    return v;
  };
  t.lateral_half_range_m = in_range("table_lateral_half_range_m", "m", t.lateral_half_range_m, 0.002, 0.03);
  t.lateral_step_m = in_range("table_lateral_step_m", "m", t.lateral_step_m, 2e-5, 1e-3);
  t.roll_half_range_rad = in_range("table_roll_half_range_rad", "rad", t.roll_half_range_rad, 0.002, 0.1);
  t.roll_step_rad = in_range("table_roll_step_rad", "rad", t.roll_step_rad, 1e-4, 0.02);
  return s;
}

// Reads the profiles and builds the contact table once, for every model of
// the scene; a profile error is reported under the contact's key.
void load_profile_geometry(const TableReader& contact, ContactSpec& spec) {
  for (std::string_view key : kFlangelessKeys)
    contact.reject_if_present(key, "no " + std::string(key) +
                                       " with geometry = \"profiles\" (the profiles define it)");
  if (spec.normal != NormalForceKind::hertz)
    contact.fail("normal", "\"hertz\" with geometry = \"profiles\" (the normal force follows "
                           "from the penetration at each contact point)",
                 "another normal force model");
  spec.profile_source = read_profile_source(contact);
  try {
    spec.profile_geometry =
        build_profile_contact_geometry(spec.profile_source, spec.nominal_rolling_radius_m);
  } catch (const ProfileError& e) {
    throw scene_error(contact.source(), contact.key_path(), e.what());
  }
}

ContactSpec read_contact(const TableReader& contact, std::string name) {
  ContactSpec spec;
  spec.name = std::move(name);
  spec.geometry = contact.choice("geometry", kContactGeometries);
  spec.normal = contact.choice("normal", kNormalForces);
  spec.tangential = contact.choice("tangential", kTangentialForces);

  const bool linear_conicity = spec.geometry == ContactGeometryKind::linear_conicity;
  const bool prescribed = spec.normal == NormalForceKind::prescribed;
  const bool constant = spec.tangential == TangentialForceKind::constant;
  spec.cone_angle_rad = contact.number_or("cone_angle_rad", "rad", spec.cone_angle_rad);
  spec.conicity = number_required_when(
      contact, linear_conicity, "when geometry = 'linear_conicity'", "conicity", "", spec.conicity);
  spec.prescribed_wheel_load_N =
      number_required_when(contact, prescribed, "when normal = 'prescribed'",
                           "prescribed_wheel_load_N", "N", spec.prescribed_wheel_load_N);
  const std::string_view constant_reason = "when tangential = 'constant'";
  spec.f11_N = number_required_when(contact, constant, constant_reason, "f11_N", "N", spec.f11_N);
  spec.f22_N = number_required_when(contact, constant, constant_reason, "f22_N", "N", spec.f22_N);
  spec.f23_N_m =
      number_required_when(contact, constant, constant_reason, "f23_N_m", "N m", spec.f23_N_m);
  spec.f33_N_m2 =
      number_required_when(contact, constant, constant_reason, "f33_N_m2", "N m2", spec.f33_N_m2);

  spec.half_contact_distance_m =
      contact.number_or("half_contact_distance_m", "m", spec.half_contact_distance_m);
  spec.nominal_rolling_radius_m =
      contact.number_or("nominal_rolling_radius_m", "m", spec.nominal_rolling_radius_m);
  spec.rail_head_transverse_radius_m =
      contact.number_or("rail_head_transverse_radius_m", "m", spec.rail_head_transverse_radius_m);
  spec.wheel_young_modulus_Pa =
      contact.number_or("wheel_young_modulus_Pa", "Pa", spec.wheel_young_modulus_Pa);
  spec.wheel_poisson_ratio = contact.number_or("wheel_poisson_ratio", "", spec.wheel_poisson_ratio);
  spec.rail_young_modulus_Pa =
      contact.number_or("rail_young_modulus_Pa", "Pa", spec.rail_young_modulus_Pa);
  spec.rail_poisson_ratio = contact.number_or("rail_poisson_ratio", "", spec.rail_poisson_ratio);
  spec.spin_creepage = contact.flag_or("spin_creepage", spec.spin_creepage);
  spec.flange_clearance_m = contact.number_or("flange_clearance_m", "m", spec.flange_clearance_m);
  spec.normal_damping_N_s_per_m =
      contact.number_or("normal_damping_N_s_per_m", "N s/m", spec.normal_damping_N_s_per_m);
  spec.creep_law = read_creep_law(contact, spec);
  if (spec.geometry == ContactGeometryKind::profiles) {
    load_profile_geometry(contact, spec);
  } else {
    for (std::string_view key : kProfileKeys)
      contact.reject_if_present(key, "no " + std::string(key) +
                                         " unless geometry = \"profiles\"");
  }
  return spec;
}

std::vector<ContactSpec> read_contacts(const TableReader& top) {
  std::vector<ContactSpec> contacts;
  const toml::table* all_contacts = top.raw_table_or_null("contacts");
  if (!all_contacts) return contacts;
  for (const auto& [name, node] : *all_contacts) {
    const std::string path = child_path("contacts", name.str());
    if (!node.is_table())
      fail_expectation(top.source(), path, "a table [" + path + "] describing a contact model",
                       describe_found(node));
    std::vector<std::string_view> keys = {
        "geometry", "cone_angle_rad", "conicity", "half_contact_distance_m",
        "nominal_rolling_radius_m", "normal", "prescribed_wheel_load_N",
        "rail_head_transverse_radius_m", "wheel_young_modulus_Pa", "wheel_poisson_ratio",
        "rail_young_modulus_Pa", "rail_poisson_ratio", "tangential", "spin_creepage", "f11_N",
        "f22_N", "f23_N_m", "f33_N_m2", "flange_clearance_m",
        "normal_damping_N_s_per_m", "creep_law", "friction_coefficient",
        "kalker_reduction_factor", "polach_limit_friction_ratio",
        "polach_friction_decrease_s_per_m", "polach_adhesion_reduction_factor",
        "polach_slip_reduction_factor"};
    keys.insert(keys.end(), kProfileKeys.begin(), kProfileKeys.end());
    const TableReader contact(*node.as_table(), path, top.source(), std::move(keys));
    contacts.push_back(read_contact(contact, std::string(name.str())));
  }
  return contacts;
}

// --- [[bodies]] ------------------------------------------------------------------
// free = ["y", "yaw"] -> which of the six coordinates move.
std::array<bool, 6> read_free_coordinates(const TableReader& body) {
  Choices<int> coordinates;
  for (int c = 0; c < kCoordinatesPerBody; ++c) coordinates.push_back({kCoordinateKeys[c], c});
  const toml::array& names =
      body.array("free", "an array of coordinate names such as [\"y\", \"yaw\"]");
  std::array<bool, 6> free = {false, false, false, false, false, false};
  for (size_t i = 0; i < names.size(); ++i) {
    const std::string path = indexed_path(body.path_of("free"), i);
    const int c = choice_from(*names.get(i), body.source(), path, coordinates);
    if (free[c])
      fail_expectation(body.source(), path, "each coordinate at most once",
                       quoted(kCoordinateKeys[c]) + " a second time");
    free[c] = true;
  }
  return free;
}

// initial_offset = { y_m = 0.001 } and initial_rate = { yaw_rad_per_s = 0.1 }:
// one optional number per coordinate, in the order x, y, z, roll, pitch, yaw.
struct CoordinateKey {
  std::string_view key;
  std::string_view unit;
};
const std::array<CoordinateKey, 6> kOffsetKeys = {{{"x_m", "m"},
                                                   {"y_m", "m"},
                                                   {"z_m", "m"},
                                                   {"roll_rad", "rad"},
                                                   {"pitch_rad", "rad"},
                                                   {"yaw_rad", "rad"}}};
const std::array<CoordinateKey, 6> kRateKeys = {{{"x_m_per_s", "m/s"},
                                                 {"y_m_per_s", "m/s"},
                                                 {"z_m_per_s", "m/s"},
                                                 {"roll_rad_per_s", "rad/s"},
                                                 {"pitch_rad_per_s", "rad/s"},
                                                 {"yaw_rad_per_s", "rad/s"}}};

std::array<double, 6> read_coordinate_values(const TableReader& body, std::string_view table_key,
                                             const std::array<CoordinateKey, 6>& keys) {
  std::vector<std::string_view> known_keys;
  for (const CoordinateKey& key : keys) known_keys.push_back(key.key);
  const std::optional<TableReader> table = body.optional_table(table_key, known_keys);
  std::array<double, 6> values = {0, 0, 0, 0, 0, 0};
  if (!table) return values;
  for (int c = 0; c < kCoordinatesPerBody; ++c)
    values[c] = table->number_or(keys[c].key, keys[c].unit, 0.0);
  return values;
}

BodySpec read_body(const TableReader& body) {
  BodySpec spec;
  spec.name = body.text("name");
  spec.is_wheelset = body.choice("type", kBodyIsWheelset);
  spec.mass_kg = body.number("mass_kg", "kg");
  spec.inertia_kg_m2 = body.vector3("inertia_kg_m2", "kg m2");
  spec.track_offset_m = body.number_or("track_offset_m", "m", 0.0);
  spec.position_m = body.vector3("position_m", "m");
  if (body.has("free")) spec.free = read_free_coordinates(body);
  if (spec.is_wheelset && !body.has("contact"))
    body.fail_missing("contact",
                      "the name of a [contacts.<name>] table (every wheelset needs one)");
  if (spec.is_wheelset)
    spec.contact = body.text("contact");
  else
    body.reject_if_present("contact",
                           "no contact on a rigid_body (only wheelsets touch the rails)");
  spec.initial_offset = read_coordinate_values(body, "initial_offset", kOffsetKeys);
  spec.initial_rate = read_coordinate_values(body, "initial_rate", kRateKeys);
  return spec;
}

std::vector<BodySpec> read_bodies(const TableReader& top) {
  std::vector<BodySpec> bodies;
  for (const TableReader& body : top.tables_in_array(
           "bodies", {"name", "type", "mass_kg", "inertia_kg_m2", "track_offset_m", "position_m",
                      "free", "contact", "initial_offset", "initial_rate"}))
    bodies.push_back(read_body(body));
  return bodies;
}

// --- [[elements]] ----------------------------------------------------------------
// Keys every element takes; each type adds its own (ElementReader::keys) and
// rejects any other. Adding an element type is one ElementReader below.
const std::vector<std::string_view> kCommonElementKeys = {"name",     "type",     "body1",
                                                          "body2",    "point1_m", "point2_m",
                                                          "mirror_lateral"};

// A number in its physical range (scene/physical_ranges.hpp), optionally
// with a default for a missing key.
double ranged(const TableReader& t, std::string_view key, const PhysicalRange& range,
              std::optional<double> fallback = std::nullopt) {
  const double v = fallback && !t.has(key) ? *fallback : t.number(key, range.unit);
  if (!range.contains(v)) t.fail(key, range_text(range), format_number(v));
  return v;
}
// Three numbers, each in the range; the message names the component.
Eigen::Vector3d ranged_each(const TableReader& t, std::string_view key, const PhysicalRange& range,
                            std::optional<Eigen::Vector3d> fallback = std::nullopt) {
  const Eigen::Vector3d v = fallback && !t.has(key) ? *fallback : t.vector3(key, range.unit);
  for (Eigen::Index i = 0; i < 3; ++i)
    if (!range.contains(v(i)))
      fail_expectation(t.source(), indexed_path(t.path_of(key), size_t(i)), range_text(range),
                       format_number(v(i)));
  return v;
}

// A force characteristic: `linear_key` (a coefficient) or `table_key`
// ([[x, F], ...] with x strictly increasing), exactly one of them.
ForceCharacteristic<double> characteristic(const TableReader& t, std::string_view linear_key,
                                           const PhysicalRange& linear_range,
                                           std::string_view table_key, const PhysicalRange& x_range,
                                           bool required = true) {
  const std::string_view linear_unit = linear_range.unit, x_unit = x_range.unit;
  const bool has_linear = t.has(linear_key), has_table = t.has(table_key);
  if (has_linear && has_table)
    t.fail(table_key, "either " + std::string(linear_key) + " or " + std::string(table_key),
           "both");
  if (has_linear) return ForceCharacteristic<double>::linear(ranged(t, linear_key, linear_range));
  if (!has_table) {
    if (required)
      t.fail_missing(linear_key, "a number" + unit_suffix(linear_unit) + " (or " +
                                     std::string(table_key) + ")");
    return ForceCharacteristic<double>::linear(0.0);
  }
  const std::string expected = "an array of at least 2 [x, F] pairs (x in " +
                               std::string(x_unit) + ", F in N) with x strictly increasing";
  const toml::array& rows = t.array(table_key, expected);
  std::vector<double> xs, fs;
  for (size_t i = 0; i < rows.size(); ++i) {
    const toml::array* row = rows.get(i)->as_array();
    const std::string row_path = indexed_path(t.path_of(table_key), i);
    if (!row || row->size() != 2)
      fail_expectation(t.source(), row_path, "a pair [x, F]", describe_found(*rows.get(i)));
    xs.push_back(number_from(*row->get(0), t.source(), indexed_path(row_path, 0), x_unit));
    fs.push_back(number_from(*row->get(1), t.source(), indexed_path(row_path, 1), "N"));
    if (!x_range.contains(xs.back()))
      fail_expectation(t.source(), indexed_path(row_path, 0), range_text(x_range),
                       format_number(xs.back()));
    if (!physical_ranges::table_force_N.contains(fs.back()))
      fail_expectation(t.source(), indexed_path(row_path, 1),
                       range_text(physical_ranges::table_force_N), format_number(fs.back()));
    if (i > 0 && !(xs[i] > xs[i - 1]))
      fail_expectation(t.source(), indexed_path(row_path, 0),
                       "x greater than the previous row's " + format_number(xs[i - 1]),
                       format_number(xs[i]));
  }
  if (xs.size() < 2) t.fail(table_key, expected, std::to_string(xs.size()) + " rows");
  return ForceCharacteristic<double>::table(xs, fs);
}

template <class Element> ElementSpec with_ends(Element e, const ElementEnds& ends) {
  e.ends = ends;
  return e;
}

struct ElementReader {
  std::string_view type;
  std::vector<std::string_view> keys;  // besides kCommonElementKeys
  bool points_required;
  std::function<ElementSpec(const TableReader&, const ElementEnds&)> read;
};

const std::vector<ElementReader>& element_readers() {
  static const std::vector<ElementReader> readers = {
      {SpringDamper3d<double>::kType,
       {"stiffness_N_per_m", "damping_N_s_per_m", "actuator_force_N"},
       true,
       [](const TableReader& t, const ElementEnds& ends) -> ElementSpec {
         SpringDamper3d<double> e;
         e.stiffness_N_per_m = ranged_each(t, "stiffness_N_per_m", physical_ranges::stiffness_N_per_m);
         e.damping_N_s_per_m = ranged_each(t, "damping_N_s_per_m", physical_ranges::damping_N_s_per_m);
         e.actuator_force_N = ranged_each(t, "actuator_force_N", physical_ranges::actuator_force_N,
                                          Eigen::Vector3d::Zero());
         return with_ends(e, ends);
       }},
      {RotationalSpringDamper<double>::kType,
       {"stiffness_N_m_per_rad", "damping_N_m_s_per_rad", "actuator_moment_N_m"},
       false,
       [](const TableReader& t, const ElementEnds& ends) -> ElementSpec {
         RotationalSpringDamper<double> e;
         e.stiffness_N_m_per_rad =
             ranged_each(t, "stiffness_N_m_per_rad", physical_ranges::stiffness_N_m_per_rad);
         e.damping_N_m_s_per_rad =
             ranged_each(t, "damping_N_m_s_per_rad", physical_ranges::damping_N_m_s_per_rad);
         e.actuator_moment_N_m = ranged_each(t, "actuator_moment_N_m",
                                             physical_ranges::actuator_moment_N_m,
                                             Eigen::Vector3d::Zero());
         return with_ends(e, ends);
       }},
      {SeriesSpringDamper<double>::kType,
       {"series_stiffness_N_per_m", "damping_N_s_per_m", "damper_force_velocity_table"},
       true,
       [](const TableReader& t, const ElementEnds& ends) -> ElementSpec {
         SeriesSpringDamper<double> e;
         e.series_stiffness_N_per_m =
             ranged(t, "series_stiffness_N_per_m", physical_ranges::positive_stiffness_N_per_m);
         const ForceCharacteristic<double> damper =
             characteristic(t, "damping_N_s_per_m", physical_ranges::damping_N_s_per_m,
                            "damper_force_velocity_table", physical_ranges::table_velocity_m_per_s);
         if (!damper.strictly_increasing())
           t.fail(damper.is_table ? "damper_force_velocity_table" : "damping_N_s_per_m",
                  "a damper whose force strictly increases with velocity (the series element "
                  "needs its velocity as a function of force)",
                  damper.is_table ? "a table with a flat or falling step" : "zero damping");
         e.set_damper(damper);
         return with_ends(e, ends);
       }},
      {LineSpringDamper<double>::kType,
       {"stiffness_N_per_m", "spring_force_deflection_table", "damping_N_s_per_m",
        "damper_force_velocity_table"},
       true,
       [](const TableReader& t, const ElementEnds& ends) -> ElementSpec {
         LineSpringDamper<double> e;
         e.spring = characteristic(t, "stiffness_N_per_m", physical_ranges::stiffness_N_per_m,
                                   "spring_force_deflection_table",
                                   physical_ranges::table_deflection_m, false);
         e.damper = characteristic(t, "damping_N_s_per_m", physical_ranges::damping_N_s_per_m,
                                   "damper_force_velocity_table",
                                   physical_ranges::table_velocity_m_per_s, false);
         return with_ends(e, ends);
       }},
      {BumpStop<double>::kType,
       {"axis", "clearance_m", "stiffness_N_per_m", "progressive_stiffness_N_per_m3",
        "contact_smoothing_m"},
       true,
       [](const TableReader& t, const ElementEnds& ends) -> ElementSpec {
         BumpStop<double> e;
         const Eigen::Vector3d axis = t.vector3("axis", "");
         if (!(axis.norm() > 0.0) || !axis.allFinite())
           t.fail("axis", "a non-zero direction in body 1's frame", format_vector(axis));
         e.axis = axis.normalized();
         e.clearance_m = ranged(t, "clearance_m", physical_ranges::clearance_m);
         e.stiffness_N_per_m =
             ranged(t, "stiffness_N_per_m", physical_ranges::positive_stiffness_N_per_m);
         e.progressive_stiffness_N_per_m3 = ranged(
             t, "progressive_stiffness_N_per_m3", physical_ranges::progressive_stiffness_N_per_m3, 0.0);
         e.contact_smoothing_m =
             ranged(t, "contact_smoothing_m", physical_ranges::smoothing_length_m, 5e-4);
         return with_ends(e, ends);
       }},
      {TractionRod<double>::kType,
       {"stiffness_N_per_m", "damping_N_s_per_m"},
       true,
       [](const TableReader& t, const ElementEnds& ends) -> ElementSpec {
         TractionRod<double> e;
         e.stiffness_N_per_m =
             ranged(t, "stiffness_N_per_m", physical_ranges::positive_stiffness_N_per_m);
         e.damping_N_s_per_m =
             ranged(t, "damping_N_s_per_m", physical_ranges::damping_N_s_per_m, 0.0);
         return with_ends(e, ends);
       }},
      {AntiRollBar<double>::kType,
       {"roll_stiffness_N_m_per_rad", "link_half_spacing_m"},
       true,
       [](const TableReader& t, const ElementEnds& ends) -> ElementSpec {
         AntiRollBar<double> e;
         e.roll_stiffness_N_m_per_rad = ranged(t, "roll_stiffness_N_m_per_rad",
                                               physical_ranges::positive_stiffness_N_m_per_rad);
         e.link_half_spacing_m =
             ranged(t, "link_half_spacing_m", physical_ranges::link_half_spacing_m);
         return with_ends(e, ends);
       }},
  };
  return readers;
}

// mirror_lateral = true: "<name>_left" as given, "<name>_right" with the y of
// both points (and of a bump stop's axis) negated.
std::array<ElementSpec, 2> mirrored_pair(const ElementSpec& element) {
  ElementSpec left = element;
  ElementSpec right = element;
  ends_of(left).name += "_left";
  ElementEnds& r = ends_of(right);
  r.name += "_right";
  r.point1_m.y() = -r.point1_m.y();
  r.point2_m.y() = -r.point2_m.y();
  if (auto* stop = std::get_if<BumpStop<double>>(&right)) stop->axis.y() = -stop->axis.y();
  return {left, right};
}

// Elements as built, and for each the key path of the [[elements]] table it
// came from (a mirrored table gives two elements with the same path).
struct ElementList {
  std::vector<ElementSpec> specs;
  std::vector<std::string> file_paths;
};

// The element tables of the array `key` of `owner` ([[elements]], and
// [[train.couplers]] which are elements too).
ElementList read_element_tables(const TableReader& owner, std::string_view key) {
  std::vector<std::string_view> all_keys = kCommonElementKeys;
  Choices<size_t> types;
  for (size_t i = 0; i < element_readers().size(); ++i) {
    const ElementReader& r = element_readers()[i];
    types.emplace_back(r.type, i);
    all_keys.insert(all_keys.end(), r.keys.begin(), r.keys.end());
  }
  ElementList list;
  for (const TableReader& any : owner.tables_in_array_or_none(key, all_keys)) {
    const ElementReader& reader = element_readers()[any.choice("type", types)];
    std::vector<std::string_view> keys = kCommonElementKeys;
    keys.insert(keys.end(), reader.keys.begin(), reader.keys.end());
    // A key of another element type: say which keys this type takes.
    for (const std::string_view key : all_keys)
      if (std::find(keys.begin(), keys.end(), key) == keys.end()) {
        std::string takes;
        for (const std::string_view own : reader.keys)
          takes += (takes.empty() ? "" : ", ") + std::string(own);
        any.reject_if_present(key, "no " + std::string(key) + " on a " + std::string(reader.type) +
                                       " (it takes " + takes + ")");
      }
    const TableReader element = any.with_keys(keys, "a " + std::string(reader.type));
    ElementEnds ends;
    ends.name = element.text("name");
    // Checked here, before mirroring appends "_left" / "_right".
    if (const std::optional<std::string> problem = name_problem(ends.name))
      element.fail("name", kNameExpectation, *problem);
    ends.body1_name = element.text("body1");
    ends.body2_name = element.text("body2");
    const std::optional<Eigen::Vector3d> no_point =
        reader.points_required ? std::nullopt : std::optional(Eigen::Vector3d::Zero().eval());
    ends.point1_m = ranged_each(element, "point1_m", physical_ranges::coordinate_m, no_point);
    ends.point2_m = ranged_each(element, "point2_m", physical_ranges::coordinate_m, no_point);
    const ElementSpec spec = reader.read(element, ends);
    if (element.flag_or("mirror_lateral", false)) {
      for (const ElementSpec& half : mirrored_pair(spec)) {
        list.specs.push_back(half);
        list.file_paths.push_back(element.key_path());
      }
    } else {
      list.specs.push_back(spec);
      list.file_paths.push_back(element.key_path());
    }
  }
  return list;
}

ElementList read_elements(const TableReader& top) { return read_element_tables(top, "elements"); }

// --- [train] ---------------------------------------------------------------------
// cars, car_spacing_m, [[train.couplers]] (scene/train.hpp). The train is
// expanded here, before the semantic checks, so that every later stage sees
// an ordinary scene; what only the file knows (coupler bodies are the
// vehicle's, cars a whole number) is checked against the file's keys first.
constexpr int kMaxTrainCars = 64;

struct TrainExpansion {
  SceneSpec scene;
  std::vector<std::string> element_paths;
};

TrainExpansion expand_train(const TableReader& train, SceneSpec vehicle,
                            std::vector<std::string> vehicle_element_paths) {
  TrainSpec spec;
  const double cars = train.number("cars", "");
  if (!(cars >= 1 && cars <= kMaxTrainCars && cars == std::floor(cars)))
    train.fail("cars", "a whole number of cars from 1 to " + std::to_string(kMaxTrainCars),
               format_number(cars));
  spec.cars = int(cars);
  spec.car_spacing_m = train.number("car_spacing_m", "m");
  if (!(spec.car_spacing_m > 0.0 && spec.car_spacing_m <= 1000.0))
    train.fail("car_spacing_m",
               "the distance along the track between the same point of two consecutive cars, "
               "in (0, 1000] m",
               format_number(spec.car_spacing_m));
  ElementList couplers = read_element_tables(train, "couplers");
  std::vector<std::string> names;
  for (const BodySpec& body : vehicle.bodies) names.push_back(body.name);
  for (size_t i = 0; i < couplers.specs.size(); ++i) {
    const ElementEnds& e = ends_of(couplers.specs[i]);
    for (const auto& [key, body] : {std::pair<const char*, const std::string*>{"body1", &e.body1_name},
                                    {"body2", &e.body2_name}})
      if (std::find(names.begin(), names.end(), *body) == names.end())
        throw scene_error(train.source(), child_path(couplers.file_paths[i], key),
                          "unknown body " + quoted(*body) + " (a coupler joins bodies of the " +
                              "vehicle: " + comma_separated(names) + ")");
  }
  spec.couplers = std::move(couplers.specs);
  TrainExpansion out{make_train(vehicle, spec), {}};
  for (int car = 1; car <= spec.cars; ++car)
    out.element_paths.insert(out.element_paths.end(), vehicle_element_paths.begin(),
                             vehicle_element_paths.end());
  for (int car = 1; car < spec.cars; ++car)
    out.element_paths.insert(out.element_paths.end(), couplers.file_paths.begin(),
                             couplers.file_paths.end());
  return out;
}

// --- [simulation] ------------------------------------------------------------------
const Choices<IntegratorKind>& integrator_choices() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (IntegratorKind k : all_integrator_kinds()) n.push_back(integrator_name(k));
    return n;
  }();
  static const Choices<IntegratorKind> choices = [] {
    Choices<IntegratorKind> c;
    for (size_t i = 0; i < names.size(); ++i) c.emplace_back(names[i], all_integrator_kinds()[i]);
    return c;
  }();
  return choices;
}

SimulationSpec read_simulation(const std::optional<TableReader>& simulation) {
  SimulationSpec spec;
  if (!simulation) return spec;
  spec.t_end_s = simulation->number_or("t_end_s", "s", spec.t_end_s);
  spec.output_interval_s = simulation->number_or("output_interval_s", "s", spec.output_interval_s);
  spec.integrator = simulation->choice_or("integrator", integrator_choices(), spec.integrator);
  const double order = simulation->number_or("integrator_order", "", spec.integrator_order);
  if (!(order == std::floor(order) && order >= 0.0 && order <= 12.0) ||
      !order_available(spec.integrator, int(order)))
    simulation->fail("integrator_order",
                     "0 (the method's default) or an order " + integrator_name(spec.integrator) +
                         " offers: " + available_orders_text(spec.integrator),
                     format_number(order));
  spec.integrator_order = int(order);
  spec.relative_tolerance =
      simulation->number_or("relative_tolerance", "", spec.relative_tolerance);
  spec.absolute_tolerance =
      simulation->number_or("absolute_tolerance", "", spec.absolute_tolerance);
  return spec;
}

toml::table parse_toml(const std::string& text, const std::string& source) {
  try {
    return toml::parse(std::string_view(text), std::string_view(source));
  } catch (const toml::parse_error& error) {
    const toml::source_position& where = error.source().begin;
    throw SceneError(source + ": line " + std::to_string(where.line) + ", column " +
                     std::to_string(where.column) + ": expected valid TOML, got a syntax error: " +
                     std::string(error.description()));
  }
}

// ============================================================================
// 5. Semantic checks
// ============================================================================


std::string contact_path(const ContactSpec& contact) {
  return child_path("contacts", contact.name);
}
std::string body_path(size_t index) { return indexed_path("bodies", index); }

// validate_scene, one check per function. Element messages use the key path
// of the [[elements]] table the element came from (mirroring makes two).
class SceneChecker {
 public:
  SceneChecker(const SceneSpec& scene, std::vector<std::string> element_paths)
      : scene_(scene),
        source_(scene.source_path.empty() ? "<scene>" : scene.source_path),
        element_paths_(std::move(element_paths)) {}

  void check_all() const {
    check_scene_numbers();
    check_simulation();
    check_track();
    check_contact_names();
    for (const ContactSpec& contact : scene_.contacts) check_contact(contact);
    check_body_names();
    for (size_t i = 0; i < scene_.bodies.size(); ++i) check_body(i);
    for (size_t i = 0; i < scene_.elements.size(); ++i) check_element(i);
    check_speed_for_creep_forces();
    check_bodies_on_track();
  }

 private:
  [[noreturn]] void fail(std::string_view path, std::string_view expected,
                         std::string_view found) const {
    fail_expectation(source_, path, expected, found);
  }
  // Every number in its physical range (scene/physical_ranges.hpp).
  void require_in(std::string_view path, double value, const PhysicalRange& range) const {
    if (!range.contains(value)) fail(path, range_text(range), format_number(value));
  }
  void require_each_in(std::string_view path, const Eigen::Vector3d& values,
                       const PhysicalRange& range) const {
    for (Eigen::Index i = 0; i < 3; ++i)
      require_in(indexed_path(path, size_t(i)), values(i), range);
  }
  void check_name(std::string_view path, const std::string& name) const {
    if (const std::optional<std::string> problem = name_problem(name))
      fail(path, kNameExpectation, *problem);
  }

  void check_scene_numbers() const {
    namespace r = physical_ranges;
    check_name("scene.name", scene_.name);
    require_in("scene.gravity_m_per_s2", scene_.gravity_m_per_s2, r::gravity_m_per_s2);
    require_in("scene.reference_arc_length_m", scene_.reference_arc_length_m, r::arc_length_m);
  }

  void check_simulation() const {
    namespace r = physical_ranges;
    const SimulationSpec& simulation = scene_.simulation;
    require_in("simulation.t_end_s", simulation.t_end_s, r::t_end_s);
    require_in("simulation.output_interval_s", simulation.output_interval_s, r::output_interval_s);
    require_in("simulation.relative_tolerance", simulation.relative_tolerance,
               r::relative_tolerance);
    require_in("simulation.absolute_tolerance", simulation.absolute_tolerance,
               r::absolute_tolerance);
    // The integrator would refuse the run later (integrate/integrator.hpp);
    // say it here, with the keys, before any model is built.
    const double outputs = std::ceil(simulation.t_end_s / simulation.output_interval_s - 1e-9);
    if (!(outputs <= r::kMaxOutputs))
      fail("simulation.output_interval_s",
           "at most " + format_number(r::kMaxOutputs) +
               " stored outputs (t_end_s / output_interval_s; lengthen output_interval_s or "
               "shorten t_end_s)",
           "t_end_s = " + format_number(simulation.t_end_s) + " s / output_interval_s = " +
               format_number(simulation.output_interval_s) + " s = " + format_number(outputs) +
               " outputs");
  }

  void check_cant(std::string_view path, double cant_m) const {
    const double distance = scene_.track.rail_contact_distance_m;
    if (!(std::abs(cant_m) < distance))
      fail(path, "|cant| < rail_contact_distance_m = " + format_number(distance) + " m",
           format_number(cant_m));
  }

  void check_track() const {
    namespace r = physical_ranges;
    const TrackSpec& track = scene_.track;
    require_in("track.rail_contact_distance_m", track.rail_contact_distance_m,
               r::rail_contact_distance_m);
    require_in("track.start_x_m", track.start_x_m, r::track_position_m);
    require_in("track.start_y_m", track.start_y_m, r::track_position_m);
    require_in("track.start_z_m", track.start_z_m, r::track_position_m);
    require_in("track.start_heading_rad", track.start_heading_rad, r::heading_rad);
    require_in("track.start_curvature_per_m", track.start_curvature_per_m, r::curvature_per_m);
    check_cant("track.start_cant_m", track.start_cant_m);
    if (track.segments.empty())
      fail("track.segments", "at least one segment [[track.segments]]", "none");
    for (size_t i = 0; i < track.segments.size(); ++i) {
      const std::string path = indexed_path("track.segments", i);
      require_in(child_path(path, "length_m"), track.segments[i].length_m, r::segment_length_m);
      check_cant(child_path(path, "end_cant_m"), track.segments[i].end_cant_m);
      require_in(child_path(path, "end_curvature_per_m"), track.segments[i].end_curvature_per_m,
                 r::curvature_per_m);
    }
  }

  void check_contact_names() const {
    for (size_t i = 0; i < scene_.contacts.size(); ++i) {
      const std::string& name = scene_.contacts[i].name;
      if (name.empty()) fail(indexed_path("contacts", i), "a named contact", "an empty name");
      if (const std::optional<std::string> problem = name_problem(name))
        fail(indexed_path("contacts", i), "a contact name of 1 to " +
             std::to_string(physical_ranges::kMaxNameBytes) + " bytes without control characters",
             *problem);
      for (size_t j = 0; j < i; ++j)
        if (scene_.contacts[j].name == name)
          fail(contact_path(scene_.contacts[i]), "a unique contact name", quoted(name) + " twice");
    }
  }

  void check_contact(const ContactSpec& contact) const {
    const std::string path = contact_path(contact);
    auto at = [&](std::string_view key) { return child_path(path, key); };
    if (contact.geometry == ContactGeometryKind::knife_edge_cone &&
        !(contact.cone_angle_rad > 0 && contact.cone_angle_rad < 0.5))
      fail(at("cone_angle_rad"), "a cone angle in (0, 0.5) rad",
           format_number(contact.cone_angle_rad));
    namespace r = physical_ranges;
    if (contact.geometry == ContactGeometryKind::linear_conicity)
      require_in(at("conicity"), contact.conicity, r::conicity);
    if (contact.geometry != ContactGeometryKind::profiles) {
      require_in(at("half_contact_distance_m"), contact.half_contact_distance_m,
                 r::half_contact_distance_m);
      check_contact_distances(at("half_contact_distance_m"), contact.half_contact_distance_m);
    }
    require_in(at("nominal_rolling_radius_m"), contact.nominal_rolling_radius_m,
               r::rolling_radius_m);
    require_in(at("flange_clearance_m"), contact.flange_clearance_m, r::flange_clearance_m);
    require_in(at("normal_damping_N_s_per_m"), contact.normal_damping_N_s_per_m,
               r::damping_N_s_per_m);
    require_in(at("rail_head_transverse_radius_m"), contact.rail_head_transverse_radius_m,
               r::rail_head_radius_m);
    require_in(at("wheel_young_modulus_Pa"), contact.wheel_young_modulus_Pa, r::young_modulus_Pa);
    require_in(at("rail_young_modulus_Pa"), contact.rail_young_modulus_Pa, r::young_modulus_Pa);
    check_poisson_ratio(at("wheel_poisson_ratio"), contact.wheel_poisson_ratio);
    check_poisson_ratio(at("rail_poisson_ratio"), contact.rail_poisson_ratio);
    if (contact.normal == NormalForceKind::prescribed)
      require_in(at("prescribed_wheel_load_N"), contact.prescribed_wheel_load_N, r::wheel_load_N);
    if (contact.normal == NormalForceKind::prescribed && contact.normal_damping_N_s_per_m != 0.0)
      fail(at("normal_damping_N_s_per_m"), "0 with normal = 'prescribed' (the damper acts on "
           "the Hertz penetration rate; a prescribed load has none)",
           format_number(contact.normal_damping_N_s_per_m));
    if (contact.tangential == TangentialForceKind::constant) {
      require_in(at("f11_N"), contact.f11_N, r::creep_coefficient_N);
      require_in(at("f22_N"), contact.f22_N, r::creep_coefficient_N);
      require_in(at("f33_N_m2"), contact.f33_N_m2, r::creep_coefficient_N_m2);
      require_in(at("f23_N_m"), contact.f23_N_m, r::creep_coefficient_N_m);
    }
  }

  // e0 (the contact's half distance between the wheel contact points) and D
  // (the track's distance between the rail contact points, which sets the
  // cant angle asin(cant / D)) describe the same points: they must agree.
  // 5 % admits rounding (1435 mm gauge: 2 e0 = 1.5 m, D = 1.5 m or 1.505 m).
  void check_contact_distances(std::string_view path, double e0) const {
    const double D = scene_.track.rail_contact_distance_m;
    if (!(std::abs(2.0 * e0 - D) <= 0.05 * D))
      fail(path,
           "half of track.rail_contact_distance_m = " + format_number(D) +
               " m within 5 % (both are the distance between the contact points; the cant "
               "angle uses D, the contact geometry 2 e0)",
           format_number(e0) + " m (2 e0 = " + format_number(2.0 * e0) + " m)");
  }

  void check_poisson_ratio(std::string_view path, double ratio) const {
    if (!(ratio >= 0 && ratio < 0.5))
      fail(path, "a Poisson ratio in [0, 0.5)", format_number(ratio));
  }

  void check_body_names() const {
    for (size_t i = 0; i < scene_.bodies.size(); ++i) {
      const std::string path = child_path(body_path(i), "name");
      const std::string& name = scene_.bodies[i].name;
      if (name.empty()) fail(path, "a non-empty name", "''");
      check_name(path, name);
      if (name == kTrackBodyName)
        fail(path, "a name other than 'track' (reserved: elements use it for the track frame)",
             quoted(name));
      for (size_t j = 0; j < i; ++j)
        if (scene_.bodies[j].name == name)
          fail(path, "a unique body name", quoted(name) + ", already the name of " + body_path(j));
    }
    if (scene_.bodies.empty()) fail("bodies", "at least one body [[bodies]]", "none");
  }

  void check_body(size_t index) const {
    const BodySpec& body = scene_.bodies[index];
    const std::string path = body_path(index);
    namespace r = physical_ranges;
    require_in(child_path(path, "mass_kg"), body.mass_kg, r::mass_kg);
    require_each_in(child_path(path, "inertia_kg_m2"), body.inertia_kg_m2, r::inertia_kg_m2);
    check_inertia(child_path(path, "inertia_kg_m2"), body);
    require_each_in(child_path(path, "position_m"), body.position_m, r::coordinate_m);
    require_in(child_path(path, "track_offset_m"), body.track_offset_m, r::track_offset_m);
    for (int c = 0; c < kCoordinatesPerBody; ++c) {
      const bool angle = c >= 3;
      require_in(child_path(child_path(path, "initial_offset"), kOffsetKeys[c].key),
                 body.initial_offset[c], angle ? r::offset_rad : r::offset_m);
      require_in(child_path(child_path(path, "initial_rate"), kRateKeys[c].key),
                 body.initial_rate[c], angle ? r::rate_rad_per_s : r::rate_m_per_s);
    }
    if (body.is_wheelset) {
      check_wheelset_contact(child_path(path, "contact"), body);
      check_wheelset_position(child_path(path, "position_m"), body);
    }
    else if (!body.contact.empty())
      fail(child_path(path, "contact"),
           "no contact on a rigid_body (only wheelsets touch the rails)", quoted(body.contact));
  }

  void check_inertia(std::string_view path, const BodySpec& body) const {
    const Eigen::Vector3d& J = body.inertia_kg_m2;
    if (!(J.array() > 0).all())
      fail(path, "positive principal moments Jx, Jy, Jz (kg m2)", format_vector(J));
    if (body.is_wheelset && std::abs(J.x() - J.z()) > 1e-9 * std::max(J.x(), J.z()))
      fail(path, "Jx = Jz (a wheelset must be axisymmetric; the model drops its spin angle)",
           "Jx = " + format_number(J.x()) + ", Jz = " + format_number(J.z()));
    const char* names[3] = {"Jx", "Jy", "Jz"};
    for (int k = 0; k < 3; ++k) {
      const int i = (k + 1) % 3, j = (k + 2) % 3;
      if (J(i) + J(j) < J(k) * (1.0 - 1e-12))
        fail(path, "principal moments with Ji + Jj >= Jk for every pair",
             format_vector(J) + ", which is not a physical (positive-definite) inertia (" +
                 names[i] + " + " + names[j] + " = " + format_number(J(i) + J(j)) + " < " +
                 names[k] + " = " + format_number(J(k)) + ")");
    }
  }

  // A wheelset's nominal position is on the rails: its centre within the
  // flange clearance of the track centre and at its rolling radius above
  // the rail plane (10 %). A wheelset placed at y = -1 m failed deep in the
  // model ("relative curvatures must be positive") or found no equilibrium.
  void check_wheelset_position(const std::string& path, const BodySpec& wheelset) const {
    const ContactSpec* contact = find_contact(wheelset.contact);
    if (!contact) return;
    const double y = wheelset.position_m.y(), z = wheelset.position_m.z();
    const double clearance = contact->flange_clearance_m, r0 = contact->nominal_rolling_radius_m;
    if (!(std::abs(y) <= clearance))
      fail(indexed_path(path, 1),
           "a wheelset's nominal lateral position within the flange clearance of the track "
           "centre, [-" + format_number(clearance) + ", " + format_number(clearance) +
               "] m (contacts." + contact->name + ".flange_clearance_m)",
           format_number(y));
    if (!(std::abs(z - r0) <= 0.1 * r0))
      fail(indexed_path(path, 2),
           "a wheelset's axle height at its rolling radius above the rail plane, " +
               format_number(r0) + " m within 10 % (contacts." + contact->name +
               ".nominal_rolling_radius_m)",
           format_number(z));
  }

  void check_wheelset_contact(std::string_view path, const BodySpec& wheelset) const {
    if (wheelset.contact.empty())
      fail(path, "the name of a [contacts.<name>] table for a wheelset", "nothing");
    if (!find_contact(wheelset.contact)) {
      std::vector<std::string> names;
      for (const ContactSpec& contact : scene_.contacts) names.push_back(contact.name);
      throw scene_error(source_, path,
                        "unknown contact " + quoted(wheelset.contact) +
                            " (contacts: " + comma_separated(names) + ")");
    }
  }

  void check_element(size_t index) const {
    const ElementEnds& element = ends_of(scene_.elements[index]);
    const std::string path =
        index < element_paths_.size() ? element_paths_[index] : indexed_path("elements", index);
    if (element.name.empty()) fail(child_path(path, "name"), "a non-empty name", "''");
    // (+ 6: a mirrored element's "_right"; the file's name was checked by the reader.)
    if (const std::optional<std::string> problem =
            name_problem(element.name, physical_ranges::kMaxNameBytes + 6))
      fail(child_path(path, "name"), kNameExpectation, *problem);
    if (element.body1_name != kTrackBodyName && !has_body(element.body1_name))
      throw unknown_body(child_path(path, "body1"), element.body1_name, "; or 'track'");
    if (element.body2_name == kTrackBodyName)
      fail(child_path(path, "body2"), "a body (only body1 may be 'track')",
           quoted(element.body2_name));
    if (!has_body(element.body2_name))
      throw unknown_body(child_path(path, "body2"), element.body2_name, "");
    if (element.body1_name == element.body2_name)
      fail(child_path(path, "body2"), "a body other than body1",
           quoted(element.body2_name) + " for both");
  }

  SceneError unknown_body(std::string_view path, const std::string& name,
                          std::string_view alternatives) const {
    std::vector<std::string> names;
    for (const BodySpec& body : scene_.bodies) names.push_back(body.name);
    return scene_error(source_, path,
                       "unknown body " + quoted(name) + " (bodies: " + comma_separated(names) +
                           std::string(alternatives) + ")");
  }

  // Creepages are divided by the speed: creep forces need V > 0.
  void check_speed_for_creep_forces() const {
    const char* path = "scene.speed_m_per_s";
    for (const BodySpec& body : scene_.bodies) {
      const ContactSpec* contact = body.is_wheelset ? find_contact(body.contact) : nullptr;
      if (contact && contact->tangential != TangentialForceKind::none &&
          !(scene_.speed_m_per_s > 0))
        fail(path, "> 0 when creep forces are on (creepages are divided by the speed)",
             format_number(scene_.speed_m_per_s));
    }
    require_in(path, scene_.speed_m_per_s, physical_ranges::speed_m_per_s);
  }

  // Each body's own track frame starts at reference + offset: it must be on the track.
  void check_bodies_on_track() const {
    double track_length_m = 0.0;
    for (const TrackSegmentSpec& segment : scene_.track.segments)
      track_length_m += segment.length_m;
    for (size_t i = 0; i < scene_.bodies.size(); ++i) {
      const double offset = scene_.bodies[i].track_offset_m;
      const double arc_length = scene_.reference_arc_length_m + offset;
      if (!(arc_length >= 0 && arc_length <= track_length_m))
        fail(child_path(body_path(i), "track_offset_m"),
             "the body's track position at t = 0 (reference_arc_length_m + track_offset_m) "
             "inside the track [0, " +
                 format_number(track_length_m) + "] m",
             format_number(scene_.reference_arc_length_m) + (offset < 0 ? " - " : " + ") +
                 format_number(std::abs(offset)) + " = " + format_number(arc_length) + " m");
    }
  }

  const ContactSpec* find_contact(const std::string& name) const {
    for (const ContactSpec& contact : scene_.contacts)
      if (contact.name == name) return &contact;
    return nullptr;
  }

  bool has_body(const std::string& name) const {
    return std::any_of(scene_.bodies.begin(), scene_.bodies.end(),
                       [&](const BodySpec& body) { return body.name == name; });
  }

  const SceneSpec& scene_;
  std::string source_;
  std::vector<std::string> element_paths_;
};

}  // namespace

// ============================================================================
// 6. Public API
// ============================================================================

namespace {
// The sections of a scene file (parse_scene reads them all,
// load_scene_contacts only [contacts]).
const std::vector<std::string_view> kSceneSections = {"scene",    "track",      "contacts", "bodies",
                                                      "elements", "simulation", "train"};
}  // namespace

std::string read_scene_text(const std::string& path) {
  // A named pipe, a folder or a device is refused before anything is read
  // (io/regular_file.hpp): a FIFO used to hang here.
  try {
    return read_regular_file(path);
  } catch (const std::runtime_error& e) {
    throw SceneError(path + ": scene file: " + e.what());
  }
}

SceneSpec parse_scene(const std::string& toml_text, const std::string& source_name) {
  const toml::table root = parse_toml(toml_text, source_name);
  const TableReader top(root, "", source_name, kSceneSections);
  SceneSpec scene;
  scene.source_path = source_name;
  read_scene_section(top.table("scene", {"name", "speed_m_per_s", "gravity_m_per_s2",
                                         "reference_arc_length_m", "preload"}),
                     scene);
  scene.track = read_track(top.table(
      "track", {"start_x_m", "start_y_m", "start_z_m", "start_heading_rad", "start_curvature_per_m",
                "start_cant_m", "rail_contact_distance_m", "segments"}));
  scene.contacts = read_contacts(top);
  scene.bodies = read_bodies(top);
  ElementList elements = read_elements(top);
  scene.elements = std::move(elements.specs);
  scene.simulation = read_simulation(top.optional_table(
      "simulation", {"t_end_s", "output_interval_s", "integrator", "integrator_order",
                     "relative_tolerance", "absolute_tolerance"}));
  if (const std::optional<TableReader> train =
          top.optional_table("train", {"cars", "car_spacing_m", "couplers"})) {
    TrainExpansion expanded = expand_train(*train, std::move(scene), std::move(elements.file_paths));
    scene = std::move(expanded.scene);
    elements.file_paths = std::move(expanded.element_paths);
  }
  SceneChecker(scene, std::move(elements.file_paths)).check_all();
  return scene;
}

SceneSpec load_scene_file(const std::string& path) {
  return parse_scene(read_scene_text(path), path);
}

std::vector<ContactSpec> load_scene_contacts(const std::string& path,
                                             const std::vector<SceneValueSetting>& settings) {
  std::string text = read_scene_text(path);
  if (!settings.empty()) text = scene_text_with_values(text, path, settings);
  const toml::table root = parse_toml(text, path);
  const TableReader top(root, "", path, kSceneSections);
  return read_contacts(top);
}

// Without the file at hand, elements are named by name: after mirroring, an
// element's index no longer matches its [[elements]] table in the file.
void validate_scene(const SceneSpec& scene) {
  std::vector<std::string> element_paths;
  for (size_t i = 0; i < scene.elements.size(); ++i)
    element_paths.push_back(ends_of(scene.elements[i]).name.empty()
                                ? indexed_path("elements", i)
                                : "elements[" + quoted(ends_of(scene.elements[i]).name) + "]");
  SceneChecker(scene, std::move(element_paths)).check_all();
}

}  // namespace railstab
