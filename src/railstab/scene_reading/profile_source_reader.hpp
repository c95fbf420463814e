#pragma once
// geometry = "profiles" in a [contacts.<name>] table: which wheel and rail
// profile files, how they are placed, and the grid of the contact table
// (contact_geometry/profile_contact_geometry.hpp). Only recorded here: the
// files are read and the table built by the set-up step
// (setup/contact_tables.hpp), not while the scene is read.
#include <railstab/scene/scene_spec.hpp>
#include <railstab/scene_reading/table_reader.hpp>

#include <string_view>
#include <vector>

namespace railstab::scene_reading {

// The keys of a profile contact, for the contact table's declaration.
const std::vector<std::string_view>& profile_keys();

// Reads spec.profile_source (the file paths resolved against the scene's
// folder) and refuses the keys of the flangeless models and a normal force
// other than Hertz.
void read_profile_contact(const TableReader& contact, ContactSpec& spec);

// geometry = "table": the keys contact_table (the file, relative to the
// scene) and contact_table_format ("railstab", default, or "rsgeo"); the
// grid keys table_* only for an RSGEO table (resampled on that grid). The
// same refusals as for profiles.
const std::vector<std::string_view>& table_file_keys();
void read_table_contact(const TableReader& contact, ContactSpec& spec);

// The table_* grid keys of a profile (or RSGEO) contact into `grid`.
void read_table_grid(const TableReader& contact, ContactTableOptions& grid);

}  // namespace railstab::scene_reading
