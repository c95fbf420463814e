#pragma once
// `--set KEY=VALUE`: a value of a scene file replaced (or added) by its key
// path, without copying the file. VALUE is a number, or any TOML value
// written as in the file: an inline table `{ y_m = 0.001 }`, an array
// `[[0.0, 0.0], [0.1, 900.0]]`, a quoted string `"polach"` or a boolean.
//
// The value is written into the parsed TOML document, and the document is
// then read by the scene reader exactly as a file the user had edited: every
// check and every message stays the reader's (a mass set to -3 reads
// "bodies[0].mass_kg: expected a positive number (kg), got -3"), and nothing
// here knows which keys a scene has or what their ranges are.
//
// Key paths name tables by their key and entries of arrays of tables
// ([[bodies]], [[elements]], [[track.segments]]) by their `name` or by an
// index, with one optional index into a numeric array at the end:
//   bodies.carbody.mass_kg              elements.yaw_damper.damping_N_s_per_m[0]
//   contacts.wheel_rail.friction_coefficient   track.segments[1].length_m
//   scene.speed_m_per_s                 bodies[0].inertia_kg_m2[2]
// They match the parameter keys of sensitivity/parameter_derivative.hpp (a
// mirrored element is one scene entry: its key moves both halves). A name
// holding '.' is found too (the longest name that fits is taken). A last key
// the table does not hold is added (an optional key at its default, e.g. a
// friction coefficient); the reader refuses it if that table has no such key.
// Tables missing on the way are added too when the rest of the path has no
// index (`bodies.wheelset1.initial_offset.y_m=0.001` on a body without
// `initial_offset`, `assessment.y_over_q_limit=0.9` on a scene without
// `[assessment]`): an optional section at its default is an empty one. An
// entry of [[bodies]], [[elements]], [[track.segments]] or [contacts.<name>]
// is never created: a name that is not there is refused with the names that
// are.
#include <railstab/scene/scene_spec.hpp>
#include <railstab/scene_reading/scene_error.hpp>

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace railstab {

struct SceneValueSetting {
  SceneValueSetting() = default;
  SceneValueSetting(std::string key_path, double new_value, std::string from = {})
      : key(std::move(key_path)), value(new_value), origin(std::move(from)) {}
  std::string key;
  double value = 0.0;
  // Non-empty: the value is this TOML text (a table, an array, a string or a
  // boolean, as parse_scene_value_setting read it), and `value` is unused.
  std::string toml_value;
  // Where the setting came from, for messages; empty: "--set KEY=VALUE".
  std::string origin;
};

// "KEY=VALUE" with a finite number as VALUE, or a TOML value that starts
// with '{', '[', '"' or '\'' or is true/false (checked to parse here, so a
// malformed one fails before any scene is read); throws
// std::invalid_argument saying what is wrong and what was expected (without
// the flag's name, which the caller adds).
SceneValueSetting parse_scene_value_setting(std::string_view text);

// "KEY=VALUE", the value in its shortest form that reads back exactly.
std::string setting_text(const SceneValueSetting& setting);
std::string number_text_exact(double value);

// The TOML text of a scene with the settings applied in order (a later one
// wins). Throws SceneError "<source>: --set KEY=VALUE: <what is wrong>" (or
// the setting's origin in place of "--set KEY=VALUE") for a
// key the document does not have, an index out of range or a value that is
// not a number where a number is asked (a string, a table, an array given
// without an index), or a TOML value for an entry of an array of tables.
std::string scene_text_with_values(const std::string& toml_text, const std::string& source_name,
                                   const std::vector<SceneValueSetting>& settings);

// " (with --set KEY=VALUE ...)": what a reader's message says after its
// text when settings were in force (each by its origin if it has one).
std::string settings_in_force(const std::vector<SceneValueSetting>& settings);

}  // namespace railstab
