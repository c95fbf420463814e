// The integration driver: output times, root events (validity limits and
// wheel lift-off), progress, work limits and statistics, the same for every
// stepper.
#include <railstab/integrate/integrator.hpp>

#include <railstab/integrate/root_functions.hpp>
#include <railstab/integrate/stepper.hpp>
#include <railstab/model/wheel_forces.hpp>

#include <chrono>
#include <cmath>
#include <ctime>
#include <iomanip>
#include <optional>
#include <limits>
#include <sstream>

namespace railstab {

namespace {

std::unique_ptr<Stepper> make_stepper(const IntegrationOptions& o, const Eigen::VectorXd& x0,
                                      ModelCallbackData& data) {
  switch (o.kind) {
    case IntegratorKind::cvode_bdf:
    case IntegratorKind::cvode_adams: return make_cvode_stepper(o, x0, data);
    case IntegratorKind::arkode_erk: return make_erk_stepper(o, x0, data);
    case IntegratorKind::arkode_dirk:
    case IntegratorKind::arkode_imex: return make_ark_stepper(o, x0, data);
  }
  throw std::invalid_argument("unknown integrator kind");
}

ContactEvent contact_event(const RootFunctionSet& roots, int i, ContactEvent::Kind kind,
                           double t_s) {
  ContactEvent e;
  e.kind = kind;
  e.time_s = t_s;
  e.body = roots[i].body;
  e.side = roots[i].side;
  std::ostringstream text;
  text << roots.wheel_name(i);
  switch (kind) {
    case ContactEvent::Kind::lost: text << " lost contact at t = " << t_s << " s"; break;
    case ContactEvent::Kind::regained: text << " regained contact at t = " << t_s << " s"; break;
    case ContactEvent::Kind::out_of_contact_at_start:
      text << " lost contact at t = " << t_s << " s (out of contact in the initial state)";
      break;
  }
  e.description = text.str();
  return e;
}

std::string flange_message(const Model& model, const RootFunction& f, double t_s) {
  std::ostringstream msg;
  msg << model.bodies[size_t(f.body)].name << " lateral shift reached the flange clearance "
      << f.clearance_m << " m at t = " << t_s
      << " s: flange contact is outside the model's validity";
  return msg.str();
}

// A wheel at the edge of its contact table (root_functions.hpp): where it
// sits, and what it is doing, from its forces at that moment: a wheel on
// its flange with Y/Q beyond Nadal's limit, or lifted above a centred
// wheel's height by more than 1 mm, is climbing its rail.
std::string table_edge_message(const Model& model, const RootFunctionSet& roots, int i,
                               double speed_m_per_s, double t_s, const Eigen::VectorXd& x) {
  const RootFunction& f = roots[i];
  const RootFunctionSet::TablePosition p = roots.table_position(i, t_s, x);
  std::ostringstream msg;
  msg << std::setprecision(3);
  msg << roots.wheel_name(i) << " reached the edge of its contact table at t = " << t_s
      << " s: lateral shift " << 1e3 * p.lateral_m << " mm from the centred position (table +-"
      << 1e3 * p.half_range_m << " mm), roll " << 1e3 * p.roll_rad << " mrad (table +-"
      << 1e3 * p.roll_half_range_rad << " mrad), the wheel " << 1e3 * p.lift_m
      << " mm above a centred wheel";
  std::optional<WheelForces> wheel;
  std::string forces_error;
  try {
    for (const WheelForces& w : wheel_forces(model, speed_m_per_s, t_s, x))
      if (w.body == f.body && w.side == f.side) wheel = w;
  } catch (const std::exception& e) {
    forces_error = e.what();
  }
  bool climbing = p.lift_m > 1e-3;
  if (wheel) {
    msg << "; Y " << 1e-3 * wheel->Y_N << " kN, Q " << 1e-3 * wheel->Q_N << " kN";
    if (wheel->y_over_q) msg << ", Y/Q " << *wheel->y_over_q;
    if (wheel->nadal_limit) {
      msg << " (Nadal's limit " << *wheel->nadal_limit << ")";
      if (wheel->y_over_q && *wheel->y_over_q >= *wheel->nadal_limit) climbing = true;
    }
    if (wheel->Q_N <= 0.0) msg << ", the wheel in the air";
  } else if (forces_error.empty()) {
    msg << "; no contact force: the wheel in the air";  // (wheel_forces lists loaded wheels)
  } else {
    msg << "; its forces cannot be evaluated there (" << forces_error << ")";
  }
  msg << (climbing ? ": flange climbing, the wheelset is derailing"
                   : ": beyond the table's range (widen table_lateral_half_range_m or "
                     "table_roll_half_range_rad if the motion is physical)");
  return msg.str();
}

// Records the events of one root return; returns the stop message, if any.
std::string handle_roots(const Model& model, const RootFunctionSet& roots,
                         const std::vector<int>& directions, double t_s,
                         const IntegrationOptions& options, double speed_m_per_s,
                         const Eigen::VectorXd& x, Trajectory& traj) {
  std::string flange_stop, lift_off_stop;
  for (int i = 0; i < roots.size(); ++i) {
    if (directions[size_t(i)] == 0) continue;
    if (roots[i].kind == RootFunction::Kind::table_edge) {
      // Only reaching the edge stops; coming back from it is no event.
      if (directions[size_t(i)] < 0 && flange_stop.empty())
        flange_stop = table_edge_message(model, roots, i, speed_m_per_s, t_s, x);
      continue;
    }
    if (roots[i].kind == RootFunction::Kind::flange_clearance) {
      if (flange_stop.empty()) flange_stop = flange_message(model, roots[i], t_s);
      continue;
    }
    const bool lost = directions[size_t(i)] < 0;  // penetration falling through zero
    traj.events.push_back(contact_event(
        roots, i, lost ? ContactEvent::Kind::lost : ContactEvent::Kind::regained, t_s));
    if (lost && options.stop_on_lift_off && lift_off_stop.empty())
      lift_off_stop = traj.events.back().description;
  }
  return flange_stop.empty() ? lift_off_stop : flange_stop;
}

[[noreturn]] void report_failure(const IntegrationOptions& options, const StepOutcome& outcome,
                                 const ModelCallbackData& data, IntegrationStats work) {
  std::ostringstream msg;
  msg << "time integration (" << integrator_name(options.kind) << ") stopped at t = "
      << outcome.t_reached << " s: ";
  if (data.budget_exhausted) {
    msg << "gave up: CPU time budget of " << options.cpu_time_budget_s << " s exhausted";
    throw IntegrationGaveUp(msg.str(), outcome.t_reached, work);
  }
  msg << outcome.flag_name;
  if (!data.error.empty()) msg << "; cause: " << data.error;
  if (outcome.status == StepOutcome::Status::too_much_work) {
    msg << " (gave up after " << options.max_steps << " steps in one output interval)";
    throw IntegrationGaveUp(msg.str(), outcome.t_reached, work);
  }
  if (!data.sundials_message.empty()) msg << " (SUNDIALS " << data.sundials_message << ")";
  throw std::runtime_error(msg.str());
}

// The run length and output interval must be finite and give a bounded
// number of outputs; before this check, t_end = 1e20 overflowed the output
// count and the run silently ended after one interval.
void check_output_count(const IntegrationOptions& o) {
  const double span = o.t_end_s - o.t_start_s;
  std::ostringstream msg;
  msg << "time integration from t = " << o.t_start_s << " s to t_end_s = " << o.t_end_s
      << " s every output_interval_s = " << o.output_interval_s << " s: ";
  if (!std::isfinite(o.t_start_s) || !std::isfinite(o.t_end_s) || !(span >= 0.0)) {
    msg << "expected a finite end time not before the start";
    throw std::invalid_argument(msg.str());
  }
  if (!std::isfinite(o.output_interval_s) || !(o.output_interval_s > 0.0)) {
    msg << "expected a finite, positive output interval";
    throw std::invalid_argument(msg.str());
  }
  const double outputs = std::ceil(span / o.output_interval_s - 1e-9);
  if (!(outputs <= o.max_outputs)) {
    msg << "would keep " << outputs << " output states; at most " << o.max_outputs
        << " (shorten t_end_s or lengthen output_interval_s)";
    throw std::invalid_argument(msg.str());
  }
}

}  // namespace

IntegrationOptions integration_options_for(const SimulationSpec& simulation) {
  IntegrationOptions o;
  o.kind = simulation.integrator;
  o.order = simulation.integrator_order;
  o.t_end_s = simulation.t_end_s;
  o.output_interval_s = simulation.output_interval_s;
  o.relative_tolerance = simulation.relative_tolerance;
  o.absolute_tolerance = simulation.absolute_tolerance;
  return o;
}

bool uses_sparse_newton(NewtonMatrixKind kind, int n_states) {
  if (kind != NewtonMatrixKind::automatic) return kind == NewtonMatrixKind::sparse;
  return n_states >= kSparseNewtonFromStates;
}

Trajectory integrate(const Model& model, double speed_m_per_s, const Eigen::VectorXd& x0,
                     const IntegrationOptions& options) {
  if (!order_available(options.kind, options.order))
    throw std::invalid_argument("time integration: " + integrator_name(options.kind) +
                                " has no order " + std::to_string(options.order) + " (offers " +
                                available_orders_text(options.kind) + ")");
  check_output_count(options);
  const auto wall_start = std::chrono::steady_clock::now();
  const std::clock_t cpu_start = std::clock();
  const RootFunctionSet roots(model, speed_m_per_s);
  ModelCallbackData data(model, speed_m_per_s, roots, options.cpu_time_budget_s);
  const bool implicit = options.kind != IntegratorKind::arkode_erk;
  if (implicit && uses_sparse_newton(options.newton_matrix, model.state_size()))
    data.sparse_layout = sparse_jacobian_layout(data.jacobian_plan.pattern);

  Trajectory traj;
  traj.times_s.push_back(options.t_start_s);
  traj.states.push_back(x0);
  auto work_so_far = [&](IntegrationStats stats) {
    stats.rhs_evaluations = data.model_evaluations;
    stats.wall_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
    stats.cpu_seconds = double(std::clock() - cpu_start) / CLOCKS_PER_SEC;
    return stats;
  };

  // Root finding sees sign changes only, so a wheel already in the air at
  // the start is reported here (e.g. the thesis cases' 1 mm initial lateral
  // offset lifts a knife-edge wheel by ~70 um).
  std::vector<double> g0(size_t(roots.size()));
  if (!g0.empty()) roots.evaluate(options.t_start_s, x0, g0.data());
  for (int i = 0; i < roots.size(); ++i) {
    if (roots[i].kind != RootFunction::Kind::wheel_contact || g0[size_t(i)] > 0.0) continue;
    traj.events.push_back(contact_event(roots, i, ContactEvent::Kind::out_of_contact_at_start,
                                        options.t_start_s));
    if (options.stop_on_lift_off && traj.stopped_early.empty())
      traj.stopped_early = traj.events.back().description;
  }
  if (!traj.stopped_early.empty()) {
    traj.stats = work_so_far({});
    return traj;
  }

  const std::unique_ptr<Stepper> stepper = make_stepper(options, x0, data);
  const double span = options.t_end_s - options.t_start_s;
  const long n_out = std::max(1L, long(std::ceil(span / options.output_interval_s - 1e-9)));
  auto last_report = wall_start;
  double last_root_t = -std::numeric_limits<double>::infinity();
  int stalled_roots = 0;
  for (long i = 1; i <= n_out && traj.stopped_early.empty(); ++i) {
    const double t_out = std::min(options.t_end_s, options.t_start_s + i * options.output_interval_s);
    for (;;) {
      const StepOutcome outcome = stepper->advance(t_out);
      if (outcome.status == StepOutcome::Status::failed ||
          outcome.status == StepOutcome::Status::too_much_work)
        report_failure(options, outcome, data, work_so_far(stepper->statistics()));
      if (outcome.status == StepOutcome::Status::root) {
        // Guard against a root finder that stops without advancing (each
        // root return must move on; a bouncing wheel gives a few per period).
        stalled_roots = outcome.t_reached > last_root_t ? 0 : stalled_roots + 1;
        last_root_t = outcome.t_reached;
        if (stalled_roots > 100)
          throw std::runtime_error("time integration (" + integrator_name(options.kind) +
                                   "): root finding stalled at t = " +
                                   std::to_string(outcome.t_reached) + " s");
        traj.stopped_early =
            handle_roots(model, roots, stepper->root_directions(), outcome.t_reached, options,
                         speed_m_per_s, stepper->state(), traj);
        if (traj.stopped_early.empty()) continue;  // an event only: go on to t_out
      }
      traj.times_s.push_back(outcome.t_reached);
      traj.states.push_back(stepper->state());
      if (options.stop_at_output && traj.stopped_early.empty())
        traj.stopped_early = options.stop_at_output(traj.times_s.back(), traj.states.back());
      break;
    }
    const auto now = std::chrono::steady_clock::now();
    if (options.progress && now - last_report > std::chrono::seconds(1)) {
      options.progress(traj.times_s.back());
      last_report = now;
    }
  }
  traj.stats = work_so_far(stepper->statistics());
  return traj;
}

}  // namespace railstab
