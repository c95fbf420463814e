#include <railstab/report/simulation_report.hpp>

#include <railstab/io/json_writer.hpp>

#include <cmath>
#include <numbers>
#include <sstream>

namespace railstab {

std::string simulation_run_json(const Model& model, double speed_m_per_s,
                                const IntegrationOptions& opt, const Trajectory& traj,
                                const std::optional<ErrorEstimate>& error,
                                const RunStart& start, const RideHistory* ride) {
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
  j.key("track_irregularities");
  if (const TrackIrregularities* irr = model.track.irregularities())
    j.value(irregularity_description(*irr));
  else
    j.null();
  j.key("start").begin_object();
  if (start.on_mode) {
    j.field("kind", "mode")
        .field("mode", start.mode_name)
        .field("eigenvalue_real_per_s", start.eigenvalue.real())
        .field("eigenvalue_frequency_Hz", std::abs(start.eigenvalue.imag()) / (2.0 * std::numbers::pi))
        .field("leading_wheelset", start.leading_wheelset)
        .field("leading_wheelset_y_m", start.amplitude_m);
  } else {
    j.field("kind", "initial offsets");
    j.key("offset_settings").begin_array();
    for (const std::string& text : start.offset_settings) j.value(text);
    j.end_array();
  }
  j.end_object();
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
          .field("reference_wall_s", error->wall_seconds)
          .field("reference_cpu_s", error->cpu_seconds)
          .field("position_error_kind",
                 error->limit_cycle.settled
                     ? "phase drift along the limit cycle (both runs on the same cycle; not an "
                       "error of the cycle: see limit_cycle)"
                     : "trajectory difference");
      const LimitCycleError& c = error->limit_cycle;
      j.key("limit_cycle").begin_object().field("settled", c.settled).field("reason", c.reason);
      // Null where the runs did not settle on a cycle.
      auto number_or_null = [&](const char* key, double value) {
        j.key(key);
        if (c.settled) j.value(value);
        else j.null();
      };
      j.field("signal", c.signal).field("periods_compared", c.periods_compared);
      number_or_null("amplitude_m", c.amplitude_m);
      number_or_null("reference_amplitude_m", c.reference_amplitude_m);
      number_or_null("amplitude_error_m", c.amplitude_error_m);
      number_or_null("period_s", c.period_s);
      number_or_null("reference_period_s", c.reference_period_s);
      number_or_null("period_error_s", c.period_error_s);
      j.end_object();
    }
    j.end_object();
  }
  if (ride) {
    j.key("ride").begin_object().field("prudhomme_factor", ride->prudhomme_factor);
    j.key("wheelsets").begin_array();
    const std::vector<WheelsetExtremes> extremes = wheelset_extremes(*ride);
    for (size_t w = 0; w < extremes.size(); ++w) {
      const WheelsetExtremes& e = extremes[w];
      const StaticWheelLoad& load = ride->static_loads[w];
      j.begin_object()
          .field("name", model.bodies[size_t(e.body)].name)
          .field("static_wheel_load_left_N", load.left_N)
          .field("static_wheel_load_right_N", load.right_N)
          .field("max_abs_sum_y_N", e.max_abs_sum_y_N)
          .field("max_abs_sum_y_time_s", e.max_abs_sum_y_time_s)
          .field("prudhomme_limit_N", e.prudhomme_limit_N)
          .field("max_abs_sum_y_over_prudhomme_limit", e.max_abs_sum_y_N / e.prudhomme_limit_N)
          .field("max_delta_q_over_q0", e.max_delta_q_over_q0);
      j.key("max_y_over_q_left");
      if (e.max_y_over_q_left) j.value(*e.max_y_over_q_left);
      else j.null();
      j.key("max_y_over_q_right");
      if (e.max_y_over_q_right) j.value(*e.max_y_over_q_right);
      else j.null();
      j.key("max_abs_sum_y_2m_N");
      if (e.max_abs_sum_y_2m_N) j.value(*e.max_abs_sum_y_2m_N);
      else j.null();
      j.key("max_y_over_q_2m");
      if (e.max_y_over_q_2m) j.value(*e.max_y_over_q_2m);
      else j.null();
      j.end_object();
    }
    j.end_array().end_object();
  }
  j.end_object();
  return out.str();
}

}  // namespace railstab
