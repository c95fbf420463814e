#pragma once
// [contacts.<name>]: one table per wheel-rail contact model, named by its
// key; wheelsets name theirs (bodies[i].contact). geometry =
// knife_edge_cone | linear_conicity | profiles, normal = hertz |
// prescribed, tangential = kalker_hertz | constant | none, their numbers,
// the creep law (creep_law_reader.hpp) and, for profiles, the profile files
// (profile_source_reader.hpp).
#include <railstab/scene/scene_spec.hpp>
#include <railstab/scene_reading/table_reader.hpp>

#include <vector>

namespace railstab::scene_reading {

// What the contacts are read for: a vehicle model needs every force model
// (normal and tangential required); the contact geometry alone
// (contact-geometry, a file of contacts) needs neither: without the keys
// they take the profile contact's only choices, hertz and kalker_hertz.
enum class ContactUse { model, geometry_only };

// Every [contacts.<name>] table of the document `top`, in file order.
std::vector<ContactSpec> read_contacts(const TableReader& top,
                                       ContactUse use = ContactUse::model);

}  // namespace railstab::scene_reading
