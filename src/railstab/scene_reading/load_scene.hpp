#pragma once
// Loading a scene file (TOML) into a checked SceneSpec: the one header for
// every way in (a file, a file with --set values, TOML text, the contacts
// of a file).
//
// The file format is documented at the top of every file in cases/, in
// docs/scene_format.md and, section by section, in the readers of
// scene_reading/ (scene_reader.hpp lists them). Parsing is strict: unknown
// keys, wrong types, non-finite numbers and missing required keys are
// errors. Every error is a SceneError whose message reads
//   "<file>: <key path>: <what was expected>, got <what was found>"
// e.g. "cases/x.toml: bodies[2].mass_kg: expected a positive number (kg), got -3".
// The loaded scene is checked once (scene_checker.hpp).
//
// Loading records the profile files of a geometry = "profiles" contact but
// does not read them: the set-up step builds the contact tables
// (setup/contact_tables.hpp; prepare_scene and build_model do it).
#include <railstab/scene/scene_spec.hpp>
#include <railstab/scene_reading/scene_error.hpp>
#include <railstab/scene_reading/scene_set_values.hpp>

#include <string>
#include <vector>

namespace railstab {

// The text of a scene file; a file that cannot be read, or is not a regular
// file (a pipe, a folder), is a SceneError "<path>: scene file: ...".
std::string read_scene_text(const std::string& path);

// Reads the file, parses it and checks the result. SceneSpec::source_sha256
// is the SHA-256 of the bytes read.
SceneSpec load_scene_file(const std::string& path);

// The same with `settings` (--set values) applied to the file's text first
// (scene_set_values.hpp); a reader or checker error then also says which
// settings were in force. source_sha256 is that of the file's bytes as
// read, before the settings (reports list the settings apart).
SceneSpec load_scene_file(const std::string& path, const std::vector<SceneValueSetting>& settings);

// The scene's [track.irregularities], or SceneError naming `path` and the
// key when the track is perfect (for `railstab track` and its Python twin,
// which have nothing to show then).
const IrregularitySpec& required_track_irregularities(const SceneSpec& spec, const std::string& path);

// Parses TOML text and checks the result; `source_name` (usually the file
// path) prefixes every message and becomes SceneSpec::source_path. No file
// is read, so source_sha256 stays empty.
SceneSpec load_scene_text(const std::string& toml_text, const std::string& source_name);

// Reads only the [contacts.NAME] tables of a scene file, or of a file that
// holds contacts alone (e.g. cases/s1002_uic60_contact.toml), with the keys
// and messages of a scene; the other sections are neither read nor
// checked. `settings`: --set values applied to the file's text first.
// Profile contacts come without their tables: load_scene_contacts
// (setup/contact_tables.hpp) builds them.
std::vector<ContactSpec> read_scene_contacts(const std::string& path,
                                             const std::vector<SceneValueSetting>& settings = {});

}  // namespace railstab
