#include <railstab/integrate/error_estimate.hpp>

#include <railstab/integrate/work_precision.hpp>
#include <railstab/model/leading_wheelset.hpp>

#include <cmath>

namespace railstab {

namespace {

std::vector<double> signal_of(const Trajectory& run, int state) {
  std::vector<double> y;
  y.reserve(run.states.size());
  for (const Eigen::VectorXd& x : run.states) y.push_back(x(state));
  return y;
}

}  // namespace

LimitCycleError limit_cycle_error(const Model& model, int signal_state, const Trajectory& run,
                                  const Trajectory& reference,
                                  const SettledOscillationCriteria& criteria) {
  LimitCycleError e;
  if (signal_state < 0) {
    e.reason = "no wheelset with a free lateral shift to follow";
    return e;
  }
  e.signal = model.state_name(signal_state);
  const SettledOscillation a = settled_oscillation(run.times_s, signal_of(run, signal_state), criteria);
  const SettledOscillation b =
      settled_oscillation(reference.times_s, signal_of(reference, signal_state), criteria);
  if (!a.settled || !b.settled) {
    e.reason = !a.settled ? "the run: " + a.reason : "the tighter run: " + b.reason;
    return e;
  }
  e.settled = true;
  e.periods_compared = criteria.periods;
  e.amplitude_m = a.amplitude;
  e.reference_amplitude_m = b.amplitude;
  e.period_s = a.period_s;
  e.reference_period_s = b.period_s;
  e.amplitude_error_m = std::abs(a.amplitude - b.amplitude);
  e.period_error_s = std::abs(a.period_s - b.period_s);
  return e;
}

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
  e.cpu_seconds = ref.stats.cpu_seconds;
  e.reference_end_s = ref.times_s.back();
  e.reference_stopped_early = ref.stopped_early;
  // Compared at the output times both runs reached (a stop at a root is at
  // each run's own time and is skipped).
  e.position_error = trajectory_position_error(model, run, ref, &e.where,
                                               ErrorCoordinates::positions, &e.compared_outputs);
  e.lateral_error = trajectory_position_error(model, run, ref, nullptr, ErrorCoordinates::lateral);
  e.limit_cycle = limit_cycle_error(model, leading_wheelset_lateral_state(model), run, ref);
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
