#pragma once
// Plots of `simulate`'s ride-quantity CSVs (io/ride_files.hpp) with gnuplot:
// Sum Y of every wheelset against time with Prud'homme's limit, Y/Q of every
// wheel, and the lateral and vertical accelerations of the bodies' points.
// The script <stem>_ride_plots.gp is kept beside the PNGs.
#include <railstab/io/output_set.hpp>
#include <railstab/model/model.hpp>
#include <railstab/report/time_plots.hpp>
#include <railstab/ride/ride_history.hpp>

#include <string>
#include <vector>

namespace railstab {

void plot_ride_quantities(const Model& model, double speed_m_per_s, OutputSet& outputs,
                          const std::string& stem, const RideHistory& history,
                          const PlottedCsv& wheel_forces, const PlottedCsv& accelerations,
                          double t_start_s, double t_end_s);

// Every file plot_ride_quantities may write for `stem`.
std::vector<std::string> ride_plot_file_names(const std::string& stem);

}  // namespace railstab
