#include <railstab/nonlinear/periodic_orbit.hpp>

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

// Extremes over the samples.
void fill_ranges(PeriodicOrbit& orbit) {
  const Eigen::Index n = orbit.start.size();
  orbit.range_min = Eigen::VectorXd::Constant(n, std::numeric_limits<double>::infinity());
  orbit.range_max = -orbit.range_min;
  for (const Eigen::VectorXd& s : orbit.samples) {
    orbit.range_min = orbit.range_min.cwiseMin(s);
    orbit.range_max = orbit.range_max.cwiseMax(s);
  }
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
                                   const ShootingOptions& options) {
  require_coordinates(system, coords);
  const int n = system.size;
  if (x0.size() != n) throw std::invalid_argument("periodic orbit: guess has the wrong size");
  if (!(period_s > 0.0)) throw std::invalid_argument("periodic orbit: the period guess must be > 0");
  const std::clock_t cpu0 = std::clock();
  const int is = coords.section_state, ia = coords.amplitude_state;
  x0(is) = 0.0;  // on the section from the start
  double T = period_s, V = speed_m_per_s;
  PeriodicOrbit orbit;
  FlowOptions flow_options = options.flow;
  flow_options.sensitivities = true;
  flow_options.samples = options.samples_per_period;
  Eigen::VectorXd range = Eigen::VectorXd::Zero(n);
  double last_step_norm = std::numeric_limits<double>::infinity();
  // One flow over the current period; its work added to the orbit's.
  auto shoot = [&] {
    FlowResult flow;
    try {
      flow = integrate_flow(system, x0, V, T, flow_options);
    } catch (const std::exception& e) {
      throw ShootingFailure(std::string("periodic orbit: ") + e.what());
    }
    orbit.integration_steps += flow.steps;
    orbit.jacobian_evaluations += flow.jacobian_evaluations;
    return flow;
  };
  for (int iteration = 1; iteration <= options.max_newton_iterations; ++iteration) {
    FlowResult flow = shoot();
    range.setZero();
    {
      Eigen::VectorXd lo = flow.samples.front(), hi = lo;
      for (const auto& s : flow.samples) lo = lo.cwiseMin(s), hi = hi.cwiseMax(s);
      range = hi - lo;
    }
    Eigen::VectorXd f_end;
    system.rhs(flow.end_state, V, f_end);
    // Residual and Newton matrix (see the header).
    Eigen::VectorXd r(n + 2);
    r.head(n) = flow.end_state - x0;
    r(n) = x0(is);
    r(n + 1) = constraint.speed_coefficient * (V - constraint.reference_speed_m_per_s) +
               constraint.amplitude_coefficient * (x0(ia) - constraint.reference_amplitude);
    Eigen::MatrixXd N = Eigen::MatrixXd::Zero(n + 2, n + 2);
    N.topLeftCorner(n, n) = flow.state_sensitivity - Eigen::MatrixXd::Identity(n, n);
    N.block(0, n, n, 1) = f_end;
    N.block(0, n + 1, n, 1) = flow.speed_sensitivity;
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
    const bool converged = step_norm <= 1.0;
    // Take the step unless it is the converging last one, which is then
    // applied and checked by the final flow below.
    x0 += dz.head(n);
    T += dz(n);
    V += dz(n + 1);
    x0(is) = 0.0;
    if (!(T > 0.0))
      throw ShootingFailure("periodic orbit: the period became non-positive (Newton diverged)");
    orbit.newton_iterations = iteration;
    if (converged || (iteration > 3 && step_norm > 1e3 * last_step_norm)) {
      if (!converged)
        throw ShootingFailure("periodic orbit: Newton diverges at V = " + std::to_string(V) +
                              " m/s");
      // The final flow at the corrected point: multipliers, samples, residual.
      flow = shoot();
      orbit.speed_m_per_s = V;
      orbit.period_s = T;
      orbit.start = x0;
      orbit.monodromy = flow.state_sensitivity;
      orbit.sample_times_s = flow.sample_times_s;
      orbit.samples = flow.samples;
      fill_ranges(orbit);
      // Every steady state is a "periodic orbit" of any period: refuse it.
      if (!(orbit.amplitude(ia) > 1e-9 * (std::abs(x0(ia)) + 1e-6)))
        throw ShootingFailure("periodic orbit: Newton converged onto the steady state (no "
                              "oscillation left at V = " + std::to_string(V) + " m/s)");
      const double scale = std::max(orbit.amplitude.cwiseAbs().maxCoeff(), 1e-300);
      orbit.periodicity_residual = (flow.end_state - x0).cwiseAbs().maxCoeff() / scale;
      Eigen::VectorXd f0;
      system.rhs(x0, V, f0);
      classify_floquet_multipliers(orbit, f0, options.multiplier_tolerance);
      orbit.cpu_seconds = double(std::clock() - cpu0) / CLOCKS_PER_SEC;
      return orbit;
    }
    last_step_norm = step_norm;
  }
  std::ostringstream msg;
  msg << "periodic orbit: Newton did not converge in " << options.max_newton_iterations
      << " iterations (V = " << V << " m/s, T = " << T << " s)";
  throw ShootingFailure(msg.str());
}

OrbitGuess orbit_guess_from_samples(const std::vector<double>& times_s,
                                    const std::vector<Eigen::VectorXd>& states,
                                    const OrbitCoordinates& coords) {
  const int is = coords.section_state;
  // Crossings of x[is] from + to - (a maximum of x[ia] when x[is] is its rate).
  std::vector<std::pair<double, Eigen::VectorXd>> crossings;
  for (size_t k = 1; k < states.size(); ++k) {
    const double a = states[k - 1](is), b = states[k](is);
    if (a > 0.0 && b <= 0.0) {
      const double s = a / (a - b);
      crossings.emplace_back(times_s[k - 1] + s * (times_s[k] - times_s[k - 1]),
                             states[k - 1] + s * (states[k] - states[k - 1]));
    }
  }
  if (crossings.size() < 2)
    throw std::runtime_error(
        "periodic orbit: the run holds fewer than two periods of the leading wheelset's lateral "
        "motion (no oscillation to start from)");
  OrbitGuess g;
  g.start = crossings.back().second;
  g.period_s = crossings.back().first - crossings[crossings.size() - 2].first;
  return g;
}

}  // namespace railstab
