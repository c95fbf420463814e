#include <railstab/verify/verification.hpp>

#include <railstab/stability/speed_analysis.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <numbers>
#include <stdexcept>

namespace railstab {

namespace {

// The lateral shift (any body) with the largest modal amplitude |v_k|: the
// signal to fit. Complex magnitudes, not real parts: the phase of an
// eigenvector is arbitrary, so a real part can hide the largest motion.
int lateral_signal_state(const Model& model, const LinearModel& lin, const Eigen::VectorXcd& v) {
  int signal = -1;
  double largest = 0.0;
  for (size_t i = 0; i < lin.kept_states.size(); ++i) {
    const int k = lin.kept_states[i];
    if (!model.is_position(k)) continue;
    if (model.coordinate_of_state[size_t(k)].second != int(CoordinateIndex::y)) continue;
    if (std::abs(v(Eigen::Index(i))) > largest) {
      largest = std::abs(v(Eigen::Index(i)));
      signal = k;
    }
  }
  if (signal < 0) throw std::runtime_error("verify: the chosen mode moves no body laterally");
  return signal;
}

// Any mode: the coordinate with the largest kinetic-energy share; its
// position state where the linear model keeps it, else its rate.
int dominant_signal_state(const Model& model, const LinearModel& lin, const ModeReport& mode) {
  auto kept = [&](int k) {
    return std::find(lin.kept_states.begin(), lin.kept_states.end(), k) != lin.kept_states.end();
  };
  for (const Participation& p : mode.participation)
    for (int k = 0; k < model.n_coordinates; ++k) {
      const auto [b, c] = model.coordinate_of_state[size_t(k)];
      if (c != p.coordinate || model.bodies[size_t(b)].name != p.body) continue;
      if (kept(k)) return k;
      if (kept(k + model.n_coordinates)) return k + model.n_coordinates;
    }
  throw std::runtime_error("verify: the chosen mode moves no coordinate of the linear model");
}

// Perturbation of the full state along the mode, rotated so the signal's
// component is real and positive (the response starts at a crest, the
// best-conditioned fit) and scaled so the signal starts at `amplitude`.
// No lateral shift has a larger modal amplitude, so none oscillates above
// it. (Scaling by the wheelsets alone would blow a car-body sway mode, in
// which they hardly move, up to centimetres of car-body motion.)
Eigen::VectorXd mode_perturbation(const Model& model, const LinearModel& lin,
                                  const Eigen::VectorXcd& v, int signal_state, double amplitude) {
  Eigen::Index s = 0;
  for (size_t i = 0; i < lin.kept_states.size(); ++i)
    if (lin.kept_states[i] == signal_state) s = Eigen::Index(i);
  const Eigen::VectorXcd rotated = v * (std::conj(v(s)) / std::abs(v(s)));
  Eigen::VectorXd dx = Eigen::VectorXd::Zero(model.state_size());
  for (size_t i = 0; i < lin.kept_states.size(); ++i)
    dx(lin.kept_states[i]) = rotated(Eigen::Index(i)).real();
  return dx * (amplitude / std::abs(v(s)));
}

}  // namespace

VerificationResult verify_least_stable_mode(const Model& model, double speed_m_per_s,
                                            const Eigen::VectorXd& equilibrium,
                                            const VerificationOptions& options) {
  VerificationResult out;
  out.speed_m_per_s = speed_m_per_s;
  StabilityOptions so;
  so.max_frequency_hz = options.hunting_band_hz;
  SpeedStability stability(model, equilibrium, speed_m_per_s, so);
  const StabilityPoint point = stability.at(speed_m_per_s);
  // Hunting is a lateral mode: a lightly damped longitudinal or vertical
  // mode (e.g. bogie longitudinal on the thesis vehicle at 100 m/s) may be
  // less damped but moves no wheelset laterally, so it cannot be fitted on
  // a lateral signal.
  const int chosen = options.lateral_modes_only
                         ? least_stable_lateral_mode(point.modes, options.hunting_band_hz)
                         : least_stable_lateral_mode(point.modes, options.hunting_band_hz, 0.0);
  if (chosen < 0)
    throw std::runtime_error(
        std::string("verify: no oscillatory ") +
        (options.lateral_modes_only ? "lateral mode (lateral share >= 0.5)" : "mode") +
        " at or below " + std::to_string(options.hunting_band_hz) + " Hz; nothing to fit" +
        (options.lateral_modes_only ? " (--any-mode fits the least stable mode of any kind)" : ""));
  const ModeReport& mode = point.modes[size_t(chosen)];
  out.eigenvalue = mode.eigenvalue;
  out.mode_name = mode.name;
  out.eigen_real_per_s = mode.eigenvalue.real();
  out.eigen_frequency_hz = mode.frequency_hz;

  const int signal_state = options.lateral_modes_only
                               ? lateral_signal_state(model, point.linear, mode.vector)
                               : dominant_signal_state(model, point.linear, mode);
  const Eigen::VectorXd dx =
      mode_perturbation(model, point.linear, mode.vector, signal_state, options.amplitude_m);
  out.signal = model.state_name(signal_state);

  const double period = 1.0 / mode.frequency_hz;
  double t_end = std::min(options.max_t_end_s, options.periods * period);
  if (mode.eigenvalue.real() > 0.0)
    t_end = std::min(t_end, options.settle_periods * period +
                                std::log(options.max_growth) / mode.eigenvalue.real());
  // The eigenvalue belongs to one steady state: the run must stay on the
  // uniform stretch of track (tangent or arc at constant cant) it starts on.
  double track_limit_s = std::numeric_limits<double>::infinity();
  std::string first_out;
  for (int b = 0; b < int(model.bodies.size()); ++b) {
    const double s0 = model.arc_length_of(b, 0.0, speed_m_per_s);
    const double t_b = (model.track.uniform_stretch_end_m(s0) - s0) / speed_m_per_s;
    if (t_b < track_limit_s) track_limit_s = t_b, first_out = model.bodies[size_t(b)].name;
  }
  if (track_limit_s < t_end) {
    // At least two periods to fit (a damped sinusoid sampled 50 times a
    // period is well determined by two).
    const double needed = (options.settle_periods + 2.0) * period;
    if (track_limit_s < needed) {
      std::ostringstream msg;
      msg << "verify: " << first_out << " leaves the uniform stretch of track (tangent or arc at "
          << "constant cant) it starts on after " << track_limit_s << " s at "
          << speed_m_per_s << " m/s, short of the " << needed
          << " s needed to settle and fit two periods of the mode; start inside a longer "
             "tangent or arc (--arc-length) or settle for fewer periods (--settle-periods)";
      throw std::runtime_error(msg.str());
    }
    t_end = track_limit_s;
    out.track_limited = true;
  }
  out.window_start_s = options.settle_periods * period;
  out.window_end_s = t_end;

  IntegrationOptions io;
  io.t_end_s = t_end;
  io.output_interval_s = period / 50.0;
  io.relative_tolerance = options.relative_tolerance;
  io.absolute_tolerance = options.absolute_tolerance;
  const Eigen::VectorXd x0 =
      options.initial_state ? *options.initial_state : Eigen::VectorXd(point.equilibrium.state + dx);
  if (x0.size() != point.equilibrium.state.size())
    throw std::invalid_argument("verify: the given initial state has the wrong size");
  out.trajectory = integrate(model, speed_m_per_s, x0, io);
  out.integration_seconds = out.trajectory.stats.wall_seconds;
  out.integration_cpu_seconds = out.trajectory.stats.cpu_seconds;
  out.integrator = integrator_name(io.kind);
  out.relative_tolerance = io.relative_tolerance;
  out.start = !options.initial_state ? "mode perturbation"
              : options.initial_state_description.empty() ? "given initial state"
                                                          : options.initial_state_description;
  if (!out.trajectory.stopped_early.empty()) {
    std::ostringstream msg;
    msg << "verify: the time integration stopped early: " << out.trajectory.stopped_early;
    // The usual reason: the steady state is unstable through a mode the
    // hunting band leaves out (the wheel-rail contact modes in curves).
    if (!point.unstable_above_band.empty()) {
      const ModeReport& m = point.modes[size_t(point.unstable_above_band.front())];
      msg << ". The steady state has " << point.unstable_above_band.size()
          << " unstable mode(s) above the hunting band, e.g. " << m.name << " at "
          << m.frequency_hz << " Hz growing at " << m.eigenvalue.real()
          << " 1/s, so the time domain leaves it (contacts.<name>.normal_damping_N_s_per_m "
             "damps the wheel-rail contact modes)";
    }
    throw std::runtime_error(msg.str());
  }

  const double y_eq = point.equilibrium.state(signal_state);
  for (size_t i = 0; i < out.trajectory.times_s.size(); ++i) {
    const double t = out.trajectory.times_s[i];
    if (t < out.window_start_s) continue;
    out.window_times.push_back(t);
    out.window_signal.push_back(out.trajectory.states[i](signal_state) - y_eq);
  }
  out.fit = fit_damped_sinusoid(out.window_times, out.window_signal, mode.eigenvalue.real(),
                                std::abs(mode.eigenvalue.imag()));
  out.fitted_real_per_s = out.fit.sigma_per_s;
  out.fitted_frequency_hz = out.fit.omega_rad_s / (2.0 * std::numbers::pi);
  out.real_difference_relative =
      std::abs(out.fitted_real_per_s - out.eigen_real_per_s) / std::abs(out.eigen_real_per_s);
  out.frequency_difference_relative =
      std::abs(out.fitted_frequency_hz - out.eigen_frequency_hz) / out.eigen_frequency_hz;

  // Integration error estimate: the same run at 100x tighter tolerances.
  IntegrationOptions tight = io;
  tight.relative_tolerance /= 100.0;
  tight.absolute_tolerance /= 100.0;
  const Trajectory ref = integrate(model, speed_m_per_s, x0, tight);
  out.reference_integration_seconds = ref.stats.wall_seconds;
  out.reference_integration_cpu_seconds = ref.stats.cpu_seconds;
  if (ref.times_s.size() != out.trajectory.times_s.size() || !ref.stopped_early.empty())
    throw std::runtime_error(
        "verify: the run at 100x tighter tolerances did not reach the same end (" +
        (ref.stopped_early.empty() ? std::string("it ended at t = ") + std::to_string(ref.times_s.back()) + " s"
                                   : ref.stopped_early) +
        "): the response is not resolved at the verify tolerances");
  double diff = 0.0, peak = 0.0;
  const size_t n = ref.states.size();
  for (size_t i = 0; i < n; ++i) {
    diff = std::max(diff, std::abs(ref.states[i](signal_state) - out.trajectory.states[i](signal_state)));
    peak = std::max(peak, std::abs(ref.states[i](signal_state) - y_eq));
  }
  out.integration_error_relative = peak > 0.0 ? diff / peak : 0.0;
  return out;
}

}  // namespace railstab
