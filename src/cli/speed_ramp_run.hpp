#pragma once
// `simulate --ramp-rate A [--ramp-rate A2 ...] [--ramp-to V] [--hunting-threshold M]`:
// one speed ramp per rate from the run's speed (nonlinear/speed_ramp.hpp),
// each from the same start, written as one output set
// (report/speed_ramp_report.hpp).
#include <railstab/integrate/integrator.hpp>
#include <railstab/report/simulation_report.hpp>
#include <railstab/setup/prepare_scene.hpp>

#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <vector>

namespace railstab {

// Without --ramp-to the ramp ends at this share of the start speed.
inline constexpr double kDefaultRampEndSpeedShare = 0.5;
inline constexpr double kDefaultHuntingThreshold_m = 1e-4;

struct RampFlags {
  std::vector<double> rates_m_per_s2;  // empty: no ramp
  std::optional<double> end_speed_m_per_s;
  double hunting_threshold_m = kDefaultHuntingThreshold_m;
};

void add_ramp_flags(CLI::App* cmd, RampFlags& ramp);

// Runs the ramps and writes their outputs into out_dir, named after the
// scene file (scene_path's stem) and the start speed; prints the summary.
void run_speed_ramps(const PreparedScene& scene, const std::string& scene_path,
                     const Eigen::VectorXd& x0, const RunStart& start,
                     const IntegrationOptions& integration, const RampFlags& ramp,
                     const std::string& out_dir);

}  // namespace railstab
