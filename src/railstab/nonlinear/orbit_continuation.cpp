#include <railstab/nonlinear/orbit_continuation.hpp>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <limits>
#include <numbers>
#include <sstream>

namespace railstab {

std::string orbit_bifurcation_name(OrbitBifurcationKind kind) {
  switch (kind) {
    case OrbitBifurcationKind::fold: return "fold";
    case OrbitBifurcationKind::period_doubling: return "period_doubling";
    case OrbitBifurcationKind::torus: return "torus";
  }
  return "fold";
}

namespace {

// Non-trivial multipliers outside the unit circle.
int unstable_multipliers(const PeriodicOrbit& o, double tolerance) {
  int count = 0;
  for (Eigen::Index k = 0; k < o.floquet_multipliers.size(); ++k)
    if (k != o.trivial_multiplier && std::abs(o.floquet_multipliers(k)) > 1.0 + tolerance) ++count;
  return count;
}

// The non-trivial multiplier of `o` nearest the point z of the complex plane.
std::complex<double> multiplier_nearest(const PeriodicOrbit& o, std::complex<double> z) {
  std::complex<double> best = 0.0;
  double distance = std::numeric_limits<double>::infinity();
  for (Eigen::Index k = 0; k < o.floquet_multipliers.size(); ++k) {
    if (k == o.trivial_multiplier) continue;
    const double d = std::abs(o.floquet_multipliers(k) - z);
    if (d < distance) distance = d, best = o.floquet_multipliers(k);
  }
  return best;
}

// The fold's speed and excursion through three orbits around it: V as a
// parabola in the excursion a (the fold is a regular point of V(a)); falls
// back to the middle orbit when the three excursions are not distinct.
// `excursion` (optional) receives the vertex's excursion (a1 when it falls
// back).
void fold_vertex(const PeriodicOrbit& p, const PeriodicOrbit& c, const PeriodicOrbit& n, int ia,
                 int amplitude_state, double& V, double& amplitude, double* excursion = nullptr) {
  const double a0 = p.start(ia), a1 = c.start(ia), a2 = n.start(ia);
  const double v0 = p.speed_m_per_s, v1 = c.speed_m_per_s, v2 = n.speed_m_per_s;
  V = v1, amplitude = c.amplitude(amplitude_state);
  if (excursion) *excursion = a1;
  const double d01 = a0 - a1, d02 = a0 - a2, d12 = a1 - a2;
  if (d01 == 0.0 || d02 == 0.0 || d12 == 0.0) return;
  // Lagrange form: V(a) = A a^2 + B a + C.
  const double A = v0 / (d01 * d02) - v1 / (d01 * d12) + v2 / (d02 * d12);
  const double B = -v0 * (a1 + a2) / (d01 * d02) + v1 * (a0 + a2) / (d01 * d12) -
                   v2 * (a0 + a1) / (d02 * d12);
  if (A == 0.0) return;
  const double a_star = -B / (2.0 * A);
  const double lo = std::min({a0, a1, a2}), hi = std::max({a0, a1, a2});
  if (a_star < lo || a_star > hi) return;
  const double C = v1 - A * a1 * a1 - B * a1;
  V = A * a_star * a_star + B * a_star + C;
  if (excursion) *excursion = a_star;
  // The excursion scales the half peak-to-peak amplitude: interpolate it.
  const double s = (a_star - a1) / ((a_star >= a1 ? a2 : a0) - a1);
  const PeriodicOrbit& other = a_star >= a1 ? n : p;
  amplitude = c.amplitude(amplitude_state) +
              s * (other.amplitude(amplitude_state) - c.amplitude(amplitude_state));
}

// `speed_resolution`: speed changes below it are the corrector's noise (its
// relative tolerance on V), not a turn of the branch (a branch at nearly
// constant speed, as a nearly linear model's, would show "folds" at every
// orbit).
// A fold recorded within the last three orbits before orbit k: the speed's
// turn and the multiplier's passing +1 mark the same fold an orbit apart.
OrbitBifurcation* recent_fold(OrbitBranch& branch, int k) {
  for (OrbitBifurcation& f : branch.bifurcations)
    if (f.kind == OrbitBifurcationKind::fold && f.after_orbit >= k - 3) return &f;
  return nullptr;
}

void detect_bifurcations(OrbitBranch& branch, int ia, double tolerance, double speed_resolution) {
  const auto& o = branch.orbits;
  const int k = int(o.size()) - 1;  // the orbit just added
  if (k < 1) return;
  // Fold in V: the speed turns round at orbit k - 1.
  if (k >= 2) {
    const double before = o[size_t(k - 1)].speed_m_per_s - o[size_t(k - 2)].speed_m_per_s;
    const double after = o[size_t(k)].speed_m_per_s - o[size_t(k - 1)].speed_m_per_s;
    if (before * after < 0.0 && std::abs(before) > speed_resolution &&
        std::abs(after) > speed_resolution) {
      OrbitBifurcation b;
      b.kind = OrbitBifurcationKind::fold;
      b.after_orbit = k - 1;
      fold_vertex(o[size_t(k - 2)], o[size_t(k - 1)], o[size_t(k)], ia, ia, b.speed_m_per_s,
                  b.amplitude);
      b.multiplier = multiplier_nearest(o[size_t(k - 1)], 1.0);
      // A fold recorded an orbit earlier from its multiplier passing +1 is
      // this one: the parabola's vertex is the better estimate of it.
      if (OrbitBifurcation* same = recent_fold(branch, k)) *same = b;
      else branch.bifurcations.push_back(b);
    }
  }
  // Stability changes: a multiplier leaving or entering the unit circle at
  // -1 or as a complex pair, or at +1 (a fold the speed's turn missed).
  const PeriodicOrbit &a = o[size_t(k - 1)], &c = o[size_t(k)];
  if (unstable_multipliers(a, tolerance) == unstable_multipliers(c, tolerance)) return;
  const std::complex<double> mu = crossing_multiplier(a, c, tolerance);
  const bool real = std::abs(mu.imag()) <= 1e-6 * std::abs(mu);
  if (real && mu.real() > 0.0) {
    // +1: a fold. Recorded above where the speed turned by more than its
    // resolution; a turn spread over orbits whose speeds differ by less
    // (the S1002 bogie's branch: 35.0809, 35.0754, 35.0754, 35.0828 m/s) is
    // found here, by the multiplier passing +1.
    if (recent_fold(branch, k)) return;
  }
  OrbitBifurcation b;
  b.kind = real ? (mu.real() > 0.0 ? OrbitBifurcationKind::fold
                                   : OrbitBifurcationKind::period_doubling)
                : OrbitBifurcationKind::torus;
  b.after_orbit = k - 1;
  b.multiplier = mu;
  // Where |mu| = 1 between the two orbits, linear in the moduli of the
  // crossing multiplier and its counterpart on the other orbit (the one
  // nearest it), kept between the two orbits.
  const bool lost = unstable_multipliers(c, tolerance) > unstable_multipliers(a, tolerance);
  const std::complex<double> mu_a = lost ? multiplier_nearest(a, mu) : mu;
  const std::complex<double> mu_c = lost ? mu : multiplier_nearest(c, mu);
  const double ma = std::abs(mu_a) - 1.0, mc = std::abs(mu_c) - 1.0;
  const double s = ma == mc ? 0.5 : std::clamp(ma / (ma - mc), 0.0, 1.0);
  b.speed_m_per_s = a.speed_m_per_s + s * (c.speed_m_per_s - a.speed_m_per_s);
  b.amplitude = a.amplitude(ia) + s * (c.amplitude(ia) - a.amplitude(ia));
  branch.bifurcations.push_back(b);
}

}  // namespace

std::complex<double> crossing_multiplier(const PeriodicOrbit& a, const PeriodicOrbit& c,
                                         double tolerance) {
  const PeriodicOrbit& more = unstable_multipliers(c, tolerance) >= unstable_multipliers(a, tolerance) ? c : a;
  std::complex<double> best = 0.0;
  double modulus = std::numeric_limits<double>::infinity();
  for (Eigen::Index k = 0; k < more.floquet_multipliers.size(); ++k) {
    const double m = std::abs(more.floquet_multipliers(k));
    if (k == more.trivial_multiplier || m <= 1.0 + tolerance) continue;
    if (m < modulus) modulus = m, best = more.floquet_multipliers(k);
  }
  return best;
}

namespace {

// The unknowns at c + g (c - q) along the secant from q through c (g > 0
// beyond c, g < 0 back towards q): a predictor, or a guess between orbits.
struct SecantPoint {
  Eigen::VectorXd start;
  double period_s = 0.0, speed_m_per_s = 0.0;
};
SecantPoint secant_point(const PeriodicOrbit& c, const PeriodicOrbit& q, double g) {
  return {c.start + g * (c.start - q.start), c.period_s + g * (c.period_s - q.period_s),
          c.speed_m_per_s + g * (c.speed_m_per_s - q.speed_m_per_s)};
}

// A fold just found from the vertex of the parabola V(a) through orbits k-2,
// k-1, k: one more orbit at fixed excursion at the vertex's excursion a*
// (the guess interpolated from the neighbour on a*'s side), then the vertex
// again through that orbit and its nearest neighbours in a on either side.
// The branch crosses a sharp fold in few orbits (the fixed-excursion step),
// so the first vertex's error (third order in the orbits' spacing) can be
// 0.005 m/s on the S1002 vehicle; the second's comes from orbits nearer the
// vertex. The extra orbit is not part of the branch. Returns false (the
// first estimate kept) when there is no vertex inside or the orbit fails.
bool refine_fold(OrbitBifurcation& fold, const std::vector<PeriodicOrbit>& o, int k,
                 const FlowSystem& system, const OrbitCoordinates& coords,
                 const ContinuationOptions& options, std::string& failure) {
  const int ia = coords.amplitude_state;
  const PeriodicOrbit &p = o[size_t(k - 2)], &c = o[size_t(k - 1)], &n = o[size_t(k)];
  double V = 0.0, amplitude = 0.0, a_star = 0.0;
  fold_vertex(p, c, n, ia, ia, V, amplitude, &a_star);
  const double a1 = c.start(ia);
  if (a_star == a1) return false;
  const PeriodicOrbit* side = nullptr;
  for (const PeriodicOrbit* q : {&p, &n})
    if ((q->start(ia) - a1) * (a_star - a1) > 0.0 &&
        std::abs(q->start(ia) - a1) >= std::abs(a_star - a1))
      side = q;
  if (side == nullptr) return false;
  const SecantPoint guess = secant_point(c, *side, -(a_star - a1) / (side->start(ia) - a1));
  PeriodicOrbit r;
  try {
    r = solve_periodic_orbit(system, coords, OrbitConstraint::fixed_excursion(a_star), guess.start,
                             guess.period_s, guess.speed_m_per_s, options.shooting, &c);
  } catch (const ShootingFailure& e) {
    failure = e.what();
    return false;
  }
  // r's nearest neighbours in a below and above it among the three.
  const PeriodicOrbit *below = nullptr, *above = nullptr;
  for (const PeriodicOrbit* q : {&p, &c, &n}) {
    const double d = q->start(ia) - a_star;
    if (d < 0.0 && (!below || d > below->start(ia) - a_star)) below = q;
    if (d > 0.0 && (!above || d < above->start(ia) - a_star)) above = q;
  }
  if (!below || !above) return false;
  fold_vertex(*below, r, *above, ia, ia, fold.speed_m_per_s, fold.amplitude);
  return true;
}

}  // namespace

OrbitBranch continue_branch(const FlowSystem& system, const OrbitCoordinates& coords,
                            std::vector<PeriodicOrbit> first_two,
                            const ContinuationOptions& options) {
  if (first_two.size() != 2)
    throw std::invalid_argument("continue_branch: needs the branch's first two orbits");
  const std::clock_t cpu0 = std::clock();
  const int ia = coords.amplitude_state;
  const double sV = options.speed_scale_m_per_s, sa = options.amplitude_scale;
  OrbitBranch branch;
  // The branch's CPU includes its first two orbits' (solved before this).
  const double first_two_cpu = first_two[0].cpu_seconds + first_two[1].cpu_seconds;
  branch.orbits = std::move(first_two);
  if (options.progress)
    for (size_t k = 0; k < branch.orbits.size(); ++k) options.progress(int(k) + 1, branch.orbits[k]);
  const double tol = options.shooting.multiplier_tolerance;
  auto detect = [&] {
    const double V = std::max(1.0, std::abs(branch.orbits.back().speed_m_per_s));
    detect_bifurcations(branch, ia, tol, 10.0 * options.shooting.newton_relative_tolerance * V);
  };
  detect();
  double h = options.initial_step;
  int refined_fold = -1;  // after_orbit of the fold refined last
  auto finish = [&](std::string reason) {
    branch.stop_reason = std::move(reason);
    branch.cpu_seconds = first_two_cpu + double(std::clock() - cpu0) / CLOCKS_PER_SEC;
    return branch;
  };
  while (true) {
    const PeriodicOrbit& c = branch.orbits.back();
    const PeriodicOrbit& p = branch.orbits[branch.orbits.size() - 2];
    if (int(branch.orbits.size()) >= options.max_orbits) return finish("orbit limit reached");
    if (options.stop_at_first_fold)
      for (const OrbitBifurcation& f : branch.bifurcations)
        if (f.kind == OrbitBifurcationKind::fold && branch.orbits.size() >= size_t(f.after_orbit) + 3)
          return finish("stopped past the first fold (stop at fold)");
    if (c.speed_m_per_s < options.min_speed_m_per_s) return finish("below the speed range");
    if (c.speed_m_per_s > options.max_speed_m_per_s) return finish("above the speed range");
    if (c.amplitude(ia) > options.max_amplitude) return finish("amplitude limit reached");
    // The unit secant in the scaled plane, and per unit arclength for every unknown.
    const double dV = (c.speed_m_per_s - p.speed_m_per_s) / sV;
    const double da = (c.start(ia) - p.start(ia)) / sa;
    const double length = std::hypot(dV, da);
    if (!(length > 0.0)) return finish("two identical orbits: no direction");
    const double tV = dV / length, ta = da / length;
    bool accepted = false;
    while (!accepted) {
      if (h < options.min_step) return finish("step-size floor reached");
      const double g = h / length;  // fraction of the last secant
      const SecantPoint pred = secant_point(c, p, g);
      const Eigen::VectorXd& x_pred = pred.start;
      const double T_pred = pred.period_s, V_pred = pred.speed_m_per_s;
      OrbitConstraint constraint{tV / sV, ta / sa, V_pred, x_pred(ia)};
      const std::clock_t corrector_cpu0 = std::clock();
      try {
        PeriodicOrbit next = solve_periodic_orbit(system, coords, constraint, x_pred, T_pred,
                                                  V_pred, options.shooting, &c);
        // Refuse a jump back along the branch or onto another one: the new
        // secant must point the way of the last.
        const double nV = (next.speed_m_per_s - c.speed_m_per_s) / sV;
        const double na = (next.start(ia) - c.start(ia)) / sa;
        if (nV * tV + na * ta <= 0.0) throw ShootingFailure("the corrector went backwards");
        const int iterations = next.newton_iterations;
        // Fast: few iterations, or cheap chord iterations that needed fresh
        // derivatives at most once before the converged orbit's (the
        // refresh on reaching the stagnation range is the usual one).
        // Or a predictor that was nearly right: the corrected orbit within
        // straight_predictor_error of the step from the secant's prediction
        // in the scaled plane (a straight stretch of the branch, where the
        // iterations are the chord's and the flow's, not the curvature's).
        const double predictor_error =
            std::hypot((next.speed_m_per_s - V_pred) / sV, (next.start(ia) - x_pred(ia)) / sa) / h;
        const bool fast = iterations <= options.fast_newton_iterations ||
                          (next.sensitivity_flows <= 2 &&
                           iterations <= 3 * options.fast_newton_iterations) ||
                          predictor_error <= options.straight_predictor_error;
        branch.orbits.push_back(std::move(next));
        accepted = true;
        if (options.progress) options.progress(int(branch.orbits.size()), branch.orbits.back());
        if (fast)
          h = std::min(options.max_step, h * options.growth_factor);
      } catch (const ShootingFailure& e) {
        ++branch.failed_correctors;
        if (options.corrector_failed)
          options.corrector_failed(h, e.what(),
                                   double(std::clock() - corrector_cpu0) / CLOCKS_PER_SEC);
        // Then the same step's excursion alone, at fixed excursion (see the
        // header): the way through a fold in V too sharp for the plane's
        // condition.
        if (options.excursion_step_after_failure && ta != 0.0) {
          const double a_next = c.start(ia) + h * ta * sa;
          const SecantPoint guess =
              secant_point(c, p, (a_next - c.start(ia)) / (c.start(ia) - p.start(ia)));
          const std::clock_t excursion_cpu0 = std::clock();
          try {
            PeriodicOrbit next = solve_periodic_orbit(
                system, coords, OrbitConstraint::fixed_excursion(a_next), guess.start,
                guess.period_s, guess.speed_m_per_s, options.shooting, &c);
            branch.orbits.push_back(std::move(next));
            accepted = true;
            if (options.progress) options.progress(int(branch.orbits.size()), branch.orbits.back());
            continue;
          } catch (const ShootingFailure& e2) {
            ++branch.failed_correctors;
            if (options.corrector_failed)
              options.corrector_failed(h, std::string("at fixed excursion: ") + e2.what(),
                                       double(std::clock() - excursion_cpu0) / CLOCKS_PER_SEC);
          }
        }
        h /= 2.0;
      }
    }
    // An orbit shrunk to nothing is the steady state, whose multipliers past
    // the Hopf point (exp(lambda T) of its unstable pair) would read as a
    // torus point: the branch ends there, with no bifurcation against it.
    if (branch.orbits.back().amplitude(ia) < 1e-3 * options.amplitude_scale &&
        branch.orbits.back().amplitude(ia) < branch.orbits[branch.orbits.size() - 2].amplitude(ia))
      return finish("back at the steady state (the orbit shrank to zero)");
    detect();
    // A fold found just now from the speed's turn at the orbit before: its
    // vertex refined by one more orbit (refine_fold), once per fold.
    const int k = int(branch.orbits.size()) - 1;
    if (options.refine_folds && !branch.bifurcations.empty()) {
      OrbitBifurcation& f = branch.bifurcations.back();
      if (f.kind == OrbitBifurcationKind::fold && f.after_orbit == k - 1 && refined_fold != k - 1) {
        refined_fold = k - 1;
        std::string failure;
        const std::clock_t refine_cpu0 = std::clock();
        if (!refine_fold(f, branch.orbits, k, system, coords, options, failure) &&
            !failure.empty() && options.corrector_failed)
          options.corrector_failed(0.0, "refining the fold: " + failure,
                                   double(std::clock() - refine_cpu0) / CLOCKS_PER_SEC);
      }
    }
  }
}

OrbitBranch continue_from_orbit(const FlowSystem& system, const OrbitCoordinates& coords,
                                const PeriodicOrbit& first, double speed_step_m_per_s,
                                const ContinuationOptions& options) {
  const double V2 = first.speed_m_per_s + speed_step_m_per_s;
  // Predicted along the orbit's tangent in speed (the spin rates alone move
  // by dV / r0: a guess at the first orbit's state cost a flange-hunting
  // bogie 11 damped Newton iterations instead of 3-4).
  const OrbitSpeedTangent t = orbit_speed_tangent(first, coords);
  Eigen::VectorXd guess = first.start;
  double period = first.period_s;
  if (t.start_per_speed.size() == guess.size()) {
    guess += speed_step_m_per_s * t.start_per_speed;
    period += speed_step_m_per_s * t.period_per_speed;
    if (!(period > 0.0)) guess = first.start, period = first.period_s;
  }
  PeriodicOrbit second = solve_periodic_orbit(system, coords, OrbitConstraint::fixed_speed(V2),
                                              guess, period, V2, options.shooting, &first);
  return continue_branch(system, coords, {first, std::move(second)}, options);
}

OrbitBranch continue_from_hopf(const FlowSystem& system, const OrbitCoordinates& coords,
                               const HopfStart& start, double first_excursion,
                               const ContinuationOptions& options) {
  const int ia = coords.amplitude_state;
  const Eigen::VectorXcd& q = start.eigenvector;
  if (q.size() != system.size || start.equilibrium.size() != system.size)
    throw std::invalid_argument("continue_from_hopf: equilibrium or eigenvector of the wrong size");
  if (std::abs(q(ia)) == 0.0)
    throw std::invalid_argument(
        "continue_from_hopf: the critical mode does not move the amplitude state");
  if (!(start.eigenvalue.imag() > 0.0))
    throw std::invalid_argument("continue_from_hopf: the critical eigenvalue is not a pair");
  // x = x_eq + c Re(q e^{i theta}): theta = -arg q_a puts the excursion at
  // its maximum, where its rate (the section state) is 0.
  const std::complex<double> phase = std::polar(1.0, -std::arg(q(ia)));
  const Eigen::VectorXd shape = (q * phase).real() / std::abs(q(ia));
  const double period = 2.0 * std::numbers::pi / start.eigenvalue.imag();
  auto predicted_speed = [&](double excursion) {
    if (start.cycle_side == 0 || !(start.amplitude_per_sqrt_speed > 0.0))
      return start.critical_speed_m_per_s;
    const double r = excursion / start.amplitude_per_sqrt_speed;
    return start.critical_speed_m_per_s + start.cycle_side * r * r;
  };
  std::vector<PeriodicOrbit> first_two;
  first_two.push_back(solve_periodic_orbit(
      system, coords, OrbitConstraint::fixed_excursion(start.equilibrium(ia) + first_excursion),
      start.equilibrium + first_excursion * shape, period, predicted_speed(first_excursion),
      options.shooting));
  // The second at twice the excursion: from the square-root law where l1 is
  // known; without it (a profile contact's table is only C1, so the orbits
  // need not follow the law) from the first orbit, its offset from the
  // steady state doubled and its speed offset from V_c doubled (the linear
  // law of a kinked contact function), which is nearer than the linear mode.
  const double second_excursion = 2.0 * first_excursion;
  const OrbitConstraint second = OrbitConstraint::fixed_excursion(start.equilibrium(ia) + second_excursion);
  if (start.cycle_side != 0) {
    first_two.push_back(solve_periodic_orbit(system, coords, second,
                                             start.equilibrium + second_excursion * shape, period,
                                             predicted_speed(second_excursion), options.shooting));
  } else {
    const PeriodicOrbit& first = first_two.front();
    const Eigen::VectorXd guess = start.equilibrium + 2.0 * (first.start - start.equilibrium);
    const double speed = 2.0 * first.speed_m_per_s - start.critical_speed_m_per_s;
    first_two.push_back(solve_periodic_orbit(system, coords, second, guess, first.period_s, speed,
                                             options.shooting, &first));
  }
  return continue_branch(system, coords, std::move(first_two), options);
}

double lowest_stable_speed(const OrbitBranch& branch) {
  double lowest = std::numeric_limits<double>::quiet_NaN();
  auto take = [&](double v) {
    if (std::isnan(lowest) || v < lowest) lowest = v;
  };
  for (const PeriodicOrbit& o : branch.orbits)
    if (o.stable) take(o.speed_m_per_s);
  for (const OrbitBifurcation& b : branch.bifurcations)
    if (b.kind == OrbitBifurcationKind::fold) {
      const size_t k = size_t(b.after_orbit);
      const bool next_to_stable = branch.orbits[k].stable ||
                                  (k > 0 && branch.orbits[k - 1].stable) ||
                                  (k + 1 < branch.orbits.size() && branch.orbits[k + 1].stable);
      if (next_to_stable) take(b.speed_m_per_s);
    }
  return lowest;
}

}  // namespace railstab
