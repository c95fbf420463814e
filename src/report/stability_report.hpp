#pragma once
// Results of the speed analysis as files: eigenvalues over speed (CSV),
// tracked modes (gnuplot data), root-locus / damping / frequency plots,
// the critical-speed JSON and the Markdown report that links the plots.
#include "model/model.hpp"
#include "stability/speed_analysis.hpp"

#include <string>
#include <vector>

namespace railstab {

struct StabilityFiles {
  std::string csv, json, markdown;
  std::vector<std::string> plots;
};

// Writes every file under output_prefix (e.g. "out/thesis_vehicle_tangent").
// `max_plot_frequency_hz` keeps the stiff contact modes off the plots.
StabilityFiles write_stability_results(const Model& model, const CriticalSpeedResult& result,
                                       const std::string& output_prefix,
                                       const std::string& eigen_solver_name,
                                       double max_plot_frequency_hz = 20.0);

}  // namespace railstab
