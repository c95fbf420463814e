#pragma once
#include <cmath>
// Reading one TOML table of a scene file, key by key, with the diagnostics
// of scene reading: each message names the file, the key path and what was
// expected ("cases/x.toml: bodies[2].mass_kg: expected a number (kg), got a
// string 'heavy'"). A table declares the keys it may hold, so a misspelt key
// is reported as such (with the key the user most likely meant) instead of
// as a missing one. Internal to scene_reading/; the section readers use it.
#include <railstab/core/name_table.hpp>
#include <railstab/scene_reading/scene_messages.hpp>

#include <toml++/toml.h>

#include <Eigen/Dense>

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace railstab::scene_reading {

// Scene-file spellings of an enumeration, e.g. {"tangent", TrackSegmentKind::tangent}.
template <class Value>
using Choices = std::vector<std::pair<std::string_view, Value>>;
// The choices of an enumeration's name table (core/name_table.hpp).
template <class Value, size_t N>
Choices<Value> choices_of(const NameTable<Value, N>& names) {
  return Choices<Value>(names.begin(), names.end());
}

// The "got ..." of a missing key.
inline constexpr const char* kMissingKey = "nothing (the key is missing)";

// What a TOML value is, for the "got ..." part of a message.
std::string describe_found(const toml::node& node);

// " (kg)", or nothing for a plain ratio.
std::string unit_suffix(std::string_view unit);
// "a number (kg)".
std::string number_description(std::string_view unit);

// A finite number; integers are accepted where a float is expected.
double number_from(const toml::node& node, std::string_view source, std::string_view path,
                   std::string_view unit);
std::string text_from(const toml::node& node, std::string_view source, std::string_view path);
// The index of the spelling the node holds; "expected one of 'a', 'b', got
// 'c' (did you mean ...?)" otherwise.
size_t choice_index(const toml::node& node, std::string_view source, std::string_view path,
                    const std::vector<std::string_view>& spellings);

template <class Value>
Value choice_from(const toml::node& node, std::string_view source, std::string_view path,
                  const Choices<Value>& choices) {
  std::vector<std::string_view> spellings;
  for (const auto& choice : choices) spellings.push_back(choice.first);
  return choices[choice_index(node, source, path, spellings)].second;
}

// The TOML document of a scene; a syntax error is a SceneError
// "<source>: line L, column C: expected valid TOML, got a syntax error: ...".
toml::table parse_toml(const std::string& text, const std::string& source);

// One TOML table plus where it sits in the file. It knows the keys the table
// may hold (declared up front, so a misspelt key is reported as such instead
// of as a missing one) and reads each key as one type, with uniform messages.
class TableReader {
 public:
  TableReader(const toml::table& table, std::string key_path, std::string source,
              std::vector<std::string_view> known_keys, std::string owner = "");

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

  double number(std::string_view key, std::string_view unit) const;
  double number_or(std::string_view key, std::string_view unit, double fallback) const {
    return has(key) ? number(key, unit) : fallback;
  }
  // A whole number in [low, high] (read as a number), or `fallback` when the
  // key is absent; `expected` words the error ("a whole number in [1, 10]").
  double whole_number_or(std::string_view key, double low, double high, double fallback,
                         std::string_view expected) const {
    const double v = number_or(key, "", fallback);
    if (!(v >= low && v <= high && v == std::floor(v))) fail(key, expected, format_number(v));
    return v;
  }
  std::string text(std::string_view key) const;
  bool flag_or(std::string_view key, bool fallback) const;

  // An array of exactly three numbers, e.g. [0.0, 1.0, -0.6075].
  Eigen::Vector3d vector3(std::string_view key, std::string_view unit) const;

  template <class Value>
  Value choice(std::string_view key, const Choices<Value>& choices) const {
    return choice_from(required(key, "a string"), source_, path_of(key), choices);
  }
  template <class Value>
  Value choice_or(std::string_view key, const Choices<Value>& choices, Value fallback) const {
    return has(key) ? choice(key, choices) : fallback;
  }

  const toml::array& array(std::string_view key, std::string_view expected) const;

  // A sub-table ([track], initial_offset = {...}) or nothing if the key is absent.
  const toml::table* raw_table_or_null(std::string_view key) const;
  std::optional<TableReader> optional_table(std::string_view key,
                                            const std::vector<std::string_view>& known_keys) const;
  TableReader table(std::string_view key, const std::vector<std::string_view>& known_keys) const;

  // [[bodies]] and the like: one reader per table, key paths "bodies[i]".
  std::vector<TableReader> tables_in_array(std::string_view key,
                                           const std::vector<std::string_view>& known_keys) const;
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
  // Reading a key the table has not declared is a bug of the reader, not of
  // the file (std::logic_error).
  const toml::node* find(std::string_view key) const;
  const toml::node& required(std::string_view key, std::string_view expected) const;
  void reject_unknown_keys() const;

  const toml::table& table_;
  std::string key_path_;
  std::string source_;
  std::vector<std::string_view> known_keys_;
  std::string owner_;
};

}  // namespace railstab::scene_reading
