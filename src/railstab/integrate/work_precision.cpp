#include <railstab/integrate/work_precision.hpp>

#include <cmath>
#include <cstdio>
#include <ctime>
#include <limits>

namespace railstab {

std::string IntegratorVariant::label() const {
  return integrator_name(kind) + (order > 0 ? "_q" + std::to_string(order) : "");
}

std::vector<IntegratorVariant> default_variants() {
  return {{IntegratorKind::cvode_bdf, 0},   {IntegratorKind::cvode_bdf, 2},
          {IntegratorKind::cvode_adams, 0}, {IntegratorKind::arkode_erk, 0},
          {IntegratorKind::arkode_dirk, 0}, {IntegratorKind::arkode_imex, 0}};
}

IntegratorVariant parse_integrator_variant(const std::string& label) {
  const size_t q = label.rfind("_q");
  if (q != std::string::npos && q + 2 < label.size() && label.size() - q <= 4 &&
      label.find_first_not_of("0123456789", q + 2) == std::string::npos) {
    const IntegratorKind kind = parse_integrator_kind(label.substr(0, q));
    const int order = std::stoi(label.substr(q + 2));  // at most two digits
    if (order == 0 || !order_available(kind, order))
      throw std::invalid_argument("integrator '" + label + "': " + integrator_name(kind) +
                                  " offers orders " + available_orders_text(kind));
    return {kind, order};
  }
  return {parse_integrator_kind(label), 0};
}

namespace {

// Position states compared: every free coordinate but a wheelset's spin
// (or only lateral shifts and yaw angles).
std::vector<int> compared_states(const Model& model, ErrorCoordinates which) {
  std::vector<int> states;
  for (int k = 0; k < model.n_coordinates; ++k) {
    const auto [b, c] = model.coordinate_of_state[size_t(k)];
    if (model.bodies[size_t(b)].wheelset() && c == int(CoordinateIndex::pitch)) continue;
    if (which == ErrorCoordinates::lateral && c != int(CoordinateIndex::y) &&
        c != int(CoordinateIndex::yaw))
      continue;
    states.push_back(k);
  }
  return states;
}

IntegrationOptions options_for(const WorkPrecisionSettings& s, IntegratorKind kind, int order,
                               double rtol, double atol) {
  IntegrationOptions o;
  o.kind = kind;
  o.order = order;
  o.t_end_s = s.t_end_s;
  o.output_interval_s = s.output_interval_s;
  o.relative_tolerance = rtol;
  o.absolute_tolerance = atol;
  return o;
}

std::string format_run(const WorkPrecisionRun& r) {
  char line[320];
  std::snprintf(line, sizeof line,
                "%-13s rtol %.0e: error %-9.3g (lateral %-9.3g) CPU %7.3f s, %7ld steps, %8ld rhs, "
                "%5ld Jacobians  %s",
                r.label.c_str(), r.rtol, r.error, r.lateral_error, r.cpu_seconds, r.stats.steps,
                r.stats.rhs_evaluations, r.stats.jacobian_evaluations, r.status.c_str());
  return line;
}

}  // namespace

double trajectory_position_error(const Model& model, const Trajectory& run, const Trajectory& ref,
                                 std::string* where, ErrorCoordinates which, int* compared) {
  const std::vector<int> states = compared_states(model, which);
  double worst = 0.0;
  int worst_state = -1, matched = 0;
  // Rows at the same time only: both runs share the output grid, but a run
  // that stops at a root ends at its own time (and contact events add no
  // rows), so matching by index could compare different instants.
  size_t j = 0;
  for (size_t i = 0; i < run.times_s.size(); ++i) {
    const double t = run.times_s[i];
    const double slack = 1e-12 * (1.0 + std::abs(t));
    while (j < ref.times_s.size() && ref.times_s[j] < t - slack) ++j;
    if (j == ref.times_s.size()) break;
    if (std::abs(ref.times_s[j] - t) > slack) continue;
    ++matched;
    for (int k : states) {
      const double e = std::abs(run.states[i](k) - ref.states[j](k));
      if (std::isnan(e)) {
        if (where) *where = model.state_name(k);
        if (compared) *compared = matched;
        return std::numeric_limits<double>::quiet_NaN();
      }
      if (e > worst) {
        worst = e;
        worst_state = k;
      }
    }
  }
  if (where) *where = worst_state >= 0 ? model.state_name(worst_state) : "";
  if (compared) *compared = matched;
  return worst;
}

ReferenceSolution compute_reference(const Model& model, double speed_m_per_s,
    const Eigen::VectorXd& x0,
                                    const WorkPrecisionSettings& s) {
  ReferenceSolution ref;
  ref.rtol = s.reference_rtol;
  ref.atol = s.reference_rtol * s.absolute_tolerance_scale;
  ref.check_rtol = s.reference_check_rtol;
  ref.kind = s.reference_kind;
  ref.check_kind = s.reference_check_kind;
  ref.trajectory = integrate(model, speed_m_per_s, x0, options_for(s, ref.kind, 0, ref.rtol, ref.atol));
  ref.cpu_seconds = ref.trajectory.stats.cpu_seconds;
  const Trajectory check =
      integrate(model, speed_m_per_s, x0, options_for(s, ref.check_kind, 0, ref.check_rtol,
                                       ref.check_rtol * s.absolute_tolerance_scale));
  ref.check_cpu_seconds = check.stats.cpu_seconds;
  ref.check_difference = trajectory_position_error(model, check, ref.trajectory);
  return ref;
}

WorkPrecisionRun run_against_reference(const Model& model, double speed_m_per_s,
    const Eigen::VectorXd& x0,
                                       const WorkPrecisionSettings& s,
                                       const IntegratorVariant& variant, double rtol,
                                       const ReferenceSolution& reference) {
  WorkPrecisionRun r;
  r.label = variant.label();
  r.rtol = rtol;
  r.atol = rtol * s.absolute_tolerance_scale;
  r.error = r.lateral_error = std::numeric_limits<double>::quiet_NaN();
  IntegrationOptions o = options_for(s, variant.kind, variant.order, r.rtol, r.atol);
  o.cpu_time_budget_s = s.cpu_budget_per_run_s;
  const std::clock_t start = std::clock();
  try {
    const Trajectory traj = integrate(model, speed_m_per_s, x0, o);
    r.stats = traj.stats;
    r.error = trajectory_position_error(model, traj, reference.trajectory, &r.error_coordinate);
    r.lateral_error = trajectory_position_error(model, traj, reference.trajectory, nullptr,
                                                ErrorCoordinates::lateral);
    r.status = "ok";
    if (traj.stopped_early != reference.trajectory.stopped_early)
      r.status = "stopped early: " + (traj.stopped_early.empty() ? std::string("(reference did)")
                                                                : traj.stopped_early);
  } catch (const IntegrationGaveUp& e) {
    r.stats = e.stats;
    char status[80];
    std::snprintf(status, sizeof status, "gave up (at t = %.3g s)", e.t_reached_s);
    r.status = status;
  } catch (const std::exception& e) {
    r.status = std::string("failed: ") + e.what();
  }
  r.cpu_seconds = double(std::clock() - start) / CLOCKS_PER_SEC;
  r.wall_seconds = r.stats.wall_seconds;
  return r;
}

WorkPrecisionResult run_work_precision(const Model& model, double speed_m_per_s,
    const Eigen::VectorXd& x0,
                                       const WorkPrecisionSettings& s,
                                       const std::function<void(const std::string&)>& progress) {
  WorkPrecisionResult result;
  if (progress) {
    char line[120];
    std::snprintf(line, sizeof line, "reference: %s at rtol %.0e, check %s at rtol %.0e...",
                  integrator_name(s.reference_kind).c_str(), s.reference_rtol,
                  integrator_name(s.reference_check_kind).c_str(), s.reference_check_rtol);
    progress(line);
  }
  result.reference = compute_reference(model, speed_m_per_s, x0, s);
  if (progress) {
    char line[200];
    std::snprintf(line, sizeof line,
                  "reference: CPU %.2f s; the check differs from it by %.3g (error bound)",
                  result.reference.cpu_seconds, result.reference.check_difference);
    progress(line);
  }
  for (const IntegratorVariant& v : s.variants) {
    bool gave_up = false;
    for (double rtol : s.relative_tolerances) {
      WorkPrecisionRun r;
      if (gave_up) {
        r.label = v.label();
        r.rtol = rtol;
        r.atol = rtol * s.absolute_tolerance_scale;
        r.error = r.lateral_error = std::numeric_limits<double>::quiet_NaN();
        r.status = "skipped";  // a looser tolerance already gave up
      } else {
        r = run_against_reference(model, speed_m_per_s, x0, s, v, rtol, result.reference);
        gave_up = r.status.starts_with("gave up");
      }
      if (progress) progress(format_run(r));
      result.runs.push_back(r);
    }
  }
  return result;
}

}  // namespace railstab
