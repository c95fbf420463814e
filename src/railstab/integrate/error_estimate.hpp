#pragma once
// A posteriori error estimate of a time-domain run: the same run at
// tolerances `tightening` times tighter is the reference. For a convergent
// method the tight run's own error is ~tightening^(-p/(p+1)) smaller, so the
// difference estimates the loose run's error (work-precision tables show how
// well: e.g. arkode_dirk on the thesis vehicle, 3.0e-6 m at rtol 1e-3 against
// 2.3e-8 m at 1e-5).
#include <railstab/integrate/integrator.hpp>

#include <string>

namespace railstab {

struct ErrorEstimate {
  // False when fewer than two output times are common to both runs (e.g. a
  // run stopped at t = 0): then `reason` says why and the errors are 0.
  bool available = true;
  std::string reason;
  double tightening = 100.0;
  // Max over the common output times of |x - x_tight| over body positions
  // and angles (m, rad), wheelset spin angles excluded; and the same over
  // lateral shifts and yaw angles only.
  double position_error = 0.0;
  std::string where;  // state name of the maximum, e.g. "wheelset1.z_m"
  double lateral_error = 0.0;
  double wall_seconds = 0.0;  // of the tight run
  int compared_outputs = 0;   // output times common to both runs
  // Where the tight run ended and why, when it stopped early: a stop at a
  // different time than the run's own is itself a sign of the error.
  double reference_end_s = 0.0;
  std::string reference_stopped_early;
};

ErrorEstimate estimate_integration_error(const Model& model, double speed_m_per_s,
    const Eigen::VectorXd& x0,
                                         const IntegrationOptions& options, const Trajectory& run,
                                         double tightening = 100.0);

}  // namespace railstab
