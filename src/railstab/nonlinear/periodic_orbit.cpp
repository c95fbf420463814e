#include <railstab/nonlinear/periodic_orbit.hpp>

#include <railstab/linalg/dense_decompositions.hpp>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <limits>
#include <sstream>

namespace railstab {

namespace {

void require_coordinates(const FlowSystem& system, const OrbitCoordinates& c) {
  if (c.section_state < 0 || c.section_state >= system.size || c.amplitude_state < 0 ||
      c.amplitude_state >= system.size || c.section_state == c.amplitude_state)
    throw std::invalid_argument(
        "periodic orbit: the section and amplitude states must be two different states of the "
        "system");
}

// Each state's extremes over a flow's samples.
void sample_extremes(const std::vector<Eigen::VectorXd>& samples, Eigen::VectorXd& lo,
                     Eigen::VectorXd& hi) {
  lo = samples.front(), hi = lo;
  for (const Eigen::VectorXd& s : samples) lo = lo.cwiseMin(s), hi = hi.cwiseMax(s);
}

void fill_ranges(PeriodicOrbit& orbit) {
  sample_extremes(orbit.samples, orbit.range_min, orbit.range_max);
  orbit.amplitude = (orbit.range_max - orbit.range_min) / 2.0;
}

}  // namespace

void classify_floquet_multipliers(PeriodicOrbit& orbit, const Eigen::VectorXd& flow_direction,
                                  double multiplier_tolerance) {
  Eigen::EigenSolver<Eigen::MatrixXd> es(orbit.monodromy, /*computeEigenvectors=*/true);
  if (es.info() != Eigen::Success)
    throw std::runtime_error("periodic orbit: the monodromy matrix's eigenvalues did not converge");
  const Eigen::Index n = orbit.monodromy.rows();
  std::vector<Eigen::Index> order(static_cast<size_t>(n));
  for (Eigen::Index i = 0; i < n; ++i) order[size_t(i)] = i;
  const Eigen::VectorXcd mu = es.eigenvalues();
  std::stable_sort(order.begin(), order.end(),
                   [&](Eigen::Index a, Eigen::Index b) { return std::abs(mu(a)) > std::abs(mu(b)); });
  orbit.floquet_multipliers.resize(n);
  for (Eigen::Index i = 0; i < n; ++i) orbit.floquet_multipliers(i) = mu(order[size_t(i)]);
  // The trivial multiplier: among the eigenvalues near 1 (within 10 % or the
  // nearest one), the one whose eigenvector is most nearly parallel to f(x0).
  const Eigen::VectorXcd f = flow_direction.cast<std::complex<double>>();
  double nearest = std::numeric_limits<double>::infinity();
  for (Eigen::Index i = 0; i < n; ++i) nearest = std::min(nearest, std::abs(mu(i) - 1.0));
  double best = -1.0;
  for (Eigen::Index k = 0; k < n; ++k) {
    const Eigen::Index i = order[size_t(k)];
    if (std::abs(mu(i) - 1.0) > std::max(0.1, 1.000001 * nearest)) continue;
    const Eigen::VectorXcd v = es.eigenvectors().col(i);
    const double cosine = std::abs(v.dot(f)) / (v.norm() * f.norm() + 1e-300);
    if (cosine > best) best = cosine, orbit.trivial_multiplier = int(k);
  }
  orbit.trivial_multiplier_error =
      std::abs(orbit.floquet_multipliers(orbit.trivial_multiplier) - 1.0);
  orbit.critical_multiplier = 0.0;
  for (Eigen::Index k = 0; k < n; ++k)
    if (k != orbit.trivial_multiplier) {
      orbit.critical_multiplier = orbit.floquet_multipliers(k);
      break;
    }
  orbit.stable = std::abs(orbit.critical_multiplier) < 1.0 - multiplier_tolerance;
}

PeriodicOrbit solve_periodic_orbit(const FlowSystem& system, const OrbitCoordinates& coords,
                                   const OrbitConstraint& constraint, Eigen::VectorXd x0,
                                   double period_s, double speed_m_per_s,
                                   const ShootingOptions& options, const PeriodicOrbit* chord_from) {
  require_coordinates(system, coords);
  const int n = system.size;
  if (x0.size() != n) throw std::invalid_argument("periodic orbit: guess has the wrong size");
  if (!(period_s > 0.0)) throw std::invalid_argument("periodic orbit: the period guess must be > 0");
  const std::clock_t cpu0 = std::clock();
  const int is = coords.section_state, ia = coords.amplitude_state;
  x0(is) = 0.0;  // on the section from the start
  double T = period_s, V = speed_m_per_s;
  PeriodicOrbit orbit;
  // One flow over the period from x at speed V, with or without the
  // variational equations; its work added to the orbit's.
  // With the variational equations in a second pass, a flow whose
  // derivatives only feed Newton's matrix takes them at the looser
  // newton_matrix_sensitivity_tolerance (the state's flow is unchanged:
  // only Newton's path to the orbit is); the converging step's flow (the
  // multipliers) and the retry of a step that found no damped Newton step
  // at the flow's own (full_accuracy).
  auto shoot = [&](const Eigen::VectorXd& x, double period, double speed, bool sensitivities,
                   bool full_accuracy = false) {
    FlowOptions flow_options = options.flow;
    flow_options.sensitivities = sensitivities;
    if (sensitivities && !full_accuracy &&
        flow_options.variational == FlowOptions::Variational::second_pass)
      flow_options.sensitivity_relative_tolerance =
          std::max(flow_options.sensitivity_relative_tolerance,
                   options.newton_matrix_sensitivity_tolerance);
    flow_options.samples = options.samples_per_period;
    FlowResult flow;
    try {
      flow = integrate_flow(system, x, speed, period, flow_options);
    } catch (const std::exception& e) {
      throw ShootingFailure(std::string("periodic orbit: ") + e.what());
    }
    orbit.integration_steps += flow.steps;
    orbit.jacobian_evaluations += flow.jacobian_evaluations;
    orbit.sensitivity_flows += sensitivities ? 1 : 0;
    return flow;
  };
  // Each state's peak-to-peak over a flow's samples.
  auto range_of = [](const FlowResult& flow) -> Eigen::VectorXd {
    Eigen::VectorXd lo, hi;
    sample_extremes(flow.samples, lo, hi);
    return hi - lo;
  };
  // The residual (see the header) of the start x, period and speed whose flow is `flow`.
  auto residual_of = [&](const FlowResult& flow, const Eigen::VectorXd& x, double speed) {
    Eigen::VectorXd r(n + 2);
    r.head(n) = flow.end_state - x;
    r(n) = x(is);
    r(n + 1) = constraint.speed_coefficient * (speed - constraint.reference_speed_m_per_s) +
               constraint.amplitude_coefficient * (x(ia) - constraint.reference_amplitude);
    return r;
  };
  // The derivatives in Newton's matrix: exact from the last flow with the
  // variational equations, or (chord) kept from an earlier one.
  Eigen::MatrixXd chord_monodromy;
  Eigen::VectorXd chord_speed_sensitivity;
  const bool chord = options.chord_iterations && chord_from != nullptr &&
                     chord_from->monodromy.rows() == n && chord_from->speed_sensitivity.size() == n;
  if (chord) {
    chord_monodromy = chord_from->monodromy;
    chord_speed_sensitivity = chord_from->speed_sensitivity;
  }
  FlowResult flow = shoot(x0, T, V, !chord);
  double last_step_norm = std::numeric_limits<double>::infinity();
  for (int iteration = 1; iteration <= options.max_newton_iterations; ++iteration) {
    const bool exact = flow.state_sensitivity.rows() == n;
    if (exact) {
      chord_monodromy = flow.state_sensitivity;
      chord_speed_sensitivity = flow.speed_sensitivity;
    }
    const Eigen::VectorXd range = range_of(flow);
    Eigen::VectorXd f_end;
    system.rhs(flow.end_state, V, f_end);
    const Eigen::VectorXd r = residual_of(flow, x0, V);
    Eigen::MatrixXd N = Eigen::MatrixXd::Zero(n + 2, n + 2);
    N.topLeftCorner(n, n) = chord_monodromy - Eigen::MatrixXd::Identity(n, n);
    N.block(0, n, n, 1) = f_end;
    N.block(0, n + 1, n, 1) = chord_speed_sensitivity;
    N(n, is) = 1.0;
    N(n + 1, ia) = constraint.amplitude_coefficient;
    N(n + 1, n + 1) = constraint.speed_coefficient;
    const Eigen::VectorXd dz = N.fullPivLu().solve(-r);
    if (!dz.allFinite())
      throw ShootingFailure("periodic orbit: singular Newton matrix at V = " + std::to_string(V) +
                            " m/s (the constraint does not fix the orbit)");
    // Weighted RMS of the state part; period and speed relative.
    const Eigen::ArrayXd w = 1.0 / (options.newton_relative_tolerance *
                                        (x0.array().abs() + range.array()) +
                                    options.newton_absolute_tolerance);
    const double state_norm = std::sqrt((dz.head(n).array() * w).square().mean());
    const double step_norm =
        std::max({state_norm, std::abs(dz(n)) / (options.newton_relative_tolerance * T),
                  std::abs(dz(n + 1)) / (options.newton_relative_tolerance * std::max(1.0, std::abs(V)))});
    orbit.newton_iterations = iteration;
    if (options.iteration_progress)
      options.iteration_progress({iteration, step_norm, V, T, exact,
                                  double(std::clock() - cpu0) / CLOCKS_PER_SEC});
    // Converged: the step is within the tolerance, or within
    // stagnation_step_norm of it and no longer halving: the flow's own error
    // is the floor (a period's global error can exceed the tolerance). The
    // converging step's flow carries the variational equations, so the
    // orbit's multipliers are exact either way.
    // Stagnation is judged on exact derivatives only (a chord step's
    // contraction is linear, not a sign of the floor).
    const bool converged =
        step_norm <= 1.0 ||
        (exact && step_norm <= options.stagnation_step_norm && step_norm > 0.5 * last_step_norm);
    // A chord step that no longer contracts well, or has reached the
    // stagnation range: the exact derivatives at the current point, then the
    // step again.
    if (!exact && !converged && iteration > 1 &&
        (step_norm > options.chord_contraction * last_step_norm ||
         step_norm <= options.stagnation_step_norm)) {
      flow = shoot(x0, T, V, true);
      last_step_norm = step_norm;
      continue;
    }
    if (!converged && exact && iteration > 3 && step_norm > 1e3 * last_step_norm)
      throw ShootingFailure("periodic orbit: Newton diverges at V = " + std::to_string(V) + " m/s");
    last_step_norm = step_norm;
    // The step, damped (see the header): the longest fraction lambda of it,
    // within the period and speed limits, whose flow exists and, away from
    // convergence, reduces the residual's weighted norm. The converging
    // step's flow carries the variational equations (the multipliers).
    double lambda = 1.0;
    if (std::abs(dz(n)) > options.max_relative_period_step * T)
      lambda = options.max_relative_period_step * T / std::abs(dz(n));
    if (std::abs(dz(n + 1)) > options.max_speed_step_m_per_s)
      lambda = std::min(lambda, options.max_speed_step_m_per_s / std::abs(dz(n + 1)));
    const double merit = std::sqrt((r.head(n).array() * w).square().mean());
    // Near convergence the residual is the flow's own error: take the full step.
    const bool check_merit = step_norm > options.full_step_below_step_norm;
    const bool trial_sensitivities = converged || !chord;
    std::string last_failure;
    bool accepted = false, full_step = false;
    for (int halving = 0; halving <= options.max_step_halvings && !accepted; ++halving, lambda /= 2) {
      Eigen::VectorXd x_trial = x0 + lambda * dz.head(n);
      x_trial(is) = 0.0;
      const double T_trial = T + lambda * dz(n), V_trial = V + lambda * dz(n + 1);
      if (!(T_trial > 0.0)) {
        last_failure = "the period became non-positive";
        continue;
      }
      FlowResult trial;
      try {
        trial = shoot(x_trial, T_trial, V_trial, trial_sensitivities, /*full_accuracy=*/converged);
      } catch (const ShootingFailure& e) {
        last_failure = e.what();
        continue;
      }
      const Eigen::VectorXd r_trial = residual_of(trial, x_trial, V_trial);
      const double merit_trial = std::sqrt((r_trial.head(n).array() * w).square().mean());
      if (check_merit && !(merit_trial < (1.0 - 1e-4 * lambda) * merit)) {
        last_failure = "the residual did not decrease";
        continue;
      }
      x0 = std::move(x_trial), T = T_trial, V = V_trial;
      flow = std::move(trial);
      full_step = lambda == 1.0;
      orbit.damped_steps += full_step ? 0 : 1;
      accepted = true;
    }
    if (!accepted) {
      // A chord matrix, or one from derivatives at the looser tolerance, may
      // point the wrong way: retry with the exact one at the flow's own.
      if (!exact || flow.sensitivity_relative_tolerance > options.flow.sensitivity_relative_tolerance) {
        flow = shoot(x0, T, V, true, /*full_accuracy=*/true);
        continue;
      }
      std::ostringstream msg;
      msg << "periodic orbit: no damped Newton step at V = " << V << " m/s (" << last_failure
          << " down to a " << std::ldexp(1.0, -options.max_step_halvings)
          << " step; residual " << merit << " and Newton step " << step_norm
          << " in units of the tolerance)";
      throw ShootingFailure(msg.str());
    }
    // A converging step that had to be shortened (its flow failed at the
    // full step) did not reach the corrected point: iterate on.
    if (converged && full_step) {
      // `flow` is at the corrected point: multipliers, samples, residual.
      orbit.speed_m_per_s = V;
      orbit.period_s = T;
      orbit.start = x0;
      orbit.monodromy = flow.state_sensitivity;
      orbit.speed_sensitivity = flow.speed_sensitivity;
      orbit.sample_times_s = flow.sample_times_s;
      orbit.samples = flow.samples;
      fill_ranges(orbit);
      // Every steady state is a "periodic orbit" of any period: refuse it.
      if (!(orbit.amplitude(ia) > 1e-9 * (std::abs(x0(ia)) + 1e-6)))
        throw ShootingFailure("periodic orbit: Newton converged onto the steady state (no "
                              "oscillation left at V = " + std::to_string(V) + " m/s)");
      const double scale = std::max(orbit.amplitude.cwiseAbs().maxCoeff(), 1e-300);
      orbit.periodicity_residual = (flow.end_state - x0).cwiseAbs().maxCoeff() / scale;
      system.rhs(x0, V, orbit.flow_at_start);
      classify_floquet_multipliers(orbit, orbit.flow_at_start, options.multiplier_tolerance);
      orbit.cpu_seconds = double(std::clock() - cpu0) / CLOCKS_PER_SEC;
      return orbit;
    }
  }
  std::ostringstream msg;
  msg << "periodic orbit: Newton did not converge in " << options.max_newton_iterations
      << " iterations (V = " << V << " m/s, T = " << T << " s)";
  throw ShootingFailure(msg.str());
}

OrbitSpeedTangent orbit_speed_tangent(const PeriodicOrbit& orbit, const OrbitCoordinates& coords) {
  const Eigen::Index n = orbit.start.size();
  if (orbit.monodromy.rows() != n || orbit.speed_sensitivity.size() != n ||
      orbit.flow_at_start.size() != n)
    throw std::invalid_argument("orbit_speed_tangent: the orbit has no monodromy matrix");
  Eigen::MatrixXd N = Eigen::MatrixXd::Zero(n + 1, n + 1);
  N.topLeftCorner(n, n) = orbit.monodromy - Eigen::MatrixXd::Identity(n, n);
  N.block(0, n, n, 1) = orbit.flow_at_start;
  N(n, coords.section_state) = 1.0;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n + 1);
  rhs.head(n) = -orbit.speed_sensitivity;
  const Eigen::VectorXd d = N.fullPivLu().solve(rhs);
  OrbitSpeedTangent t;
  if (!d.allFinite()) return t;  // at a fold: no tangent in speed
  t.start_per_speed = d.head(n);
  t.period_per_speed = d(n);
  return t;
}

double OrbitGuess::spread() const {
  const double periods = (period_max_s - period_min_s) / (0.5 * (period_max_s + period_min_s));
  const double excursions = half_range > 0.0 ? (excursion_max - excursion_min) / half_range : 0.0;
  return std::max(periods, excursions);
}

OrbitGuess orbit_guess_from_samples(const std::vector<double>& times_s,
                                    const std::vector<Eigen::VectorXd>& states,
                                    const OrbitCoordinates& coords) {
  const int is = coords.section_state, ia = coords.amplitude_state;
  const auto too_few = [] {
    return std::runtime_error(
        "periodic orbit: the run holds fewer than two periods of the leading wheelset's lateral "
        "motion (no oscillation to start from)");
  };
  if (states.size() < 2) throw too_few();
  double lo = states.front()(ia), hi = lo;
  for (const Eigen::VectorXd& x : states) lo = std::min(lo, x(ia)), hi = std::max(hi, x(ia));
  const double mid = 0.5 * (lo + hi);
  // Maxima (the rate falling through 0), interpolated; and the cycle each
  // lies in (the number of upward mid-range crossings before it).
  struct Maximum {
    double t;
    Eigen::VectorXd x;
    int cycle;
  };
  std::vector<Maximum> maxima;
  int cycle = -1;  // before the first upward crossing: no complete cycle yet
  for (size_t k = 1; k < states.size(); ++k) {
    if (states[k - 1](ia) < mid && states[k](ia) >= mid) ++cycle;
    const double a = states[k - 1](is), b = states[k](is);
    if (a > 0.0 && b <= 0.0 && cycle >= 0) {
      const double s = a / (a - b);
      maxima.push_back({times_s[k - 1] + s * (times_s[k] - times_s[k - 1]),
                        states[k - 1] + s * (states[k] - states[k - 1]), cycle});
    }
  }
  // The principal maximum of each complete cycle (0 .. cycle - 1; the last,
  // still open at the run's end, is left out).
  std::vector<const Maximum*> principal(size_t(std::max(cycle, 0)), nullptr);
  for (const Maximum& m : maxima)
    if (m.cycle < cycle && (!principal[size_t(m.cycle)] || m.x(ia) > principal[size_t(m.cycle)]->x(ia)))
      principal[size_t(m.cycle)] = &m;
  principal.erase(std::remove(principal.begin(), principal.end(), nullptr), principal.end());
  if (principal.size() < 2) throw too_few();
  OrbitGuess g;
  g.start = principal.back()->x;
  g.period_s = principal.back()->t - principal[principal.size() - 2]->t;
  g.cycles = int(principal.size());
  g.half_range = 0.5 * (hi - lo);
  g.period_min_s = g.period_max_s = g.period_s;
  g.excursion_min = g.excursion_max = g.start(ia);
  for (size_t k = 0; k < principal.size(); ++k) {
    g.excursion_min = std::min(g.excursion_min, principal[k]->x(ia));
    g.excursion_max = std::max(g.excursion_max, principal[k]->x(ia));
    if (k == 0) continue;
    const double period = principal[k]->t - principal[k - 1]->t;
    g.period_min_s = std::min(g.period_min_s, period);
    g.period_max_s = std::max(g.period_max_s, period);
  }
  return g;
}

}  // namespace railstab
