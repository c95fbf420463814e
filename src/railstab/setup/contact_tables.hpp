#pragma once
// The contact tables of a scene's geometry = "profiles" contacts, built in
// the set-up step rather than while the file is read: the reader records
// the profile files and the table's grid (ContactSpec::profile_source),
// this reads the profiles, places the pair and builds the table
// (contact_geometry/profile_contact_geometry.hpp, ~0.1-0.2 s each). A
// contact keeps a table it already has, so copies of a scene (the preload
// and curve twins, sensitivity scenes) share one.
#include <railstab/scene/scene_spec.hpp>
#include <railstab/scene_reading/scene_error.hpp>
#include <railstab/scene_reading/scene_set_values.hpp>

#include <string>
#include <vector>

namespace railstab {

// Builds the table of every profile contact that has none. A profile error
// is a SceneError under the contact's key: "<source>: contacts.<name>: ...".
void build_contact_tables(std::vector<ContactSpec>& contacts, const std::string& source);
void build_contact_tables(SceneSpec& scene);  // source: scene.source_path

// True if a profile contact of the scene has no table yet.
bool lacks_contact_tables(const SceneSpec& scene);

// The contacts of a scene file, or of a file of contacts alone, read as in a
// scene (read_scene_contacts, scene_reading/load_scene.hpp) and with their
// tables built: the set-up of commands about a contact (contact-geometry).
std::vector<ContactSpec> load_scene_contacts(const std::string& path,
                                             const std::vector<SceneValueSetting>& settings = {});

// The contact a command about one contact is about: the one named `name`,
// or with `name` empty the only contact with a contact table (geometry =
// "profiles" or "table"). Throws SceneError naming `path`, `name_flag`
// (how the caller's interface names the choice: "--contact") and the
// profile contacts there are.
const ContactSpec& chosen_profile_contact(const std::vector<ContactSpec>& contacts,
                                          const std::string& path, const std::string& name,
                                          const std::string& name_flag = "--contact");

}  // namespace railstab
