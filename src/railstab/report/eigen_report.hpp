#pragma once
// One speed's eigen-analysis (stability/speed_analysis.hpp) as a JSON file
// and a table for the terminal.
#include <railstab/io/output_set.hpp>
#include <railstab/model/model.hpp>
#include <railstab/stability/speed_analysis.hpp>

#include <ostream>
#include <string>
#include <vector>

namespace railstab {

// Adds <stem>_eigen_<V>mps.json (every mode: eigenvalue, frequency, damping
// ratio, residual, name, shape with energy shares: report/mode_shape_report.hpp)
// to `outputs` (staged; the caller commits). `shapes`: one per p.modes
// (stability/point_mode_shapes.hpp full_mode_shapes).
void write_eigen_json(const Model& model, const StabilityPoint& p,
                      const std::vector<ModeShape>& shapes, OutputSet& outputs,
                      const std::string& stem);

// The state count, removed cyclic states, solver and the modes with
// frequency up to `max_frequency_hz` (one line each, upper half plane).
void print_eigen_summary(std::ostream& out, const Model& model, const StabilityPoint& p,
                         double max_frequency_hz);

}  // namespace railstab
