#include "integrate/error_estimate.hpp"

#include "integrate/work_precision.hpp"

namespace railstab {

ErrorEstimate estimate_integration_error(const Model& model, const Eigen::VectorXd& x0,
                                         const IntegrationOptions& options, const Trajectory& run,
                                         double tightening) {
  IntegrationOptions tight = options;
  tight.relative_tolerance /= tightening;
  tight.absolute_tolerance /= tightening;
  // End where the run ended (a run stopped at a validity limit is compared
  // up to there); no progress lines from the second run.
  tight.t_end_s = run.times_s.back();
  tight.progress = nullptr;
  const Trajectory ref = integrate(model, x0, tight);
  ErrorEstimate e;
  e.tightening = tightening;
  e.position_error = trajectory_position_error(model, run, ref, &e.where);
  e.lateral_error = trajectory_position_error(model, run, ref, nullptr, ErrorCoordinates::lateral);
  e.wall_seconds = ref.stats.wall_seconds;
  return e;
}

}  // namespace railstab
