#include <railstab/nonlinear/bifurcation_analysis.hpp>

#include <railstab/equilibrium/speed_continuation.hpp>
#include <railstab/integrate/integrator.hpp>
#include <railstab/nonlinear/hopf_assessment.hpp>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <iomanip>
#include <memory>
#include <sstream>

namespace railstab {

namespace {

ContinuationOptions continuation_for(const BifurcationOptions& o, const std::string& origin,
                                     const OrbitCoordinates& coords, bool profile_contact) {
  ContinuationOptions c = o.continuation;
  // Profile contact: the variational equations in a second pass (see
  // BifurcationOptions::continuation).
  if (profile_contact) c.shooting.flow.variational = FlowOptions::Variational::second_pass;
  c.min_speed_m_per_s = o.linear.from_m_per_s;
  c.max_speed_m_per_s = o.linear.to_m_per_s;
  c.max_amplitude = o.max_amplitude_m;
  if (o.progress)
    c.progress = [progress = o.progress, origin, ia = coords.amplitude_state](int number,
                                                                         const PeriodicOrbit& orbit) {
      std::ostringstream line;
      line << "  " << origin << " branch, orbit " << number << ": " << std::fixed
           << std::setprecision(4) << orbit.speed_m_per_s << " m/s, amplitude "
           << 1e3 * orbit.amplitude(ia) << " mm, largest multiplier |mu| " << std::setprecision(6)
           << std::abs(orbit.critical_multiplier) << (orbit.stable ? " (stable)" : " (unstable)")
           << ", " << orbit.integration_steps << " steps, " << orbit.newton_iterations
           << " Newton iterations, " << std::setprecision(2) << orbit.cpu_seconds << " s CPU";
      progress(line.str());
    };
  // Within an orbit (a corrector in flange contact can take minutes): a
  // line when 10 s of the orbit's CPU have passed since the last, so a short
  // orbit says nothing more than its line above. The counter restarts with
  // each orbit (its CPU clock does).
  if (o.progress)
    c.shooting.iteration_progress = [progress = o.progress, origin,
                                     last = std::make_shared<double>(0.0)](const ShootingIteration& it) {
      if (it.cpu_seconds < *last) *last = 0.0;  // a new orbit
      if (it.cpu_seconds - *last < 10.0) return;
      *last = it.cpu_seconds;
      std::ostringstream line;
      line << "    " << origin << " branch, an orbit at " << std::fixed << std::setprecision(4)
           << it.speed_m_per_s << " m/s: Newton iteration " << it.iteration << ", step "
           << std::scientific << std::setprecision(2) << it.step_norm << " x the tolerance ("
           << (it.exact_derivatives ? "exact derivatives" : "chord") << "), " << std::fixed
           << std::setprecision(1) << it.cpu_seconds << " s CPU so far";
      progress(line.str());
    };
  if (o.progress)
    c.corrector_failed = [progress = o.progress, origin](double step, const std::string& reason,
                                                         double cpu_s) {
      std::ostringstream line;
      line << "  " << origin << " branch: corrector failed at step " << std::setprecision(3) << step
           << " (" << reason << "; " << std::fixed << std::setprecision(2) << cpu_s
           << " s CPU), retried with half the step";
      progress(line.str());
    };
  return c;
}

BranchResult branch_from_hopf(const Model& model, const FlowSystem& system, BifurcationResult& r,
                              const BifurcationOptions& o) {
  BranchResult b;
  b.origin = "hopf";
  try {
    r.hopf = hopf_criticality(model, r.linear);
    HopfStart start = model_hopf_start(model, r.reduced_states, r.linear.at_critical.equilibrium.state,
                                       r.hopf, r.coords);
    if (r.profile_contact) {
      // No l1 from a C1 table: the first orbits decide the side.
      start.cycle_side = 0;
      start.amplitude_per_sqrt_speed = 0.0;
    } else {
      r.hopf_computed = true;
      r.hopf_kind = hopf_kind_name(r.hopf.kind);
    }
    b.branch = continue_from_hopf(system, r.coords, start, o.first_excursion_m,
                                  continuation_for(o, "hopf", r.coords, r.profile_contact));
    if (r.profile_contact && !b.branch.orbits.empty())
      r.hopf_kind = b.branch.orbits.front().speed_m_per_s > r.linear.critical_speed_m_per_s
                        ? "supercritical"
                        : "subcritical";
  } catch (const std::exception& e) {
    b.error = e.what();
  }
  return b;
}

// The settled cycles' periods and principal maxima, as the progress line
// and a failure say them; with the "not periodic" verdict where they spread
// beyond kSettledCycleSpreadLimit.
std::string settled_cycles_text(const OrbitGuess& guess, bool irregular) {
  std::ostringstream settled;
  settled << std::setprecision(4) << "the settled run's last " << guess.cycles
          << " cycles: periods " << guess.period_min_s << "-" << guess.period_max_s
          << " s, excursions " << 1e3 * guess.excursion_min << "-" << 1e3 * guess.excursion_max
          << " mm";
  if (irregular)
    settled << ": not periodic to " << 100.0 * kSettledCycleSpreadLimit
            << " % (still settling, or hunting that is not periodic at this speed; `railstab "
               "simulate` shows which; a lower --cycle-speed may settle on a periodic cycle)";
  return settled.str();
}

BranchResult branch_from_time_domain(const Model& model, const FlowSystem& system,
                                     const Eigen::VectorXd& equilibrium, double speed,
                                     BifurcationResult& r, const BifurcationOptions& o) {
  BranchResult b;
  b.origin = "time_domain";
  std::string settled;  // the settled cycles, once the start is chosen
  bool irregular = false;
  try {
    // How periodic the settled run was: shooting needs a periodic orbit near
    // the guess, and a motion whose cycles differ (the S1002 vehicle above
    // 105 m/s: periods 2-8 % apart) has none, so Newton spends its
    // iterations, minutes of them, for nothing. Said before the first orbit,
    // and with its failure. The default start (not a speed the user gave)
    // then tries kDefaultStartLowering lower, up to kDefaultStartTries
    // times, within the range.
    OrbitGuess guess;
    for (int attempt = 0;; ++attempt) {
      const double V = r.cycle_speed_m_per_s;
      const EquilibriumResult eq = continue_equilibrium_in_speed(model, speed, equilibrium, V, {});
      if (o.progress) {
        std::ostringstream line;
        line << "  time domain: " << o.settle_time_s << " s at " << V << " m/s from a "
             << 1e3 * o.disturbance_m << " mm displacement";
        o.progress(line.str());
      }
      guess = settled_cycle_guess(model, V, eq.state, r.reduced_states, r.coords, o.disturbance_m,
                                  o.settle_time_s);
      irregular = guess.spread() > kSettledCycleSpreadLimit;
      const double lower = kDefaultStartLowering * V;
      if (!irregular || !r.cycle_speed_default || attempt + 1 >= kDefaultStartTries ||
          lower < o.linear.from_m_per_s)
        break;
      if (o.progress)
        o.progress("  time domain: " + settled_cycles_text(guess, false) +
                   ": not periodic; the default start tries a lower speed");
      r.cycle_speeds_not_periodic_m_per_s.push_back(V);
      r.cycle_speed_m_per_s = lower;
    }
    const double V = r.cycle_speed_m_per_s;
    settled = settled_cycles_text(guess, irregular);
    if (o.progress) o.progress("  time domain: " + settled + "; the first orbit from it");
    const ContinuationOptions c = continuation_for(o, "time-domain", r.coords, r.profile_contact);
    const PeriodicOrbit first = solve_periodic_orbit(
        system, r.coords, OrbitConstraint::fixed_speed(V), guess.start, guess.period_s, V, c.shooting);
    b.branch = continue_from_orbit(system, r.coords, first, o.cycle_speed_step_m_per_s, c);
  } catch (const std::exception& e) {
    b.error = e.what();
    if (irregular && !settled.empty()) b.error += " (" + settled + ")";
  }
  return b;
}

}  // namespace

std::string stable_bound_name(StableBound bound) {
  switch (bound) {
    case StableBound::none: return "none";
    case StableBound::fold: return "fold";
    case StableBound::hopf_point: return "hopf_point";
    case StableBound::period_doubling: return "period_doubling";
    case StableBound::torus: return "torus";
    case StableBound::speed_range_end: return "speed_range_end";
    case StableBound::branch_end: return "branch_end";
  }
  return "none";
}

namespace {

struct StableCandidate {
  double speed_m_per_s = 0.0;
  StableBound bound = StableBound::none;
};

// The lowest stable orbit of one branch and what lies next to it along the
// branch: the orbit's speed, or the speed of the bifurcation between it and
// an unstable neighbour (a fold: the parabola's vertex; a period doubling or
// torus point: interpolated in |mu| - 1).
StableCandidate lowest_stable_of(const BranchResult& b, const BifurcationResult& r) {
  StableCandidate c;
  const std::vector<PeriodicOrbit>& o = b.branch.orbits;
  int k = -1;
  for (size_t i = 0; i < o.size(); ++i)
    if (o[i].stable && (k < 0 || o[i].speed_m_per_s < o[size_t(k)].speed_m_per_s)) k = int(i);
  if (k < 0) return c;
  c.speed_m_per_s = o[size_t(k)].speed_m_per_s;
  // A bifurcation at or next to orbit k that lies below it.
  for (const OrbitBifurcation& f : b.branch.bifurcations) {
    if (std::abs(f.after_orbit - k) > 1 || !(f.speed_m_per_s <= c.speed_m_per_s)) continue;
    if (f.kind == OrbitBifurcationKind::fold) {
      c.speed_m_per_s = f.speed_m_per_s;
      c.bound = StableBound::fold;
      return c;
    }
    // A stability change between orbits after_orbit and after_orbit + 1, one of them k.
    if (f.after_orbit == k || f.after_orbit + 1 == k) {
      c.speed_m_per_s = f.speed_m_per_s;
      c.bound = f.kind == OrbitBifurcationKind::torus ? StableBound::torus
                                                      : StableBound::period_doubling;
      return c;
    }
  }
  const bool last = k + 1 == int(o.size());
  // The branch from a supercritical Hopf point: stable from its start. Its
  // first orbits lie within (a / coefficient)^2 of V_c, their multiplier
  // 1 - O(a^2) within the integration's error of 1, so one may be
  // classified unstable by noise: orbits before k count as the start when
  // every one is marginal (|mu| within kMarginalMultiplier of 1).
  if (b.origin == "hopf" && r.hopf_kind == "supercritical") {
    constexpr double kMarginalMultiplier = 1e-4;
    bool marginal_start = true;
    for (int i = 0; i < k; ++i)
      marginal_start = marginal_start &&
                       std::abs(std::abs(o[size_t(i)].critical_multiplier) - 1.0) < kMarginalMultiplier;
    if (marginal_start && o[size_t(k)].speed_m_per_s >= o.front().speed_m_per_s) {
      c.bound = StableBound::hopf_point;
      c.speed_m_per_s = o.front().speed_m_per_s;  // the branch's start, at V_c
      return c;
    }
  }
  if (last && (b.branch.stop_reason == "below the speed range" ||
               c.speed_m_per_s < r.from_m_per_s + 1e-9)) {
    c.bound = StableBound::speed_range_end;
    return c;
  }
  // Otherwise orbit k is an end of the branch (a turn of the speed between
  // stable neighbours is a fold, handled above): the branch's last orbit,
  // or the first of a time-domain branch.
  c.bound = StableBound::branch_end;
  return c;
}

}  // namespace

NonlinearCriticalSpeed nonlinear_critical_speed(const BifurcationResult& r) {
  NonlinearCriticalSpeed n;
  for (size_t i = 0; i < r.branches.size(); ++i) {
    const StableCandidate c = lowest_stable_of(r.branches[i], r);
    if (c.bound == StableBound::none) continue;
    if (n.branch < 0 || c.speed_m_per_s < n.lowest_stable_speed_m_per_s) {
      n.branch = int(i);
      n.bound = c.bound;
      n.lowest_stable_speed_m_per_s = c.speed_m_per_s;
    }
  }
  std::ostringstream e;
  e << std::fixed << std::setprecision(2);
  const double v = n.lowest_stable_speed_m_per_s;
  switch (n.bound) {
    case StableBound::none:
      e << "not found: no stable orbit on the computed branches";
      for (const BranchResult& b : r.branches)
        e << "; " << b.origin << " branch: "
          << (!b.error.empty() ? "not started (" + b.error + ")"
                               : std::to_string(b.branch.orbits.size()) + " orbits, none stable, stopped: " +
                                     b.branch.stop_reason);
      if (r.branches.empty()) e << " (no branch was started)";
      break;
    case StableBound::fold:
      e << v << " m/s, the fold where the stable hunting orbits of the " << r.branches[size_t(n.branch)].origin
        << " branch end: below it that branch has no orbit";
      break;
    case StableBound::hopf_point:
      e << v << " m/s, the first orbit of the branch from the supercritical Hopf point: the stable "
        << "hunting orbits grow from zero amplitude at the linear critical speed (on the computed "
        << "part of the branch; a fold at larger amplitude is not excluded)";
      break;
    case StableBound::period_doubling:
    case StableBound::torus:
      e << v << " m/s, where the " << r.branches[size_t(n.branch)].origin << " branch's stable orbits lose "
        << "stability by a " << (n.bound == StableBound::torus ? "torus (Neimark-Sacker)" : "period-doubling")
        << " bifurcation; below it the branch's orbits are unstable";
      break;
    case StableBound::speed_range_end:
      e << "not found: stable orbits reach the lower end of the speed range (" << v
        << " m/s); the nonlinear critical speed lies at or below it: lower --from";
      break;
    case StableBound::branch_end:
      e << "not found: the lowest stable orbit computed is at " << v << " m/s, where the "
        << r.branches[size_t(n.branch)].origin << " branch stopped ("
        << r.branches[size_t(n.branch)].branch.stop_reason
        << "); whether stable orbits exist below it is not known";
      break;
  }
  n.found = n.bound == StableBound::fold || n.bound == StableBound::hopf_point ||
            n.bound == StableBound::period_doubling || n.bound == StableBound::torus;
  if (n.found) n.speed_m_per_s = v;
  n.explanation = e.str();
  return n;
}

bool starts_a_branch(const Model& model, const BifurcationOptions& options) {
  return options.from_hopf || options.cycle_speed_m_per_s > 0.0 ||
         (options.default_cycle_start && has_profile_contact(model));
}

double cycle_speed_step_for(const std::string& direction, const std::string& option) {
  if (direction == "down") return -0.5;
  if (direction == "up") return 0.5;
  throw std::invalid_argument(option + ": expected 'down' or 'up', got '" + direction + "'");
}

BifurcationResult analyse_bifurcation(const Model& model, const Eigen::VectorXd& equilibrium,
                                      double speed_m_per_s, const BifurcationOptions& options) {
  if (!(options.linear.from_m_per_s < options.linear.to_m_per_s))
    throw std::invalid_argument("bifurcation analysis: the speed range must have from < to");
  if (!(options.max_amplitude_m > 0.0) || !std::isfinite(options.max_amplitude_m))
    throw std::invalid_argument("bifurcation analysis: the maximum amplitude must be positive");
  if (options.cycle_speed_m_per_s > 0.0 && !(options.cycle_speed_m_per_s >= options.linear.from_m_per_s &&
                                             options.cycle_speed_m_per_s <= options.linear.to_m_per_s))
    throw std::invalid_argument("bifurcation analysis: the cycle speed must lie in the speed range");
  if (!(options.cycle_speed_step_m_per_s != 0.0 && std::abs(options.cycle_speed_step_m_per_s) <= 5.0))
    throw std::invalid_argument(
        "bifurcation analysis: the time-domain branch's first speed step must be non-zero and at "
        "most 5 m/s");
  const std::clock_t cpu0 = std::clock();
  BifurcationResult r;
  r.from_m_per_s = options.linear.from_m_per_s;
  r.to_m_per_s = options.linear.to_m_per_s;
  r.max_amplitude_m = options.max_amplitude_m;
  if (options.progress) options.progress("linear critical speed");
  r.linear = find_critical_speed(model, equilibrium, speed_m_per_s, options.linear);
  r.hopf_assessment = assess_hopf(model, r.linear);
  r.profile_contact = has_profile_contact(model);
  const FlowSystem system = model_flow_system(model, 0.0, &r.reduced_states);
  r.state_names = system.state_names;
  r.coords = wheelset_orbit_coordinates(model, r.reduced_states, options.wheelset);
  r.amplitude_state_name = r.state_names[size_t(r.coords.amplitude_state)];
  for (const auto& b : model.bodies) {
    if (!b.wheelset()) continue;
    WheelsetOrbitStates w;
    w.name = b.name;
    for (size_t k = 0; k < r.state_names.size(); ++k) {
      if (r.state_names[k] == b.name + ".y_m") w.lateral_state = int(k);
      if (r.state_names[k] == b.name + ".yaw_rad") w.yaw_state = int(k);
    }
    r.wheelsets.push_back(w);
  }
  if (options.from_hopf) {
    if (r.linear.critical_speed_found && r.linear.loss.kind == LossOfStabilityKind::oscillatory_crossing) {
      if (options.progress) options.progress("branch from the Hopf point");
      r.branches.push_back(branch_from_hopf(model, system, r, options));
    } else {
      r.branches.push_back({"hopf", {}, r.linear.critical_speed_found
                                            ? "the stability is not lost by a complex pair "
                                              "crossing the imaginary axis: no Hopf point"
                                            : "no linear critical speed in the range: no Hopf "
                                              "point to start from"});
    }
  }
  r.cycle_speed_m_per_s = options.cycle_speed_m_per_s;
  r.cycle_branch_upwards = options.cycle_speed_step_m_per_s > 0.0;
  if (!(r.cycle_speed_m_per_s > 0.0) && r.profile_contact && options.default_cycle_start) {
    const bool hopf = r.linear.critical_speed_found &&
                      r.linear.loss.kind == LossOfStabilityKind::oscillatory_crossing;
    if (hopf) {
      r.cycle_speed_m_per_s =
          std::min(options.linear.to_m_per_s, kDefaultCycleSpeedRatio * r.linear.critical_speed_m_per_s);
      r.cycle_speed_default = true;
    } else {
      r.no_default_cycle_reason =
          "no time-domain branch: the default start lies just above the linear critical speed "
          "(an oscillatory crossing), and the range has none; give the cycle speed";
    }
  }
  if (r.cycle_speed_m_per_s > 0.0) {
    if (options.progress)
      options.progress(std::string("branch from a time-domain cycle") +
                       (r.cycle_speed_default ? " (default start on profile contact)" : ""));
    r.branches.push_back(branch_from_time_domain(model, system, equilibrium, speed_m_per_s, r, options));
  }
  r.nonlinear = nonlinear_critical_speed(r);
  r.cpu_seconds = double(std::clock() - cpu0) / CLOCKS_PER_SEC;
  return r;
}

}  // namespace railstab
