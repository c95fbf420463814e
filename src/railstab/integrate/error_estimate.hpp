#pragma once
// A posteriori error estimate of a time-domain run: the same run at
// tolerances `tightening` times tighter is the reference. For a convergent
// method the tight run's own error is ~tightening^(-p/(p+1)) smaller, so the
// difference estimates the loose run's error (work-precision tables show how
// well: e.g. arkode_dirk on the thesis vehicle, 3.0e-6 m at rtol 1e-3 against
// 2.3e-8 m at 1e-5).
//
// On a limit cycle that difference measures the wrong thing: two runs on the
// same cycle whose periods differ by dT drift apart in phase by dT per
// period, so after n periods they differ by up to 2 A sin(pi n dT / T) even
// when both amplitudes agree to micrometres. So when both runs have settled
// on an oscillation (integrate/oscillation.hpp, on the leading wheelset's
// lateral shift), the estimate of the cycle is the difference of the two
// runs' amplitudes and periods over their last periods; the largest
// difference is kept, named the phase drift.
#include <railstab/integrate/integrator.hpp>
#include <railstab/integrate/oscillation.hpp>

#include <string>

namespace railstab {

// The limit-cycle part of an error estimate.
struct LimitCycleError {
  // Both runs settled (SettledOscillationCriteria defaults: the last 5
  // periods, amplitude and period each within 1 %); otherwise `reason`.
  bool settled = false;
  std::string reason;
  std::string signal;  // e.g. "wheelset1.y_m"
  int periods_compared = 0;
  double amplitude_m = 0.0, reference_amplitude_m = 0.0;  // half peak-to-peak
  double period_s = 0.0, reference_period_s = 0.0;
  double amplitude_error_m = 0.0;  // |amplitude - reference amplitude|
  double period_error_s = 0.0;     // |period - reference period|
};

// Compares the settled oscillations of `signal_state` in two runs.
LimitCycleError limit_cycle_error(const Model& model, int signal_state, const Trajectory& run,
                                  const Trajectory& reference,
                                  const SettledOscillationCriteria& criteria = {});

struct ErrorEstimate {
  // False when fewer than two output times are common to both runs (e.g. a
  // run stopped at t = 0): then `reason` says why and the errors are 0.
  bool available = true;
  std::string reason;
  double tightening = 100.0;
  // Max over the common output times of |x - x_tight| over body positions
  // and angles (m, rad), wheelset spin angles excluded; and the same over
  // lateral shifts and yaw angles only. On a limit cycle (limit_cycle.settled)
  // this is the phase drift between the runs, not an error of the cycle.
  double position_error = 0.0;
  std::string where;  // state name of the maximum, e.g. "wheelset1.z_m"
  double lateral_error = 0.0;
  double wall_seconds = 0.0;  // of the tight run
  double cpu_seconds = 0.0;   // of the tight run (process CPU)
  LimitCycleError limit_cycle;
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
