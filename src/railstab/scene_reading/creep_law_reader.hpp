#pragma once
// The creep law keys of a [contacts.<name>] table: creep_law =
// "linear_kalker" (default), "shen_hedrick_elkins" or "polach", with
// friction_coefficient (default the law's: 0.4 SHE, 0.55 Polach's mu0),
// kalker_reduction_factor (1) and Polach's polach_limit_friction_ratio (A),
// polach_friction_decrease_s_per_m (B), polach_adhesion_reduction_factor
// (kA), polach_slip_reduction_factor (kS) (contact/creep/).
#include <railstab/scene/scene_spec.hpp>
#include <railstab/scene_reading/table_reader.hpp>

#include <string_view>
#include <vector>

namespace railstab::scene_reading {

// The keys above, for the contact table's declaration.
const std::vector<std::string_view>& creep_law_keys();

// `spec`: the contact as read so far (Polach's method needs tangential =
// "kalker_hertz").
CreepLawSpec read_creep_law(const TableReader& contact, const ContactSpec& spec);

}  // namespace railstab::scene_reading
