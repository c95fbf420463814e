#include <railstab/nonlinear/model_orbits.hpp>

#include <railstab/core/coordinates.hpp>

#include <algorithm>
#include <sstream>
#include <stdexcept>

namespace railstab {

OrbitCoordinates wheelset_orbit_coordinates(const Model& model,
                                            const std::vector<int>& reduced_states,
                                            const std::string& wheelset_name) {
  int body = -1;
  for (size_t b = 0; b < model.bodies.size(); ++b)
    if (model.bodies[b].wheelset() && (wheelset_name.empty() || model.bodies[b].name == wheelset_name)) {
      body = int(b);
      break;
    }
  if (body < 0)
    throw std::invalid_argument(wheelset_name.empty()
                                    ? "periodic orbits: the model has no wheelset"
                                    : "periodic orbits: no wheelset named '" + wheelset_name + "'");
  int position = -1;
  for (int k = 0; k < model.n_coordinates; ++k)
    if (model.coordinate_of_state[size_t(k)] == std::pair<int, int>{body, int(CoordinateIndex::y)})
      position = k;
  if (position < 0)
    throw std::invalid_argument("periodic orbits: the lateral displacement of " +
                                model.bodies[size_t(body)].name + " is not a free coordinate");
  auto reduced_index = [&](int full) {
    const auto it = std::find(reduced_states.begin(), reduced_states.end(), full);
    if (it == reduced_states.end()) throw std::invalid_argument("periodic orbits: state not in the reduced state");
    return int(it - reduced_states.begin());
  };
  OrbitCoordinates c;
  c.amplitude_state = reduced_index(position);
  c.section_state = reduced_index(model.n_coordinates + position);
  return c;
}

HopfStart model_hopf_start(const Model& model, const std::vector<int>& reduced_states,
                           const Eigen::VectorXd& equilibrium_full, const HopfCriticality& hopf,
                           const OrbitCoordinates& coords) {
  HopfStart s;
  s.equilibrium = reduce_state(reduced_states, equilibrium_full);
  s.critical_speed_m_per_s = hopf.critical_speed_m_per_s;
  s.eigenvalue = hopf.hopf.eigenvalue;
  s.eigenvector = Eigen::VectorXcd::Zero(Eigen::Index(reduced_states.size()));
  for (size_t i = 0; i < reduced_states.size(); ++i) {
    const auto it = std::find(hopf.kept_states.begin(), hopf.kept_states.end(), reduced_states[i]);
    if (it == hopf.kept_states.end())
      throw std::invalid_argument("periodic orbits: state " + model.state_name(reduced_states[i]) +
                                  " was removed by the linearisation; its mode shape is unknown");
    s.eigenvector(Eigen::Index(i)) = hopf.hopf.q(Eigen::Index(it - hopf.kept_states.begin()));
  }
  s.cycle_side = hopf.cycle_side;
  s.amplitude_per_sqrt_speed = 0.0;
  const int full_amplitude_state = reduced_states[size_t(coords.amplitude_state)];
  const auto it = std::find(hopf.kept_states.begin(), hopf.kept_states.end(), full_amplitude_state);
  if (it != hopf.kept_states.end() && hopf.amplitude_per_sqrt_speed.size() > 0)
    s.amplitude_per_sqrt_speed = hopf.amplitude_per_sqrt_speed(Eigen::Index(it - hopf.kept_states.begin()));
  return s;
}

}  // namespace railstab

namespace railstab {

OrbitGuess settled_cycle_guess(const Model& model, double speed_m_per_s,
                               const Eigen::VectorXd& equilibrium_full,
                               const std::vector<int>& reduced_states, const OrbitCoordinates& coords,
                               double disturbance_m, double settle_time_s, IntegrationOptions options) {
  Eigen::VectorXd x = equilibrium_full;
  x(reduced_states[size_t(coords.amplitude_state)]) += disturbance_m;
  options.t_start_s = 0.0;
  options.t_end_s = settle_time_s;
  options.output_interval_s = std::min(options.output_interval_s, 1e-3);
  const Trajectory run = integrate(model, speed_m_per_s, x, options);
  if (!run.stopped_early.empty())
    throw std::runtime_error("the time-domain run stopped early: " + run.stopped_early);
  // The settled motion: the second half of the run, whose complete cycles
  // (15-20 on the S1002 vehicle) show whether it is periodic; whether it has
  // decayed is judged on its last second.
  std::vector<double> times;
  std::vector<Eigen::VectorXd> states;
  const double last_second = std::max(0.5 * settle_time_s, settle_time_s - 1.0);
  double lo = 1e300, hi = -1e300;
  for (size_t k = 0; k < run.times_s.size(); ++k) {
    if (run.times_s[k] < 0.5 * settle_time_s) continue;
    times.push_back(run.times_s[k]);
    states.push_back(reduce_state(reduced_states, run.states[k]));
    if (run.times_s[k] < last_second) continue;
    lo = std::min(lo, states.back()(coords.amplitude_state));
    hi = std::max(hi, states.back()(coords.amplitude_state));
  }
  if (!(hi - lo > 2e-6)) {
    std::ostringstream msg;
    msg << "no self-sustained oscillation at " << speed_m_per_s << " m/s: the run from a "
        << 1e3 * disturbance_m << " mm displacement decayed to " << 0.5e3 * (hi - lo)
        << " mm peak after " << settle_time_s << " s";
    throw std::runtime_error(msg.str());
  }
  return orbit_guess_from_samples(times, states, coords);
}

}  // namespace railstab
