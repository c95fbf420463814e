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

// Every [contacts.<name>] table of the document `top`, in file order.
std::vector<ContactSpec> read_contacts(const TableReader& top);

}  // namespace railstab::scene_reading
