#include "profiles/profile_contact_scene.hpp"

#include "profiles/profile_readers.hpp"

#include <toml++/toml.h>

#include <cmath>
#include <filesystem>
#include <sstream>

namespace railstab {
namespace {

[[noreturn]] void fail(const std::string& scene, const std::string& key, const std::string& expected,
                       const std::string& got) {
  throw ProfileError(scene + ": " + key + ": expected " + expected + ", got " + got);
}

std::string describe(const toml::node& n) {
  std::ostringstream s;
  if (n.is_string()) s << '"' << n.as_string()->get() << '"';
  else if (auto v = n.value<double>()) s << *v;
  else if (auto b = n.value<bool>()) s << (*b ? "true" : "false");
  else s << "a " << n.type();
  return s.str();
}

// One of key, key_mm, key_m: the path and the unit of a plain-text file.
void read_profile_key(const std::string& scene, const std::string& table_path,
                      const toml::table& t, const std::string& key, std::string& path,
                      LengthUnit& unit) {
  int found = 0;
  for (const auto& [suffix, u] : {std::pair<const char*, LengthUnit>{"", LengthUnit::millimetre},
                                  {"_mm", LengthUnit::millimetre},
                                  {"_m", LengthUnit::metre}}) {
    const std::string k = key + suffix;
    const toml::node* n = t.get(k);
    if (!n) continue;
    ++found;
    if (!n->is_string()) fail(scene, table_path + "." + k, "a file path (string)", describe(*n));
    path = n->as_string()->get();
    unit = u;
    if (std::string(suffix).empty()) {
      std::string ext = std::filesystem::path(path).extension().string();
      if (ext != ".prw" && ext != ".prr")
        fail(scene, table_path + "." + k,
             "a SIMPACK .prw/.prr file (a plain-text profile names its unit: " + key + "_mm or " +
                 key + "_m)",
             '"' + path + '"');
    }
  }
  if (found != 1)
    fail(scene, table_path + "." + key,
         "exactly one of " + key + " (SIMPACK), " + key + "_mm or " + key + "_m (plain text)",
         found == 0 ? std::string("none") : std::to_string(found) + " of them");
}

double number_or(const std::string& scene, const std::string& table_path, const toml::table& t,
                 const std::string& key, double fallback) {
  const toml::node* n = t.get(key);
  if (!n) return fallback;
  std::optional<double> v = n->value<double>();
  if (!v || !std::isfinite(*v)) fail(scene, table_path + "." + key, "a finite number", describe(*n));
  return *v;
}

}  // namespace

ProfileContactSpec read_profile_contact(const std::string& scene_path,
                                        const std::string& contact_name) {
  toml::table root;
  try {
    root = toml::parse_file(scene_path);
  } catch (const toml::parse_error& e) {
    std::ostringstream msg;
    msg << scene_path << ":" << e.source().begin.line << ": TOML syntax error: " << e.description();
    throw ProfileError(msg.str());
  }
  const toml::table* contacts = root["contacts"].as_table();
  std::vector<std::string> profile_contacts;
  if (contacts)
    for (const auto& [name, node] : *contacts)
      if (const toml::table* t = node.as_table())
        if (t->get("geometry") && t->get("geometry")->value<std::string>() == "profiles")
          profile_contacts.emplace_back(name.str());
  std::string name = contact_name;
  if (name.empty()) {
    if (profile_contacts.size() != 1) {
      std::string list;
      for (const std::string& n : profile_contacts) list += (list.empty() ? "" : ", ") + n;
      fail(scene_path, "contacts",
           "exactly one contact with geometry = \"profiles\" (or name one with --contact)",
           profile_contacts.empty() ? "none" : list);
    }
    name = profile_contacts.front();
  }
  const std::string table_path = "contacts." + name;
  const toml::table* t = contacts ? (*contacts)[name].as_table() : nullptr;
  if (!t) fail(scene_path, table_path, "a table [" + table_path + "]", "no such table");
  const toml::node* geometry = t->get("geometry");
  if (!geometry || geometry->value<std::string>() != "profiles")
    fail(scene_path, table_path + ".geometry", "\"profiles\"",
         geometry ? describe(*geometry) : std::string("missing key"));

  ProfileContactSpec spec;
  spec.name = name;
  const std::filesystem::path folder = std::filesystem::path(scene_path).parent_path();
  read_profile_key(scene_path, table_path, *t, "wheel_profile", spec.wheel_profile_path,
                   spec.wheel_unit);
  read_profile_key(scene_path, table_path, *t, "rail_profile", spec.rail_profile_path,
                   spec.rail_unit);
  spec.wheel_profile_path = (folder / spec.wheel_profile_path).lexically_normal().string();
  spec.rail_profile_path = (folder / spec.rail_profile_path).lexically_normal().string();
  ProfilePairParameters& p = spec.parameters;
  p.track_gauge_m = number_or(scene_path, table_path, *t, "track_gauge_m", p.track_gauge_m);
  p.gauge_measuring_height_m = number_or(scene_path, table_path, *t, "gauge_measuring_height_m",
                                         p.gauge_measuring_height_m);
  p.flange_back_distance_m = number_or(scene_path, table_path, *t, "flange_back_distance_m",
                                       p.flange_back_distance_m);
  p.nominal_rolling_radius_m = number_or(scene_path, table_path, *t, "nominal_rolling_radius_m",
                                         p.nominal_rolling_radius_m);
  p.rail_inclination_rad =
      number_or(scene_path, table_path, *t, "rail_inclination_rad", p.rail_inclination_rad);
  p.tape_circle_from_flange_back_m = number_or(
      scene_path, table_path, *t, "tape_circle_from_flange_back_m", p.tape_circle_from_flange_back_m);
  return spec;
}

ProfilePair load_profile_pair(const ProfileContactSpec& spec) {
  Profile wheel = read_profile_file(spec.wheel_profile_path, ProfileKind::wheel, spec.wheel_unit);
  Profile rail = read_profile_file(spec.rail_profile_path, ProfileKind::rail, spec.rail_unit);
  try {
    return make_profile_pair(std::move(wheel), std::move(rail), spec.parameters);
  } catch (const ProfileError& e) {
    throw ProfileError("contacts." + spec.name + ": " + e.what());
  }
}

}  // namespace railstab
