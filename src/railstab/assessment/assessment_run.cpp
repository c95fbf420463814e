#include <railstab/assessment/assessment_run.hpp>

#include <railstab/integrate/integrator.hpp>
#include <railstab/integrate/work_precision.hpp>
#include <railstab/irregularity/track_irregularities.hpp>
#include <railstab/ride/ride_history.hpp>

#include <algorithm>

namespace railstab {

AssessmentRun run_running_stability_assessment(const Model& model, double speed_m_per_s,
                                               const Eigen::VectorXd& x0, const std::string& start,
                                               const SimulationSpec& simulation,
                                               const AssessmentSpec& assessment,
                                               const std::function<void(double)>& progress) {
  IntegrationOptions opt = integration_options_for(simulation);
  // EN 14363 steps its 2 m means by 0.5 m: an output at least every 0.5 m.
  opt.output_interval_s = std::min(opt.output_interval_s, 0.5 / speed_m_per_s);
  opt.progress = progress;
  const Trajectory traj = integrate(model, speed_m_per_s, x0, opt);
  const RideHistory ride = ride_history(model, speed_m_per_s, traj, assessment.prudhomme_factor);
  AssessmentRun run;
  run.assessment = assess_running_stability(model, ride, assessment, traj.stopped_early);
  AssessmentRunConditions& c = run.conditions;
  c.speed_m_per_s = speed_m_per_s;
  if (const TrackIrregularities* irr = model.track.irregularities())
    c.excitation = "irregular track (" + irregularity_description(*irr) + "), starting at t = 0 from " + start;
  else
    c.excitation = "perfect track, disturbed at t = 0 by " + start +
                   " (no [track.irregularities]: EN 14363 runs on measured track)";
  c.integrator = IntegratorVariant{opt.kind, opt.order}.label();
  c.relative_tolerance = opt.relative_tolerance;
  c.output_interval_s = opt.output_interval_s;
  c.simulated_s = traj.times_s.back() - opt.t_start_s;
  return run;
}

}  // namespace railstab
