#pragma once
// Time-history plots of a simulation CSV with gnuplot (PNG, pngcairo):
// lateral shift, yaw and roll of the bodies against time, as thesis figures
// 5.11-5.21. The gnuplot script is kept beside the PNGs so a user can restyle
// (run it from the output folder).
#include <railstab/io/output_set.hpp>
#include <railstab/model/model.hpp>

#include <string>
#include <vector>

namespace railstab {

// A CSV the plots read: where the kept script finds it (relative to the
// output folder, or absolute), where it is now (staged), and how many
// physical lines its header row takes.
struct PlottedCsv {
  std::string final_path, staged_path;
  int header_lines = 1;
};

// Adds <stem>_plots.gp and the PNGs to `outputs`, runs gnuplot in its
// staging folder and checks every PNG was made (throws GnuplotError
// otherwise). `t_start_s`..`t_end_s` is the plotted time span.
void plot_time_histories(const Model& model, double speed_m_per_s, OutputSet& outputs, const std::string& stem,
                         const PlottedCsv& trajectory, const PlottedCsv& absolute_roll,
                         double t_start_s, double t_end_s);

// The file names plot_time_histories may write for `stem` (so an old run's
// plots are replaced as a set, e.g. by a run with --no-plots).
std::vector<std::string> time_plot_file_names(const std::string& stem);

}  // namespace railstab
