#include <railstab/integrate/error_estimate.hpp>

#include <railstab/integrate/work_precision.hpp>

namespace railstab {

ErrorEstimate estimate_integration_error(const Model& model, double speed_m_per_s,
    const Eigen::VectorXd& x0,
                                         const IntegrationOptions& options, const Trajectory& run,
                                         double tightening) {
  IntegrationOptions tight = options;
  tight.relative_tolerance /= tightening;
  tight.absolute_tolerance /= tightening;
  tight.progress = nullptr;  // no progress lines from the second run
  const Trajectory ref = integrate(model, speed_m_per_s, x0, tight);
  ErrorEstimate e;
  e.tightening = tightening;
  e.wall_seconds = ref.stats.wall_seconds;
  e.reference_end_s = ref.times_s.back();
  e.reference_stopped_early = ref.stopped_early;
  // Compared at the output times both runs reached (a stop at a root is at
  // each run's own time and is skipped).
  e.position_error = trajectory_position_error(model, run, ref, &e.where,
                                               ErrorCoordinates::positions, &e.compared_outputs);
  e.lateral_error = trajectory_position_error(model, run, ref, nullptr, ErrorCoordinates::lateral);
  if (e.compared_outputs < 2) {
    e = ErrorEstimate{};
    e.available = false;
    e.tightening = tightening;
    e.reason = "fewer than two output times in common with the tighter run (the run ended at t = " +
               std::to_string(run.times_s.back()) + " s)";
  }
  return e;
}

}  // namespace railstab
