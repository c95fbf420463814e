#include <railstab/setup/contact_tables.hpp>

#include <railstab/contact_geometry/profile_contact_geometry.hpp>
#include <railstab/scene_reading/load_scene.hpp>

#include <algorithm>

namespace railstab {

namespace {
bool lacks_table(const ContactSpec& contact) {
  return contact.geometry == ContactGeometryKind::profiles && !contact.profile_geometry;
}
}  // namespace

void build_contact_tables(std::vector<ContactSpec>& contacts, const std::string& source) {
  for (ContactSpec& contact : contacts) {
    if (!lacks_table(contact)) continue;
    try {
      contact.profile_geometry =
          build_profile_contact_geometry(contact.profile_source, contact.nominal_rolling_radius_m);
    } catch (const ProfileError& e) {
      throw SceneError(source + ": contacts." + contact.name + ": " + e.what());
    }
  }
}

void build_contact_tables(SceneSpec& scene) { build_contact_tables(scene.contacts, scene.source_path); }

bool lacks_contact_tables(const SceneSpec& scene) {
  return std::any_of(scene.contacts.begin(), scene.contacts.end(), lacks_table);
}

std::vector<ContactSpec> load_scene_contacts(const std::string& path,
                                             const std::vector<SceneValueSetting>& settings) {
  std::vector<ContactSpec> contacts = read_scene_contacts(path, settings);
  build_contact_tables(contacts, path);
  return contacts;
}

}  // namespace railstab
