#pragma once
// One EN 14363 running-stability run, as the `assess` command and the
// Python module's `assess` make it: the time-domain run from a start state
// with the scene's integration options, its outputs at least every 0.5 m
// (the step of EN 14363's 2 m means), the ride quantities over it and their
// assessment (running_stability.hpp), with what a report says of the run.
#include <railstab/assessment/running_stability.hpp>
#include <railstab/model/model.hpp>
#include <railstab/scene/scene_spec.hpp>

#include <Eigen/Dense>

#include <functional>
#include <string>

namespace railstab {

struct AssessmentRunConditions {
  double speed_m_per_s = 0.0;
  std::string excitation;  // how the run was disturbed
  std::string integrator;
  double relative_tolerance = 0.0;
  double output_interval_s = 0.0;  // the scene's, or 0.5 m / V if smaller
  double simulated_s = 0.0;
};

struct AssessmentRun {
  RunningStabilityAssessment assessment;
  AssessmentRunConditions conditions;
};

// `start` says how x0 was disturbed ("the scene's initial offsets and
// rates", "mode 'hunting', wheelset1 lateral 0.005 m"): the report's
// excitation, with the track's irregularities where the model has them.
// `progress` gets the simulated time (s).
AssessmentRun run_running_stability_assessment(const Model& model, double speed_m_per_s,
                                               const Eigen::VectorXd& x0, const std::string& start,
                                               const SimulationSpec& simulation,
                                               const AssessmentSpec& assessment,
                                               const std::function<void(double)>& progress = {});

}  // namespace railstab
