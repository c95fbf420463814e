#include <railstab/scene_reading/contacts_reader.hpp>

#include <railstab/scene_reading/creep_law_reader.hpp>
#include <railstab/scene_reading/profile_source_reader.hpp>

#include <string>
#include <utility>

namespace railstab::scene_reading {

namespace {

const Choices<ContactGeometryKind> kContactGeometries = choices_of(kContactGeometryNames);
const Choices<NormalForceKind> kNormalForces = choices_of(kNormalForceNames);
const Choices<TangentialForceKind> kTangentialForces = choices_of(kTangentialForceNames);

// A number with a default that becomes required for one choice of model
// (e.g. prescribed_wheel_load_N when normal = "prescribed").
double number_required_when(const TableReader& contact, bool required, std::string_view reason,
                            std::string_view key, std::string_view unit, double fallback) {
  if (required && !contact.has(key))
    contact.fail_missing(key, number_description(unit) + ", required " + std::string(reason));
  return contact.number_or(key, unit, fallback);
}

ContactSpec read_contact(const TableReader& contact, std::string name, ContactUse use) {
  ContactSpec spec;
  spec.name = std::move(name);
  spec.geometry = contact.choice("geometry", kContactGeometries);
  if (use == ContactUse::geometry_only) {
    spec.normal = contact.choice_or("normal", kNormalForces, NormalForceKind::hertz);
    spec.tangential =
        contact.choice_or("tangential", kTangentialForces, TangentialForceKind::kalker_hertz);
  } else {
    spec.normal = contact.choice("normal", kNormalForces);
    spec.tangential = contact.choice("tangential", kTangentialForces);
  }

  const bool linear_conicity = spec.geometry == ContactGeometryKind::linear_conicity;
  const bool prescribed = spec.normal == NormalForceKind::prescribed;
  const bool constant = spec.tangential == TangentialForceKind::constant;
  spec.cone_angle_rad = contact.number_or("cone_angle_rad", "rad", spec.cone_angle_rad);
  spec.conicity = number_required_when(
      contact, linear_conicity, "when geometry = 'linear_conicity'", "conicity", "", spec.conicity);
  spec.prescribed_wheel_load_N =
      number_required_when(contact, prescribed, "when normal = 'prescribed'",
                           "prescribed_wheel_load_N", "N", spec.prescribed_wheel_load_N);
  const std::string_view constant_reason = "when tangential = 'constant'";
  spec.f11_N = number_required_when(contact, constant, constant_reason, "f11_N", "N", spec.f11_N);
  spec.f22_N = number_required_when(contact, constant, constant_reason, "f22_N", "N", spec.f22_N);
  spec.f23_N_m =
      number_required_when(contact, constant, constant_reason, "f23_N_m", "N m", spec.f23_N_m);
  spec.f33_N_m2 =
      number_required_when(contact, constant, constant_reason, "f33_N_m2", "N m2", spec.f33_N_m2);

  spec.half_contact_distance_m =
      contact.number_or("half_contact_distance_m", "m", spec.half_contact_distance_m);
  spec.nominal_rolling_radius_m =
      contact.number_or("nominal_rolling_radius_m", "m", spec.nominal_rolling_radius_m);
  spec.rail_head_transverse_radius_m =
      contact.number_or("rail_head_transverse_radius_m", "m", spec.rail_head_transverse_radius_m);
  spec.wheel_young_modulus_Pa =
      contact.number_or("wheel_young_modulus_Pa", "Pa", spec.wheel_young_modulus_Pa);
  spec.wheel_poisson_ratio = contact.number_or("wheel_poisson_ratio", "", spec.wheel_poisson_ratio);
  spec.rail_young_modulus_Pa =
      contact.number_or("rail_young_modulus_Pa", "Pa", spec.rail_young_modulus_Pa);
  spec.rail_poisson_ratio = contact.number_or("rail_poisson_ratio", "", spec.rail_poisson_ratio);
  spec.spin_creepage = contact.flag_or("spin_creepage", spec.spin_creepage);
  spec.flange_clearance_m = contact.number_or("flange_clearance_m", "m", spec.flange_clearance_m);
  // Default: the rail pad's damping for Hertz contact (contact_spec.hpp);
  // none for a prescribed load, which has no normal motion to damp.
  spec.normal_damping_N_s_per_m = contact.number_or(
      "normal_damping_N_s_per_m", "N s/m", prescribed ? 0.0 : kDefaultNormalDamping_N_s_per_m);
  spec.creep_law = read_creep_law(contact, spec);
  if (spec.geometry == ContactGeometryKind::profiles) {
    read_profile_contact(contact, spec);
  } else if (spec.geometry == ContactGeometryKind::table) {
    read_table_contact(contact, spec);
  } else {
    for (std::string_view key : profile_keys())
      contact.reject_if_present(key, "no " + std::string(key) +
                                         " unless geometry = \"profiles\"");
  }
  if (spec.geometry != ContactGeometryKind::table)
    for (std::string_view key : table_file_keys())
      contact.reject_if_present(key, "no " + std::string(key) + " unless geometry = \"table\"");
  return spec;
}

}  // namespace

std::vector<ContactSpec> read_contacts(const TableReader& top, ContactUse use) {
  std::vector<ContactSpec> contacts;
  const toml::table* all_contacts = top.raw_table_or_null("contacts");
  if (!all_contacts) return contacts;
  for (const auto& [name, node] : *all_contacts) {
    const std::string path = child_path("contacts", name.str());
    if (!node.is_table())
      fail_expectation(top.source(), path, "a table [" + path + "] describing a contact model",
                       describe_found(node));
    std::vector<std::string_view> keys = {
        "geometry", "cone_angle_rad", "conicity", "half_contact_distance_m",
        "nominal_rolling_radius_m", "normal", "prescribed_wheel_load_N",
        "rail_head_transverse_radius_m", "wheel_young_modulus_Pa", "wheel_poisson_ratio",
        "rail_young_modulus_Pa", "rail_poisson_ratio", "tangential", "spin_creepage", "f11_N",
        "f22_N", "f23_N_m", "f33_N_m2", "flange_clearance_m",
        "normal_damping_N_s_per_m"};
    keys.insert(keys.end(), creep_law_keys().begin(), creep_law_keys().end());
    keys.insert(keys.end(), profile_keys().begin(), profile_keys().end());
    keys.insert(keys.end(), table_file_keys().begin(), table_file_keys().end());
    const TableReader contact(*node.as_table(), path, top.source(), std::move(keys));
    contacts.push_back(read_contact(contact, std::string(name.str()), use));
  }
  return contacts;
}

}  // namespace railstab::scene_reading
