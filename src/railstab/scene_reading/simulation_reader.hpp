#pragma once
// [simulation] and [assessment], optional. [simulation]: t_end_s, output_interval_s, integrator,
// integrator_order (0: the method's default), relative_tolerance,
// absolute_tolerance; defaults in scene/scene_spec.hpp (SimulationSpec).
#include <railstab/scene/scene_spec.hpp>
#include <railstab/scene_reading/table_reader.hpp>

namespace railstab::scene_reading {

// Reads the [simulation] table of the document `top`, or the defaults.
SimulationSpec read_simulation(const TableReader& top);
// [assessment]: prudhomme_factor (AssessmentSpec; docs/ride_quantities.md).
AssessmentSpec read_assessment(const TableReader& top);

}  // namespace railstab::scene_reading
