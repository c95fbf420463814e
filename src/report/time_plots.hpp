#pragma once
// Time-history plots of a simulation CSV with gnuplot (PNG, pngcairo):
// lateral shift, yaw and roll of the bodies against time, as thesis figures
// 5.11-5.21. The gnuplot script is kept beside the PNGs so a user can restyle.
#include "model/model.hpp"

#include <string>
#include <vector>

namespace railstab {

// Returns the PNG paths written. Throws std::runtime_error if gnuplot fails.
std::vector<std::string> plot_time_histories(const Model& model, double speed_m_per_s,
                                             const std::string& csv_path,
                                             const std::string& absolute_roll_csv_path,
                                             const std::string& output_prefix);

// Runs gnuplot on a script file; throws with gnuplot's exit status on failure.
void run_gnuplot(const std::string& script_path);

}  // namespace railstab
