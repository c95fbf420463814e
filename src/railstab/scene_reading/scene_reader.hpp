#pragma once
// A scene file's text read section by section into a SceneSpec, not yet
// checked (scene_checker.hpp): the reading half of load_scene_file and
// load_scene_text (load_scene.hpp). Internal to scene_reading/.
//
// Sections (complete, commented examples: cases/*.toml; each has its reader):
//   [scene]             scene_section_reader.hpp
//   [track]             track_reader.hpp
//   [contacts.<name>]   contacts_reader.hpp (creep_law_reader, profile_source_reader)
//   [[bodies]]          bodies_reader.hpp
//   [[elements]]        elements_reader.hpp (element_readers/: one file per type)
//   [simulation]        simulation_reader.hpp
//   [train]             train_reader.hpp
#include <railstab/scene/scene_spec.hpp>

#include <string>
#include <vector>

namespace railstab::scene_reading {

// The scene and, for each of its elements, the key path of the table it
// came from (for the checker's messages).
struct SceneAsRead {
  SceneSpec spec;
  std::vector<std::string> element_paths;
};

// `source_name` (usually the file path) prefixes every message and becomes
// SceneSpec::source_path.
SceneAsRead read_scene_document(const std::string& toml_text, const std::string& source_name);

// Only the [contacts.NAME] tables; the other sections are neither read nor
// checked (the file may hold contacts alone).
std::vector<ContactSpec> read_contacts_document(const std::string& toml_text,
                                                const std::string& source_name);

}  // namespace railstab::scene_reading
