#include <railstab/scene_reading/scene_reader.hpp>

#include <railstab/scene_reading/bodies_reader.hpp>
#include <railstab/scene_reading/contacts_reader.hpp>
#include <railstab/scene_reading/elements_reader.hpp>
#include <railstab/scene_reading/scene_section_reader.hpp>
#include <railstab/scene_reading/simulation_reader.hpp>
#include <railstab/scene_reading/table_reader.hpp>
#include <railstab/scene_reading/track_reader.hpp>
#include <railstab/scene_reading/train_reader.hpp>

#include <algorithm>
#include <string_view>
#include <utility>

namespace railstab::scene_reading {

namespace {
// The sections of a scene file (the top-level keys), also when only
// [contacts] is read: any other key is a misspelt section.
const std::vector<std::string_view> kSceneSections = {"scene",    "track",      "contacts", "bodies",
                                                      "elements", "simulation", "train",
                                                      "assessment"};
}  // namespace

SceneAsRead read_scene_document(const std::string& toml_text, const std::string& source_name) {
  const toml::table root = parse_toml(toml_text, source_name);
  const TableReader top(root, "", source_name, kSceneSections);
  SceneAsRead read;
  SceneSpec& scene = read.spec;
  scene.source_path = source_name;
  read_scene_section(top, scene);
  scene.track = read_track(top);
  scene.contacts = read_contacts(top);
  scene.bodies = read_bodies(top);
  ElementList elements = read_elements(top);
  scene.elements = std::move(elements.specs);
  read.element_paths = std::move(elements.file_paths);
  const bool contact_table =
      std::any_of(scene.contacts.begin(), scene.contacts.end(),
                  [](const ContactSpec& c) { return uses_contact_table(c.geometry); });
  scene.simulation = read_simulation(top, contact_table);
  scene.assessment = read_assessment(top);
  read_train(top, scene, read.element_paths);
  return read;
}

std::vector<ContactSpec> read_contacts_document(const std::string& toml_text,
                                                const std::string& source_name) {
  const toml::table root = parse_toml(toml_text, source_name);
  const TableReader top(root, "", source_name, kSceneSections);
  return read_contacts(top, ContactUse::geometry_only);
}

}  // namespace railstab::scene_reading
