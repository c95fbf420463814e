#pragma once
// Time-domain verification of a linear stability prediction: start the
// nonlinear model at the steady state plus a small perturbation along the
// least stable mode, integrate, fit a damped sinusoid to the response of the
// body that moves most, and compare its rate and frequency with the
// eigenvalue. The same model serves both, so agreement checks the
// linearisation and the integration, not two models against each other.
#include <railstab/integrate/integrator.hpp>
#include <railstab/model/model.hpp>
#include <railstab/verify/damped_sinusoid_fit.hpp>

#include <complex>
#include <optional>
#include <string>

namespace railstab {

struct VerificationOptions {
  double amplitude_m = 1e-4;    // signal's value at t = 0 (lateral modes: largest lateral shift)
  double periods = 15.0;        // simulated length in periods of the mode
  double settle_periods = 2.0;  // skipped before the fit window
  double max_t_end_s = 40.0;
  double max_growth = 20.0;     // a growing response is fitted until this factor
  double relative_tolerance = 1e-7;
  double absolute_tolerance = 1e-11;
  double hunting_band_hz = 20.0;
  // false: the least stable oscillatory mode in the band whatever its
  // direction (e.g. a wheelset spin mode in a curve on real profiles), fitted
  // on the coordinate with the largest share of its kinetic energy (its
  // position, or its rate where the position is not a state of the linear
  // model: a wheelset's spin angle); amplitude_m is then in that
  // coordinate's unit (m, rad or rad/s). true: lateral modes only (share of
  // lateral-plane kinetic energy >= 0.5), fitted on a lateral shift.
  bool lateral_modes_only = true;
  // A given start (e.g. the scene's initial offsets on the equilibrium)
  // instead of the perturbation along the mode; the signal is still the
  // lateral shift the mode moves most, fitted after settle_periods.
  std::optional<Eigen::VectorXd> initial_state;
  // What that start is, for the report (default "given initial state").
  std::string initial_state_description;
};

struct VerificationResult {
  double speed_m_per_s = 0.0;
  std::complex<double> eigenvalue;
  std::string mode_name;
  std::string signal;  // state whose response is fitted, e.g. "wheelset1.y_m"
  double window_start_s = 0.0, window_end_s = 0.0;
  // The window was cut short where the first body leaves the uniform track.
  bool track_limited = false;
  DampedSinusoid fit;
  double eigen_real_per_s = 0.0, eigen_frequency_hz = 0.0;
  double fitted_real_per_s = 0.0, fitted_frequency_hz = 0.0;
  double real_difference_relative = 0.0, frequency_difference_relative = 0.0;
  // Integration error of the fitted signal, from a run at 100x tighter
  // tolerances, relative to the signal's largest magnitude.
  double integration_error_relative = 0.0;
  double integration_seconds = 0.0;      // wall time of the run
  double integration_cpu_seconds = 0.0;  // its process CPU time
  // The run at 100x tighter tolerances that gives the error estimate: it
  // costs most of a verify (e.g. 445 s CPU beside 8.5 s wall for the run).
  double reference_integration_seconds = 0.0;
  double reference_integration_cpu_seconds = 0.0;
  std::string integrator;
  double relative_tolerance = 0.0;  // of the run (the error run is 100x tighter)
  std::string start;  // "mode perturbation" or "given initial state"
  Trajectory trajectory;
  std::vector<double> window_times, window_signal;
};

VerificationResult verify_least_stable_mode(const Model& model, double speed_m_per_s,
                                            const Eigen::VectorXd& equilibrium,
                                            const VerificationOptions& options = {});

}  // namespace railstab
