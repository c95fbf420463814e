#pragma once
// Mode shapes in reports: the JSON object of one mode's shape (every free
// coordinate's amplitude, phase and energy shares) and a Markdown table.
#include <railstab/io/json_writer.hpp>
#include <railstab/model/model.hpp>
#include <railstab/stability/mode_shape.hpp>

#include <ostream>
#include <vector>

namespace railstab {

// The value of a "shape" key: {normalised_to, units, potential_energy_defined,
// coordinates: [{body, coordinate, amplitude, phase_deg,
// kinetic_energy_share, potential_energy_share (null when undefined)}]}.
void write_mode_shape_json(JsonWriter& j, const Model& model, const ModeShape& shape);

// Markdown table of the coordinates that move (amplitude or either energy
// share at least `min_share` of the largest), body order.
void write_mode_shape_markdown(std::ostream& md, const Model& model, const ModeShape& shape,
                               double min_share = 0.01);

}  // namespace railstab
