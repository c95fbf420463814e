#include <railstab/setup/contact_tables.hpp>

#include <railstab/contact_geometry/contact_table_file.hpp>
#include <railstab/contact_geometry/profile_contact_geometry.hpp>
#include <railstab/contact/rsgeo_table.hpp>
#include <railstab/scene_reading/load_scene.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace railstab {

namespace {
bool lacks_table(const ContactSpec& contact) {
  return uses_contact_table(contact.geometry) && !contact.profile_geometry;
}

// geometry = "table": the file in its format. The table's rolling radii and
// the wheel's placement are for its r0, which must be the contact's (the
// spin rate V / r0 and the pose use it).
std::shared_ptr<const ProfileContactGeometry> read_table_geometry(const ContactSpec& contact,
                                                                   const std::string& source) {
  std::shared_ptr<const ProfileContactGeometry> g;
  if (contact.contact_table_format == ContactTableFormat::rsgeo)
    g = read_rsgeo_contact_geometry(contact.contact_table_path, contact.profile_source.table,
                                    contact.nominal_rolling_radius_m);
  else
    g = read_contact_table_file(contact.contact_table_path);
  const double r0 = g->pair.parameters.nominal_rolling_radius_m;
  if (std::abs(r0 - contact.nominal_rolling_radius_m) > 1e-12) {
    std::ostringstream msg;
    msg << std::setprecision(17) << source << ": contacts." << contact.name
        << ".nominal_rolling_radius_m: expected the contact table's nominal rolling radius " << r0
        << " m (" << contact.contact_table_path << "), got " << contact.nominal_rolling_radius_m;
    throw SceneError(msg.str());
  }
  return g;
}

}  // namespace

void build_contact_tables(std::vector<ContactSpec>& contacts, const std::string& source) {
  for (ContactSpec& contact : contacts) {
    if (!lacks_table(contact)) continue;
    try {
      contact.profile_geometry =
          contact.geometry == ContactGeometryKind::table
              ? read_table_geometry(contact, source)
              : build_profile_contact_geometry(contact.profile_source,
                                               contact.nominal_rolling_radius_m);
    } catch (const ProfileError& e) {
      throw SceneError(source + ": contacts." + contact.name + ": " + e.what());
    } catch (const ContactTableFileError& e) {
      throw SceneError(source + ": contacts." + contact.name + ".contact_table: " + e.what());
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

const ContactSpec& chosen_profile_contact(const std::vector<ContactSpec>& contacts,
                                          const std::string& path, const std::string& name,
                                          const std::string& name_flag) {
  std::vector<const ContactSpec*> profile_contacts;
  std::string names;
  for (const ContactSpec& c : contacts)
    if (uses_contact_table(c.geometry) && c.profile_geometry) {
      profile_contacts.push_back(&c);
      names += (names.empty() ? "'" : ", '") + c.name + "'";
    }
  if (names.empty()) names = "none";
  if (name.empty()) {
    if (profile_contacts.size() != 1)
      throw SceneError(path + ": contacts: expected exactly one contact with geometry = "
                       "\"profiles\" or \"table\" (or name one with " + name_flag + "), got " + names);
    return *profile_contacts.front();
  }
  for (const ContactSpec* c : profile_contacts)
    if (c->name == name) return *c;
  throw SceneError(path + ": " + name_flag + " '" + name +
                   "': expected the name of a contact with geometry = \"profiles\" or "
                   "\"table\" in the scene, got no such contact (profile contacts: " + names + ")");
}

}  // namespace railstab
