#include <railstab/nonlinear/bifurcation_analysis.hpp>

#include <railstab/equilibrium/speed_continuation.hpp>
#include <railstab/integrate/integrator.hpp>
#include <railstab/nonlinear/hopf_assessment.hpp>

#include <cmath>
#include <ctime>
#include <sstream>

namespace railstab {

namespace {

ContinuationOptions continuation_for(const BifurcationOptions& o, const std::string& origin) {
  ContinuationOptions c = o.continuation;
  c.min_speed_m_per_s = o.linear.from_m_per_s;
  c.max_speed_m_per_s = o.linear.to_m_per_s;
  c.max_amplitude = o.max_amplitude_m;
  if (o.progress)
    c.progress = [progress = o.progress, origin](int orbits, double V, double amplitude) {
      std::ostringstream line;
      line << "  " << origin << " branch: orbit " << orbits << " at " << V << " m/s, amplitude "
           << 1e3 * amplitude << " mm";
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
                                  continuation_for(o, "hopf"));
    if (r.profile_contact && !b.branch.orbits.empty())
      r.hopf_kind = b.branch.orbits.front().speed_m_per_s > r.linear.critical_speed_m_per_s
                        ? "supercritical"
                        : "subcritical";
  } catch (const std::exception& e) {
    b.error = e.what();
  }
  return b;
}

BranchResult branch_from_time_domain(const Model& model, const FlowSystem& system,
                                     const Eigen::VectorXd& equilibrium, double speed,
                                     BifurcationResult& r, const BifurcationOptions& o) {
  BranchResult b;
  b.origin = "time_domain";
  const double V = o.cycle_speed_m_per_s;
  try {
    const EquilibriumResult eq = continue_equilibrium_in_speed(model, speed, equilibrium, V, {});
    Eigen::VectorXd x = eq.state;
    x(r.reduced_states[size_t(r.coords.amplitude_state)]) += o.disturbance_m;
    IntegrationOptions io;
    io.t_end_s = o.settle_time_s;
    io.output_interval_s = 1e-3;
    if (o.progress) {
      std::ostringstream line;
      line << "  time domain: " << o.settle_time_s << " s at " << V << " m/s from a "
           << 1e3 * o.disturbance_m << " mm displacement";
      o.progress(line.str());
    }
    const Trajectory run = integrate(model, V, x, io);
    if (!run.stopped_early.empty())
      throw std::runtime_error("the time-domain run stopped early: " + run.stopped_early);
    // The last second (or half the run): the settled motion.
    const double from = std::max(0.5 * o.settle_time_s, o.settle_time_s - 1.0);
    std::vector<double> times;
    std::vector<Eigen::VectorXd> states;
    double lo = 1e300, hi = -1e300;
    for (size_t k = 0; k < run.times_s.size(); ++k)
      if (run.times_s[k] >= from) {
        times.push_back(run.times_s[k]);
        states.push_back(reduce_state(r.reduced_states, run.states[k]));
        lo = std::min(lo, states.back()(r.coords.amplitude_state));
        hi = std::max(hi, states.back()(r.coords.amplitude_state));
      }
    if (!(hi - lo > 2e-6)) {
      std::ostringstream msg;
      msg << "no self-sustained oscillation at " << V << " m/s: the run from a "
          << 1e3 * o.disturbance_m << " mm displacement decayed to " << 0.5e3 * (hi - lo)
          << " mm peak after " << o.settle_time_s << " s";
      throw std::runtime_error(msg.str());
    }
    const OrbitGuess guess = orbit_guess_from_samples(times, states, r.coords);
    const ContinuationOptions c = continuation_for(o, "time-domain");
    const PeriodicOrbit first = solve_periodic_orbit(system, r.coords, OrbitConstraint::fixed_speed(V),
                                                     guess.start, guess.period_s, V, c.shooting);
    b.branch = continue_from_orbit(system, r.coords, first, o.cycle_speed_step_m_per_s, c);
  } catch (const std::exception& e) {
    b.error = e.what();
  }
  return b;
}

}  // namespace

BifurcationResult analyse_bifurcation(const Model& model, const Eigen::VectorXd& equilibrium,
                                      double speed_m_per_s, const BifurcationOptions& options) {
  const std::clock_t cpu0 = std::clock();
  BifurcationResult r;
  r.linear = find_critical_speed(model, equilibrium, speed_m_per_s, options.linear);
  r.profile_contact = has_profile_contact(model);
  const FlowSystem system = model_flow_system(model, 0.0, &r.reduced_states);
  r.state_names = system.state_names;
  r.coords = wheelset_orbit_coordinates(model, r.reduced_states, options.wheelset);
  if (options.from_hopf) {
    if (r.linear.critical_speed_found) {
      if (options.progress) options.progress("branch from the Hopf point");
      r.branches.push_back(branch_from_hopf(model, system, r, options));
    } else {
      r.branches.push_back({"hopf", {}, "no linear critical speed in the range: no Hopf point to start from"});
    }
  }
  if (options.cycle_speed_m_per_s > 0.0) {
    if (options.progress) options.progress("branch from a time-domain cycle");
    r.branches.push_back(branch_from_time_domain(model, system, equilibrium, speed_m_per_s, r, options));
  }
  for (const BranchResult& b : r.branches) {
    const double v = lowest_stable_speed(b.branch);
    if (!std::isnan(v) && (std::isnan(r.nonlinear_critical_speed_m_per_s) ||
                           v < r.nonlinear_critical_speed_m_per_s))
      r.nonlinear_critical_speed_m_per_s = v;
  }
  r.cpu_seconds = double(std::clock() - cpu0) / CLOCKS_PER_SEC;
  return r;
}

}  // namespace railstab
