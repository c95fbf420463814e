#include <railstab/report/simulation_report.hpp>

#include <railstab/io/json_writer.hpp>

#include <sstream>

namespace railstab {

std::string simulation_run_json(const Model& model, double speed_m_per_s,
                                const IntegrationOptions& opt, const Trajectory& traj,
                                const std::optional<ErrorEstimate>& error) {
  std::ostringstream out;
  JsonWriter j(out);
  const double simulated = traj.times_s.back() - opt.t_start_s;
  j.begin_object()
      .field("scene", model.name)
      .field("speed_m_per_s", speed_m_per_s)
      .field("states", model.state_size())
      .field("integrator", IntegratorVariant{opt.kind, opt.order}.label())
      .field("relative_tolerance", opt.relative_tolerance)
      .field("absolute_tolerance", opt.absolute_tolerance)
      .field("simulated_s", simulated)
      .field("wall_s", traj.stats.wall_seconds)
      .field("cpu_s", traj.stats.cpu_seconds);
  j.key("real_time_factor");
  if (simulated > 0.0 && traj.stats.wall_seconds > 0.0)
    j.value(simulated / traj.stats.wall_seconds);
  else
    j.null();
  j.field("steps", int(traj.stats.steps))
      .field("rhs_evaluations", int(traj.stats.rhs_evaluations))
      .field("jacobian_evaluations", int(traj.stats.jacobian_evaluations))
      .field("stopped_early", traj.stopped_early);
  j.key("contact_events").begin_array();
  for (const ContactEvent& e : traj.events) j.value(e.description);
  j.end_array();
  j.key("error_estimate");
  if (!error) {
    j.null();
  } else {
    j.begin_object().field("method", "difference to the same run at " +
                                         std::to_string(int(error->tightening)) +
                                         "x tighter tolerances, at the output times both reached");
    if (!error->available) {
      j.field("available", false).field("reason", error->reason);
    } else {
      j.field("available", true)
          .field("position_error", error->position_error)
          .field("position_error_at", error->where)
          .field("lateral_error", error->lateral_error)
          .field("compared_outputs", error->compared_outputs)
          .field("reference_end_s", error->reference_end_s)
          .field("reference_stopped_early", error->reference_stopped_early)
          .field("reference_wall_s", error->wall_seconds);
    }
    j.end_object();
  }
  j.end_object();
  return out.str();
}

}  // namespace railstab
