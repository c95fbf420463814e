#pragma once
// Reading scene files (TOML) into a SceneSpec, and checking that a SceneSpec
// makes physical sense before a model is built from it.
//
// The file format is documented at the top of every file in cases/ and in
// scene_loader.cpp. Parsing is strict: unknown keys, wrong types, non-finite
// numbers and missing required keys are errors. Every error is a SceneError
// whose message reads
//   "<file>: <key path>: <what was expected>, got <what was found>"
// e.g. "cases/x.toml: bodies[2].mass_kg: expected a positive number (kg), got -3".
#include <stdexcept>
#include <string>

#include <railstab/io/scene_set_values.hpp>
#include <railstab/scene/scene_spec.hpp>

namespace railstab {

struct SceneError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The text of a scene file; a file that cannot be read, or is not a regular
// file (a pipe, a folder), is a SceneError "<path>: scene file: ...".
std::string read_scene_text(const std::string& path);

// Reads the file, parses it and validates the result.
SceneSpec load_scene_file(const std::string& path);

// Reads only the [contacts.NAME] tables of a scene file, or of a file that
// holds contacts alone (e.g. cases/s1002_uic60_contact.toml), each validated
// as in a scene (profile contacts with their files read and their tables
// built). The other sections are neither read nor checked: for commands
// about a contact (contact-geometry). `settings`: --set values applied to
// the file's text first (io/scene_set_values.hpp).
std::vector<ContactSpec> load_scene_contacts(const std::string& path,
                                             const std::vector<SceneValueSetting>& settings = {});

// Parses TOML text and validates the result; `source_name` (usually the file
// path) prefixes every message and becomes SceneSpec::source_path.
SceneSpec parse_scene(const std::string& toml_text, const std::string& source_name);

// Semantic checks (positive masses, physical inertias, known body and contact
// names, speed > 0 with creep forces, track long enough, ...). parse_scene calls
// it; call it again after changing a scene in code (e.g. command-line --speed).
void validate_scene(const SceneSpec& scene);

}  // namespace railstab
