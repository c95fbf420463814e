#include <railstab/curving/steady_curving.hpp>

#include <railstab/core/coordinates.hpp>
#include <railstab/equilibrium/speed_continuation.hpp>
#include <railstab/contact/model_contact.hpp>
#include <railstab/integrate/root_functions.hpp>
#include <railstab/linear/jacobian.hpp>

#include <railstab/linalg/dense_decompositions.hpp>
#include <railstab/ride/wheelset_forces.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace railstab {

namespace {

// The cant on the curve's outer rail; on a straight no speed balances any
// cant, so all of it counts as excess (h_outer = |h|, h_d = -|h|), as the
// reports (report/run_conditions.hpp) and the plausibility check say.
double outer_cant_m(double curvature_per_m, double cant_m) {
  if (curvature_per_m == 0.0) return std::abs(cant_m);
  return curvature_per_m > 0.0 ? cant_m : -cant_m;
}

std::string fixed(double value, int digits) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << value;
  return s.str();
}

}  // namespace

double cant_deficiency_m(const CurvingCondition& c, double D, double g) {
  const double V = c.speed_m_per_s;
  return D * V * V * std::abs(c.curvature_per_m) / g - outer_cant_m(c.curvature_per_m, c.cant_m);
}

double speed_for_cant_deficiency(double curvature_per_m, double cant_m, double h_d, double D,
                                 double g) {
  if (curvature_per_m == 0.0)
    throw std::invalid_argument("a cant deficiency needs a curve (the radius is infinite)");
  const double balance = h_d + outer_cant_m(curvature_per_m, cant_m);
  if (!(balance > 0.0))
    throw std::invalid_argument("a cant deficiency of " + fixed(h_d * 1e3, 1) +
                                " mm with " + fixed(cant_m * 1e3, 1) +
                                " mm cant needs a speed of zero or less (the cant excess at rest is " +
                                fixed(outer_cant_m(curvature_per_m, cant_m) * 1e3, 1) + " mm)");
  return std::sqrt(g * balance / (D * std::abs(curvature_per_m)));
}

std::string describe_condition(const CurvingCondition& c, double D, double g) {
  std::ostringstream s;
  s << "V = " << fixed(c.speed_m_per_s, 3) << " m/s, cant deficiency "
    << fixed(cant_deficiency_m(c, D, g) * 1e3, 1) << " mm, ";
  if (c.curvature_per_m == 0.0)
    s << "straight";
  else
    s << "R = " << fixed(1.0 / std::abs(c.curvature_per_m), 1) << " m ("
      << (c.curvature_per_m > 0.0 ? "left" : "right") << ")";
  s << ", cant " << fixed(c.cant_m * 1e3, 1) << " mm";
  return s.str();
}

CurvingCondition condition_at_reference(const Model& model, double V) {
  const TrackGeometryPoint g = model.track.geometry_at(model.reference_arc_length_m);
  return {g.curvature_per_m, g.cant_m, V};
}

Model uniform_arc_model(const Model& model, double curvature_per_m, double cant_m) {
  const TrackSpec& scene = model.track.spec();
  TrackSpec arc;
  arc.start_x_m = scene.start_x_m;
  arc.start_y_m = scene.start_y_m;
  arc.start_z_m = scene.start_z_m;
  arc.start_heading_rad = scene.start_heading_rad;
  arc.start_curvature_per_m = curvature_per_m;
  arc.start_cant_m = cant_m;
  arc.rail_contact_distance_m = scene.rail_contact_distance_m;
  // An arc keeps its start curvature; a zero curvature is a tangent.
  arc.segments.push_back({curvature_per_m == 0.0 ? TrackSegmentKind::tangent : TrackSegmentKind::arc,
                          model.track.length_m(), curvature_per_m, cant_m});
  Model m = model;
  m.track = Track(arc);
  return m;
}

std::string physical_limit(const Model& model, double V, const Eigen::VectorXd& x) {
  const std::vector<WheelForces> wheels = wheel_forces(model, V, 0.0, x);
  const RootFunctionSet roots(model, V);
  std::ostringstream s;
  s << std::setprecision(3);
  auto forces_of = [&](const WheelForces& w) {
    s << " (Y " << w.Y_N * 1e-3 << " kN, Q " << w.Q_N * 1e-3 << " kN";
    for (int i = 0; i < roots.size(); ++i)
      if (roots[i].kind == RootFunction::Kind::table_edge && roots[i].body == w.body &&
          roots[i].side == w.side) {
        const RootFunctionSet::TablePosition p = roots.table_position(i, 0.0, x);
        s << ", lift " << p.lift_m * 1e3 << " mm, lateral shift " << p.lateral_m * 1e3
          << " mm of the table's +-" << p.half_range_m * 1e3 << " mm";
      }
    s << ")";
  };
  // Nadal: Y/Q at or beyond the limit on the flange. A wheel on its tread
  // cannot climb (Nadal's formula is the balance on the flange's slope).
  for (const WheelForces& w : wheels)
    if (w.y_over_q && w.nadal_limit && *w.y_over_q >= *w.nadal_limit &&
        w.max_contact_angle_rad >= kFlangeContactAngle_rad) {
      s << w.name(model) << " Y/Q " << *w.y_over_q << " reaches Nadal's limit " << *w.nadal_limit;
      forces_of(w);
      s << ": flange climbing";
      return s.str();
    }
  // A flangeless contact (cone, linear conicity) past its flange clearance:
  // the model has no flange there, so no steady state of it is one of the
  // vehicle (the time domain stops there too).
  {
    Eigen::MatrixXd q6, qd6;
    model.full_coordinates(0.0, V, x, q6, qd6);
    for (size_t b = 0; b < model.bodies.size(); ++b) {
      const WheelsetKind* w = model.bodies[b].wheelset();
      if (!w) continue;
      const ContactSpec& spec = model.contacts[size_t(w->contact)].spec;
      if (uses_contact_table(spec.geometry)) continue;
      const double shift = q6(int(CoordinateIndex::y), int(b)) - model.bodies[b].nominal_q(int(CoordinateIndex::y));
      const double clearance = lateral_validity_limit_m(spec);
      if (std::abs(shift) > clearance) {
        s << model.bodies[b].name << " is " << shift * 1e3 << " mm off centre, beyond the flange clearance "
          << clearance * 1e3 << " mm of its flangeless contact '" << spec.name
          << "': flange contact is outside the model's validity";
        return s.str();
      }
    }
  }
  // The table: a wheel lifted (climbing) or at the edge of its table.
  for (int i = 0; i < roots.size(); ++i) {
    if (roots[i].kind != RootFunction::Kind::table_edge) continue;
    const RootFunctionSet::TablePosition p = roots.table_position(i, 0.0, x);
    const double used = std::max(std::abs(p.lateral_m) / p.half_range_m,
                                 std::abs(p.roll_rad) / p.roll_half_range_rad);
    const bool lifted = p.lift_m > kClimbingLift_m;
    if (!lifted && used < kTableEdgeFraction) continue;
    s << roots.wheel_name(i)
      << (lifted ? " is lifted " + fixed(p.lift_m * 1e3, 2) + " mm above a centred wheel"
                 : " reached the edge of its contact table");
    for (const WheelForces& w : wheels)
      if (w.body == roots[i].body && w.side == roots[i].side) {
        if (w.y_over_q) s << ", Y/Q " << *w.y_over_q;
        if (w.nadal_limit) s << " (Nadal's limit " << *w.nadal_limit << ")";
        forces_of(w);
      }
    s << (lifted ? ": flange climbing" : ": the contact leaves the table");
    return s.str();
  }
  return "";
}

std::string SteadyStateStability::describe() const {
  if (stable()) return "stable";
  std::ostringstream s;
  s << std::setprecision(3) << "unstable: ";
  if (divergent > 0) s << divergent << " divergent mode(s)";
  if (divergent > 0 && oscillatory > 0) s << " and ";
  if (oscillatory > 0) s << oscillatory << " growing oscillation(s)";
  s << " (largest real part " << largest_real_part << " 1/s)";
  return s.str();
}

SteadyStateStability steady_state_stability(const Model& model, double V, const Eigen::VectorXd& x,
                                            double max_frequency_hz) {
  std::vector<int> states;
  for (int k = 0; k < model.state_size(); ++k)
    if (!is_spin_angle(model, k)) states.push_back(k);
  const RhsJacobianPlan plan = plan_rhs_jacobian(model, states, states);
  const Eigen::EigenSolver<Eigen::MatrixXd> eigen(rhs_jacobian_ad(model, plan, V, 0.0, x), false);
  SteadyStateStability out;
  out.largest_real_part = -INFINITY;
  const double omega_max = 2.0 * M_PI * max_frequency_hz;
  for (const std::complex<double>& l : eigen.eigenvalues()) {
    if (std::abs(l.imag()) > omega_max) continue;
    out.largest_real_part = std::max(out.largest_real_part, l.real());
    if (l.real() <= 1e-6) continue;
    if (std::abs(l.imag()) < 1e-9 * std::max(1.0, std::abs(l.real())))
      ++out.divergent;
    else if (l.imag() > 0.0)
      ++out.oscillatory;  // one of each conjugate pair
  }
  return out;
}

namespace {

// "no steady state physically", or, where the limit is the model's own (a
// flangeless contact past its clearance), "no steady state within the
// model's validity".
std::string no_steady_state(const std::string& reason) {
  return reason.find("outside the model's validity") != std::string::npos
             ? "no steady state within the model's validity"
             : "no steady state physically";
}

// A path between two curving conditions on uniform arcs: speed, curvature
// and cant linear in lambda. The model is rebuilt per lambda (only its
// track changes).
class CurvingPath : public SteadyStatePath {
 public:
  CurvingPath(const Model& scene_model, CurvingCondition from, CurvingCondition to)
      : scene_(scene_model), from_(from), to_(to), model_(uniform_arc_model(scene_model, from.curvature_per_m, from.cant_m)) {}
  const Model& model_at(double lambda) override {
    const CurvingCondition c = at(lambda);
    if (c.curvature_per_m != built_curvature_ || c.cant_m != built_cant_) {
      model_.track = uniform_arc_model_track(c);
      built_curvature_ = c.curvature_per_m;
      built_cant_ = c.cant_m;
    }
    return model_;
  }
  double speed_at(double lambda) const override { return at(lambda).speed_m_per_s; }
  double length_scale() const override {
    // 1 per m/s of speed and per cm of cant deficiency (of the change in
    // V^2 / R, or in h).
    const double D = scene_.track.spec().rail_contact_distance_m, g = scene_.gravity_m_per_s2;
    return std::max(1.0, std::abs(to_.speed_m_per_s - from_.speed_m_per_s) +
                             100.0 * std::abs(cant_deficiency_m(to_, D, g) -
                                              cant_deficiency_m(from_, D, g)));
  }
  std::string describe(double lambda) const override {
    return describe_condition(at(lambda), scene_.track.spec().rail_contact_distance_m,
                              scene_.gravity_m_per_s2);
  }
  CurvingCondition at(double lambda) const {
    return {from_.curvature_per_m + lambda * (to_.curvature_per_m - from_.curvature_per_m),
            from_.cant_m + lambda * (to_.cant_m - from_.cant_m),
            from_.speed_m_per_s + lambda * (to_.speed_m_per_s - from_.speed_m_per_s)};
  }

 private:
  Track uniform_arc_model_track(const CurvingCondition& c) const {
    return uniform_arc_model(scene_, c.curvature_per_m, c.cant_m).track;
  }
  const Model& scene_;
  CurvingCondition from_, to_;
  Model model_;
  double built_curvature_ = std::nan(""), built_cant_ = std::nan("");
};

// The condition of a scene-track speed path at lambda.
class SceneSpeedPath : public SpeedPath {
 public:
  SceneSpeedPath(const Model& model, double from, double to) : SpeedPath(model, from, to), model_(model) {}
  std::string describe(double lambda) const override {
    return describe_condition(condition_at_reference(model_, speed_at(lambda)),
                              model_.track.spec().rail_contact_distance_m, model_.gravity_m_per_s2);
  }

 private:
  const Model& model_;
};

EquilibriumOptions newton_only(const SteadyCurvingOptions& options) {
  EquilibriumOptions eo;
  eo.acceleration_tolerance = options.acceleration_tolerance;
  eo.pseudo_transient_fallback = false;
  return eo;
}

// The arclength continuation along `path` from `start_state` at lambda = 0
// (a state whose condition start_condition describes), stopping at a
// physical limit.
struct PathOutcome {
  std::optional<SteadyCurvingState> reached;
  std::optional<SteadyCurvingState> last;  // last converged point (reached or not)
  std::string why;                          // not reached: why
  bool physical = false;
};

template <class Condition>
PathOutcome follow(SteadyStatePath& path, const Eigen::VectorXd& start_state, Condition condition_at,
                   const std::string& from_text, const std::string& to_text,
                   const SteadyCurvingOptions& options, double D, double g) {
  ArclengthOptions ao = options.continuation;
  ao.acceleration_tolerance = options.acceleration_tolerance;
  ao.stop = [&](double lambda, const Eigen::VectorXd& x) {
    return physical_limit(path.model_at(lambda), path.speed_at(lambda), x);
  };
  const ArclengthResult r = continue_by_arclength(path, start_state, ao);
  PathOutcome out;
  auto state_at = [&](double lambda, const Eigen::VectorXd& x, EquilibriumResult eq) {
    SteadyCurvingState s;
    s.condition = condition_at(lambda);
    s.cant_deficiency_m = cant_deficiency_m(s.condition, D, g);
    eq.state = x;
    s.equilibrium = std::move(eq);
    s.continuation_steps = r.steps;
    s.method = "arclength continuation (" + std::to_string(r.steps) + " steps, " +
               std::to_string(r.fold_points.size()) + " fold(s)) from " + from_text;
    return s;
  };
  if (r.reached) {
    out.reached = state_at(1.0, r.end.state, r.end);
    out.last = out.reached;
    return out;
  }
  EquilibriumResult eq;
  if (!r.stop_reason.empty()) {
    out.last = state_at(r.last_lambda, r.last_state, eq);
    out.physical = true;
    out.why = no_steady_state(r.stop_reason) + " at " + to_text + ": followed from " + from_text +
              ", the steady state reaches the limit at " + path.describe(r.last_lambda) + ": " +
              r.stop_reason;
  } else {
    out.last = state_at(r.furthest_lambda, r.furthest_state, eq);
    out.why = "the continuation from " + from_text + " stopped (" + r.failure +
              "); the last converged point towards the target: " +
              path.describe(r.furthest_lambda);
    // A branch that turns back at a fold with a wheel on its flange root has
    // no steady state beyond the fold: said as the solver's finding.
  }
  return out;
}

}  // namespace

SteadyCurvingState solve_steady_curving(const Model& scene_model, const CurvingCondition& target,
                                        const std::optional<SteadyCurvingState>& from,
                                        const SteadyCurvingOptions& options) {
  const double D = scene_model.track.spec().rail_contact_distance_m;
  const double g = scene_model.gravity_m_per_s2;
  const Model target_model = uniform_arc_model(scene_model, target.curvature_per_m, target.cant_m);
  const double V = target.speed_m_per_s;
  SteadyCurvingState out;
  out.condition = target;
  out.cant_deficiency_m = cant_deficiency_m(target, D, g);
  const std::string target_text = describe_condition(target, D, g);

  auto finish = [&](SteadyCurvingState s) {
    // A steady state past the physical limit is none.
    const std::string limit = physical_limit(target_model, V, s.equilibrium.state);
    if (!limit.empty())
      throw CurvingError(no_steady_state(limit) + " at " + target_text + ": " + limit, true, s);
    return s;
  };

  // 1. Newton from the nearest known solution (or the nominal position).
  const Eigen::VectorXd guess =
      from ? rescaled_to_speed(target_model, from->equilibrium.state, from->condition.speed_m_per_s, V)
           : lowered_nominal_state(target_model, V);
  try {
    out.equilibrium = solve_equilibrium(target_model, V, guess, newton_only(options));
    out.method = "Newton";
    return finish(out);
  } catch (const EquilibriumError&) {
  }

  // 2. With a known solution: continuation from it to the target.
  if (from) {
    CurvingPath path(scene_model, from->condition, target);
    const std::string from_text = describe_condition(from->condition, D, g);
    PathOutcome o = follow(path, from->equilibrium.state, [&](double l) { return path.at(l); },
                           from_text, target_text, options, D, g);
    if (o.reached) return finish(*o.reached);
    if (o.physical) throw CurvingError(o.why, true, o.last);
    throw CurvingError("no steady state found at " + target_text + ": Newton's method from " +
                           from_text + " does not converge; " + o.why,
                       false, o.last);
  }
  // 3. Without one: a start that Newton reaches from the nominal position
  // (the target arc at the start speed, in cant excess; else the straight
  // at that speed), then a march to the target in steps of about 2.5 m/s
  // or 25 mm of cant deficiency (the sweeps' steps), each from the previous
  // point: Newton where it converges, continuation where it does not. A
  // continuation over the whole way at once would cross every contact
  // transition with its plain Newton corrector; the march crosses them
  // with the equilibrium solver's line search.
  const double V0 = std::min(options.start_speed_m_per_s, V);
  std::string failures;
  std::optional<SteadyCurvingState> start;
  for (const CurvingCondition c : {CurvingCondition{target.curvature_per_m, target.cant_m, V0},
                                   CurvingCondition{0.0, 0.0, V0}}) {
    const Model m = uniform_arc_model(scene_model, c.curvature_per_m, c.cant_m);
    try {
      SteadyCurvingState s;
      s.condition = c;
      s.cant_deficiency_m = cant_deficiency_m(c, D, g);
      s.equilibrium = solve_equilibrium(m, V0, lowered_nominal_state(m, V0));
      s.method = "Newton";
      start = std::move(s);
      break;
    } catch (const EquilibriumError& e) {
      failures += std::string(failures.empty() ? "" : "; ") + "no start at " +
                  describe_condition(c, D, g) + " (" + e.what() + ")";
    }
  }
  if (!start)
    throw CurvingError("no steady state found at " + target_text +
                           ": Newton's method from the nominal position does not converge, and " +
                           failures,
                       false, std::nullopt);
  const CurvingPath whole(scene_model, start->condition, target);
  const int n = std::max(1, int(std::ceil(whole.length_scale() / options.march_step)));
  std::optional<SteadyCurvingState> previous = start;
  int steps = 0;
  for (int i = 1; i <= n; ++i) {
    const CurvingCondition c = i == n ? target : whole.at(double(i) / n);
    SteadyCurvingState s = solve_steady_curving(scene_model, c, previous, options);
    steps += s.continuation_steps;
    previous = std::move(s);
  }
  previous->method = "march from " + describe_condition(start->condition, D, g) + " in " +
                     std::to_string(n) + " steps (" + std::to_string(steps) +
                     " continuation steps)";
  previous->continuation_steps = steps;
  return *previous;
}

SteadyCurvingState continue_scene_steady_state(const Model& model, double from_speed_m_per_s,
                                               const Eigen::VectorXd& from_state, double V,
                                               const SteadyCurvingOptions& options) {
  const double D = model.track.spec().rail_contact_distance_m, g = model.gravity_m_per_s2;
  // A march in speed in steps of options.march_step m/s: Newton from the
  // previous point, else the continuation from it.
  double v = from_speed_m_per_s;
  Eigen::VectorXd x = from_state;
  int steps = 0;
  std::optional<SteadyCurvingState> reached;
  while (!reached || v != V) {
    const double next = std::abs(V - v) <= options.march_step ? V : v + std::copysign(options.march_step, V - v);
    const CurvingCondition c = condition_at_reference(model, next);
    SteadyCurvingState s;
    s.condition = c;
    s.cant_deficiency_m = cant_deficiency_m(c, D, g);
    try {
      s.equilibrium = solve_equilibrium(model, next, rescaled_to_speed(model, x, v, next), newton_only(options));
      s.method = "Newton";
    } catch (const EquilibriumError&) {
      SceneSpeedPath path(model, v, next);
      const std::string from_text = describe_condition(condition_at_reference(model, v), D, g);
      PathOutcome o = follow(path, x,
                             [&](double l) { return condition_at_reference(model, path.speed_at(l)); },
                             from_text, describe_condition(condition_at_reference(model, V), D, g),
                             options, D, g);
      if (!o.reached) throw CurvingError(o.why, o.physical, o.last);
      s = *o.reached;
      steps += s.continuation_steps;
    }
    const std::string limit = physical_limit(model, next, s.equilibrium.state);
    if (!limit.empty())
      throw CurvingError(no_steady_state(limit) + " at " +
                             describe_condition(condition_at_reference(model, V), D, g) +
                             ": followed up in speed, the steady state reaches the limit at " +
                             describe_condition(c, D, g) + ": " + limit,
                         true, s);
    v = next;
    x = s.equilibrium.state;
    reached = std::move(s);
  }
  reached->continuation_steps = steps;
  return *reached;
}

CurvingPoint curving_point(const Model& scene_model, const SteadyCurvingState& s,
                           double prudhomme_factor) {
  const Model model = uniform_arc_model(scene_model, s.condition.curvature_per_m, s.condition.cant_m);
  const double V = s.condition.speed_m_per_s;
  const Eigen::VectorXd& x = s.equilibrium.state;
  CurvingPoint p;
  p.state = s;
  p.stability = steady_state_stability(model, V, x);
  const double D = model.track.spec().rail_contact_distance_m, g = model.gravity_m_per_s2;
  const double sin_phi = std::clamp(s.condition.cant_m / D, -1.0, 1.0);
  // a_y = V^2 kappa cos(phi) - g sin(phi), along the track plane's y (left).
  p.lateral_acceleration_m_per_s2 =
      V * V * s.condition.curvature_per_m * std::sqrt(1.0 - sin_phi * sin_phi) - g * sin_phi;
  double mass = 0.0;
  for (const Body& b : model.bodies) mass += b.mass_kg;
  p.mass_times_lateral_acceleration_N = mass * p.lateral_acceleration_m_per_s2;
  const std::vector<WheelsetForces> forces =
      wheelset_forces(model, V, 0.0, x, static_wheel_loads(model, V), prudhomme_factor);
  Eigen::MatrixXd q6, qd6;
  model.full_coordinates(0.0, V, x, q6, qd6);
  std::vector<WheelForces> all;
  for (const WheelsetForces& f : forces) {
    CurvingWheelset w;
    w.body = f.body;
    const Body& body = model.bodies[size_t(f.body)];
    w.lateral_shift_m = q6(int(CoordinateIndex::y), f.body) - body.nominal_q(int(CoordinateIndex::y));
    w.angle_of_attack_rad = f.angle_of_attack_rad;
    w.roll_rad = q6(int(CoordinateIndex::roll), f.body);
    w.sum_y_N = f.sum_y_N;
    w.prudhomme_limit_N = f.prudhomme_limit_N;
    w.left = f.left;
    w.right = f.right;
    w.left_flange = f.left.Q_N > 0.0 && f.left.max_contact_angle_rad >= kFlangeContactAngle_rad;
    w.right_flange = f.right.Q_N > 0.0 && f.right.max_contact_angle_rad >= kFlangeContactAngle_rad;
    // The rails' force on the wheelset along +y: -(Y_left - Y_right).
    p.rail_lateral_force_N -= f.sum_y_N;
    all.push_back(f.left);
    all.push_back(f.right);
    p.wheelsets.push_back(w);
  }
  if (const auto beyond = wheel_beyond_nadal_limit(all)) p.nadal_warning = nadal_warning(model, *beyond);
  return p;
}

CurvingSweep sweep_steady_curving(const Model& scene_model, CurvingSweepKind kind,
                                  const std::vector<double>& values, double fixed_value,
                                  double prudhomme_factor, const SteadyCurvingOptions& options) {
  const double D = scene_model.track.spec().rail_contact_distance_m, g = scene_model.gravity_m_per_s2;
  const CurvingCondition scene = condition_at_reference(scene_model, 0.0);
  // The turn: the scene's (a straight reference turns left), with its cant.
  const double turn = scene.curvature_per_m < 0.0 ? -1.0 : 1.0;
  auto condition = [&](double value) {
    const double radius = kind == CurvingSweepKind::radius ? value : fixed_value;
    const double h_d = kind == CurvingSweepKind::radius ? fixed_value : value;
    CurvingCondition c{turn / radius, scene.cant_m, 0.0};
    c.speed_m_per_s = speed_for_cant_deficiency(c.curvature_per_m, c.cant_m, h_d, D, g);
    return c;
  };
  CurvingSweep sweep;
  std::optional<SteadyCurvingState> previous;
  for (double value : values) {
    const CurvingCondition c = condition(value);
    try {
      SteadyCurvingState s = solve_steady_curving(scene_model, c, previous, options);
      CurvingPoint p = curving_point(scene_model, s, prudhomme_factor);
      if (!p.stability.stable()) {
        // The continued state is on a branch the vehicle does not stay on:
        // the vehicle's own motion from the nominal position (pseudo-
        // transient continuation, then Newton) may settle on a stable one.
        const Model arc = uniform_arc_model(scene_model, c.curvature_per_m, c.cant_m);
        try {
          EquilibriumOptions eo;
          eo.acceleration_tolerance = options.acceleration_tolerance;
          SteadyCurvingState settled = s;
          settled.equilibrium =
              solve_equilibrium(arc, c.speed_m_per_s, lowered_nominal_state(arc, c.speed_m_per_s), eo);
          settled.method = "pseudo-transient continuation from the nominal position (the state "
                           "continued from the previous point is " + p.stability.describe() + ")";
          CurvingPoint q = curving_point(scene_model, settled, prudhomme_factor);
          if (q.stability.stable() && physical_limit(arc, c.speed_m_per_s, settled.equilibrium.state).empty()) {
            s = std::move(settled);
            p = std::move(q);
          }
        } catch (const EquilibriumError&) {
        }
      }
      sweep.points.push_back(std::move(p));
      previous = s;
    } catch (const CurvingError& e) {
      if (!e.physical) throw;
      sweep.physical_limit = e.what();
      sweep.limit_condition = c;
      // The converged point nearest the limit joins the table: its forces
      // are the statement's numbers.
      if (e.last_converged && e.last_converged->equilibrium.state.size() > 0 &&
          (!previous || e.last_converged->condition.speed_m_per_s != previous->condition.speed_m_per_s ||
           e.last_converged->condition.curvature_per_m != previous->condition.curvature_per_m))
        sweep.points.push_back(curving_point(scene_model, *e.last_converged, prudhomme_factor));
      break;
    }
  }
  return sweep;
}

}  // namespace railstab
