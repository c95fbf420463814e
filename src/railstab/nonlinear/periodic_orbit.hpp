#pragma once
// Periodic orbits of x' = f(x; V) by single shooting, and their Floquet
// multipliers.
//
// Unknowns z = (x0, T, V): the orbit's start, its period and the speed.
// Equations (n + 2):
//   phi(T; x0, V) - x0 = 0                 periodicity (n),
//   x0[section_state] = 0                   the start lies on the Poincare
//                                           section where the leading
//                                           wheelset's lateral velocity is 0
//                                           (its lateral excursion at an
//                                           extremum): fixes the phase,
//   c_V (V - V_ref) + c_a (x0[amplitude_state] - a_ref) = 0
//                                           one linear constraint in the
//                                           (speed, excursion) plane: fixed
//                                           speed (c = (1, 0)), fixed
//                                           excursion (c = (0, 1)), or the
//                                           pseudo-arclength condition of
//                                           the continuation.
// Newton's matrix, exact with the flow's sensitivities (flow_sensitivity.hpp):
//   [ M - I   f(phi)   d phi/dV ]
//   [ e_s^T     0         0     ]
//   [ c_a e_a^T 0        c_V    ]
// M = d phi(T)/d x0 is the monodromy matrix; its eigenvalues are the Floquet
// multipliers. One is 1 (the flow direction f(x0), the "trivial" one); the
// orbit is stable when every other has modulus < 1. At a fold of the branch
// a second multiplier passes +1, at a period doubling one passes -1, at a
// torus (Neimark-Sacker) point a complex pair crosses the unit circle.
//
// Why single shooting: the railway model's stiff modes (Hertz contact near
// 200 Hz, creep damping to -4e3 1/s) give multipliers ~ exp(-4e3 T) ~ 0,
// harmless to M - I; the hunting orbit's unstable multipliers are modest
// (the unstable branch of a subcritical Hopf), so one arc over the period
// keeps M - I well conditioned. The flow's BDF handles the stiffness and the
// C1 kinks of a tabulated profile contact; a collocation mesh would have to
// resolve both and be n x (mesh points) in size.
#include <railstab/nonlinear/flow_sensitivity.hpp>
#include <railstab/nonlinear/flow_system.hpp>

#include <Eigen/Dense>

#include <complex>
#include <string>
#include <vector>

namespace railstab {

struct OrbitCoordinates {
  int section_state = -1;    // velocity state set to 0 at the start
  int amplitude_state = -1;  // position state whose start value the constraint uses
};

// The third equation: c_V (V - V_ref) + c_a (x0[amplitude_state] - a_ref) = 0.
struct OrbitConstraint {
  double speed_coefficient = 1.0, amplitude_coefficient = 0.0;
  double reference_speed_m_per_s = 0.0, reference_amplitude = 0.0;
  static OrbitConstraint fixed_speed(double V) { return {1.0, 0.0, V, 0.0}; }
  static OrbitConstraint fixed_excursion(double a) { return {0.0, 1.0, 0.0, a}; }
};

struct ShootingOptions {
  FlowOptions flow;             // the flow's tolerances (rtol 1e-8, atol 1e-11)
  int max_newton_iterations = 12;
  // Converged when the Newton step is below these (states: weighted RMS with
  // weights 1 / (rtol (|x0_k| + range_k) + atol), range_k the state's
  // peak-to-peak on the orbit; period and speed relative).
  double newton_relative_tolerance = 1e-7;
  double newton_absolute_tolerance = 1e-10;
  int samples_per_period = 200;  // for the amplitudes
  // A multiplier counts as on the unit circle within this of modulus 1.
  double multiplier_tolerance = 1e-6;
};

struct PeriodicOrbit {
  double speed_m_per_s = 0.0;
  double period_s = 0.0;
  Eigen::VectorXd start;                   // x0, on the section
  Eigen::MatrixXd monodromy;               // d phi(T)/d x0
  Eigen::VectorXcd floquet_multipliers;    // largest modulus first
  int trivial_multiplier = -1;             // index of the multiplier of f(x0)
  double trivial_multiplier_error = 0.0;   // |mu_trivial - 1|
  std::complex<double> critical_multiplier;  // the largest non-trivial one
  bool stable = false;                     // every non-trivial |mu| < 1
  Eigen::VectorXd range_min, range_max;    // each state's extremes on the orbit
  Eigen::VectorXd amplitude;               // (max - min) / 2 per state
  std::vector<double> sample_times_s;      // one period, samples_per_period + 1 points
  std::vector<Eigen::VectorXd> samples;
  int newton_iterations = 0;
  double periodicity_residual = 0.0;       // max |phi(T) - x0| / max amplitude, at the last flow
  long integration_steps = 0, jacobian_evaluations = 0;  // summed over the Newton iterations
  double cpu_seconds = 0.0;
};

struct ShootingFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Newton from the guess (x0, T, V). Throws ShootingFailure when Newton does
// not converge (or the flow fails) within max_newton_iterations.
PeriodicOrbit solve_periodic_orbit(const FlowSystem& system, const OrbitCoordinates& coords,
                                   const OrbitConstraint& constraint, Eigen::VectorXd x0,
                                   double period_s, double speed_m_per_s,
                                   const ShootingOptions& options = {});

// Floquet multipliers of `orbit.monodromy` into the orbit's fields (the
// trivial one is the eigenvalue whose eigenvector is most nearly parallel to
// f(x0) among those near 1). `flow_direction` = f(x0).
void classify_floquet_multipliers(PeriodicOrbit& orbit, const Eigen::VectorXd& flow_direction,
                                  double multiplier_tolerance);

// An orbit from a time-domain run: the state where the last full period
// begins (a maximum of x[amplitude_state], x[section_state] falling through
// 0, interpolated between samples) and the period from the last two such
// crossings. Throws std::runtime_error when the run holds fewer than two.
struct OrbitGuess {
  Eigen::VectorXd start;
  double period_s = 0.0;
};
OrbitGuess orbit_guess_from_samples(const std::vector<double>& times_s,
                                    const std::vector<Eigen::VectorXd>& states,
                                    const OrbitCoordinates& coords);

}  // namespace railstab
