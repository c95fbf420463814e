#pragma once
// A time-domain run's summary (`simulate`'s <stem>_run.json): the scene, the
// speed, the integrator and its tolerances, steps and evaluations, wall and
// CPU time, the wheel-rail contact events and the error estimate.
#include <railstab/integrate/error_estimate.hpp>
#include <railstab/integrate/integrator.hpp>
#include <railstab/integrate/work_precision.hpp>
#include <railstab/model/model.hpp>
#include <railstab/ride/ride_history.hpp>

#include <complex>
#include <optional>
#include <string>
#include <vector>

namespace railstab {

// How the run started: the scene's initial offsets (with --offset values
// written into them), or a mode scaled to the leading wheelset's lateral
// shift (stability/mode_start.hpp).
struct RunStart {
  bool on_mode = false;
  std::vector<std::string> offset_settings;  // --offset texts, in order
  std::string mode_name, leading_wheelset;
  std::complex<double> eigenvalue;
  double amplitude_m = 0.0;
};

// The summary as JSON text, rendered before any file is written so a failure
// here leaves no partial set of outputs. With `ride`, a "ride" object: the
// static wheel loads and per wheelset the largest |Sum Y| against
// Prud'homme's limit, the largest Y/Q per wheel and Delta Q/Q0.
std::string simulation_run_json(const Model& model, double speed_m_per_s,
                                const IntegrationOptions& opt, const Trajectory& traj,
                                const std::optional<ErrorEstimate>& error,
                                const RunStart& start = {}, const RideHistory* ride = nullptr);

}  // namespace railstab
