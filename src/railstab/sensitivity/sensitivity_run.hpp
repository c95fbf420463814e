#pragma once
// The `sensitivity` analysis of a prepared scene, whole: the critical speed
// found to 1e-6 m/s (the derivative holds at Re lambda = 0), checked to be an
// oscillatory crossing (the implicit function theorem needs an eigenvalue
// that crosses the imaginary axis continuously:
// stability/loss_of_stability.hpp), then dVc/dp of the asked parameters
// (critical_speed_sensitivity.hpp). The command line and the Python module's
// sensitivity() and critical_speed(gradient=...) both call this, so they
// give the same numbers.
#include <railstab/sensitivity/critical_speed_sensitivity.hpp>
#include <railstab/setup/prepare_scene.hpp>
#include <railstab/stability/speed_analysis.hpp>

#include <functional>
#include <string>
#include <vector>

namespace railstab {

struct SensitivityRunOptions {
  std::vector<std::string> keys;  // parameter_keys names; empty: all
  double from_m_per_s = 5.0, to_m_per_s = 150.0, grid_step_m_per_s = 2.5;
  double hunting_band_hz = 20.0;
  std::function<void(const std::string&)> progress;  // the search's lines
  // How the caller's interface names the keys and the speed range, for the
  // messages: the command line's flags by default.
  std::string keys_name = "--key", range_name = "--from/--to";
};

struct SensitivityRun {
  CriticalSpeedResult search;   // to 1e-6 m/s
  ModeReport mode;              // the hunting mode at the critical speed
  CriticalSpeedSensitivities sensitivities;
};

// Throws std::invalid_argument for a key that is no parameter of the scene,
// std::runtime_error (naming the scene file) when there is no critical speed
// in the range or it is not an oscillatory crossing.
SensitivityRun run_sensitivity(const PreparedScene& scene, const SensitivityRunOptions& options);

}  // namespace railstab
