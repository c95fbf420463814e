#pragma once
// [simulation] and [assessment], optional. [simulation]: t_end_s, output_interval_s, integrator,
// integrator_order (0: the method's default), relative_tolerance,
// absolute_tolerance; defaults in scene/scene_spec.hpp (SimulationSpec, and
// profile_contact_simulation_defaults() for a scene with a contact table).
#include <railstab/scene/scene_spec.hpp>
#include <railstab/scene_reading/table_reader.hpp>

namespace railstab::scene_reading {

// Reads the [simulation] table of the document `top`, or the defaults: those
// of a contact table where `contact_table` (any wheelset's geometry is
// "profiles" or "table"), else SimulationSpec's.
SimulationSpec read_simulation(const TableReader& top, bool contact_table);
// [assessment]: prudhomme_factor (AssessmentSpec; docs/ride_quantities.md).
AssessmentSpec read_assessment(const TableReader& top);

}  // namespace railstab::scene_reading
