#pragma once
// A time-domain run's summary (`simulate`'s <stem>_run.json): the scene, the
// speed, the integrator and its tolerances, steps and evaluations, wall and
// CPU time, the wheel-rail contact events and the error estimate.
#include <railstab/integrate/error_estimate.hpp>
#include <railstab/integrate/integrator.hpp>
#include <railstab/integrate/work_precision.hpp>
#include <railstab/model/model.hpp>

#include <optional>
#include <string>

namespace railstab {

// The summary as JSON text, rendered before any file is written so a failure
// here leaves no partial set of outputs.
std::string simulation_run_json(const Model& model, double speed_m_per_s,
                                const IntegrationOptions& opt, const Trajectory& traj,
                                const std::optional<ErrorEstimate>& error);

}  // namespace railstab
