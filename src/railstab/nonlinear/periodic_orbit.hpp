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
// Damped Newton: the step dz is scaled by the largest lambda in 1, 1/2, ...,
// 2^-max_step_halvings such that |lambda dT| <= max_relative_period_step T,
// |lambda dV| <= max_speed_step_m_per_s, the flow from the new point exists
// (a full step from a flange-hunting cycle can take a wheel outside its
// contact table, where the flow stops) and, while the step is large
// (step norm above full_step_below_step_norm, in units of the convergence
// tolerance), the weighted RMS of the periodicity residual falls:
//   ||r(z + lambda dz)||_w < (1 - 1e-4 lambda) ||r(z)||_w,
// w_k = 1 / (rtol_newton (|x0_k| + range_k) + atol_newton). Near convergence
// the residual is the flow's own error, so the full step is taken there.
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
#include <functional>
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

// One Newton iteration of an orbit, as it is taken (for progress).
struct ShootingIteration {
  int iteration = 0;
  double step_norm = 0.0;       // the Newton step in units of the tolerance
  double speed_m_per_s = 0.0, period_s = 0.0;  // where the iteration starts
  bool exact_derivatives = false;  // false: a chord step (an earlier matrix)
  double cpu_seconds = 0.0;     // this orbit's so far
};

struct ShootingOptions {
  FlowOptions flow;             // the flow's tolerances (rtol 1e-8, atol 1e-11)
  int max_newton_iterations = 20;  // chord iterations included
  // The damping of a Newton step (see the header comment).
  double max_relative_period_step = 0.25;
  double max_speed_step_m_per_s = 5.0;
  double full_step_below_step_norm = 1e3;
  int max_step_halvings = 6;
  // Chord iterations: with an earlier orbit's derivatives (chord_from, a
  // neighbour on the branch), Newton's matrix is kept and the flows between
  // carry the state only (the variational equations make a flow ~25 times
  // dearer: one AD Jacobian per step); the exact derivatives are taken again
  // when a step shrinks by less than chord_contraction, and at the converged
  // orbit (its multipliers).
  bool chord_iterations = true;
  double chord_contraction = 0.3;
  // The variational equations' rtol in flows that only feed Newton's matrix
  // where they are integrated in a second pass
  // (FlowOptions::Variational::second_pass): Newton's matrix needs a few
  // digits, and the state's flow does not depend on it. Alongside, their
  // error test also sets the state's steps, so they keep the flow's.
  double newton_matrix_sensitivity_tolerance = 1e-3;
  // Converged when the Newton step is below these (states: weighted RMS with
  // weights 1 / (rtol (|x0_k| + range_k) + atol), range_k the state's
  // peak-to-peak on the orbit; period and speed relative).
  double newton_relative_tolerance = 1e-7;
  double newton_absolute_tolerance = 1e-10;
  // Also converged when the step norm is below this and no longer halves
  // from one iteration to the next (the flow's error is the floor).
  double stagnation_step_norm = 10.0;
  int samples_per_period = 200;  // for the amplitudes
  // A multiplier counts as on the unit circle within this of modulus 1.
  double multiplier_tolerance = 1e-6;
  // Called once per Newton iteration, after its step is known: an orbit in
  // flange contact takes up to minutes, so a caller can report within one
  // (bifurcation_analysis.cpp throttles it to a line per 10 s).
  std::function<void(const ShootingIteration&)> iteration_progress;
};

struct PeriodicOrbit {
  double speed_m_per_s = 0.0;
  double period_s = 0.0;
  Eigen::VectorXd start;                   // x0, on the section
  Eigen::MatrixXd monodromy;               // d phi(T)/d x0
  Eigen::VectorXd speed_sensitivity;       // d phi(T)/dV at x0
  Eigen::VectorXd flow_at_start;           // f(x0; V)
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
  int damped_steps = 0;                    // Newton steps shortened (lambda < 1)
  int sensitivity_flows = 0;               // flows with the variational equations
  double periodicity_residual = 0.0;       // max |phi(T) - x0| / max amplitude, at the last flow
  long integration_steps = 0, jacobian_evaluations = 0;  // summed over the Newton iterations
  double cpu_seconds = 0.0;
};

struct ShootingFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Newton from the guess (x0, T, V). Throws ShootingFailure when Newton does
// not converge (or the flow fails) within max_newton_iterations. With
// `chord_from` (an orbit near the guess), chord iterations on its derivatives
// first (ShootingOptions::chord_iterations).
PeriodicOrbit solve_periodic_orbit(const FlowSystem& system, const OrbitCoordinates& coords,
                                   const OrbitConstraint& constraint, Eigen::VectorXd x0,
                                   double period_s, double speed_m_per_s,
                                   const ShootingOptions& options = {},
                                   const PeriodicOrbit* chord_from = nullptr);

// The orbit's first-order change with the speed at fixed section: (dx0/dV,
// dT/dV) from the periodicity and section rows of Newton's matrix,
//   [ M - I   f(x0) ] [ dx0/dV ]     [ d phi/dV ]
//   [ e_s^T     0   ] [ dT/dV  ] = - [    0     ],
// exact at the converged orbit (f(phi(T)) = f(x0)); singular at a fold.
// The predictor of an orbit at a nearby speed.
struct OrbitSpeedTangent {
  Eigen::VectorXd start_per_speed;
  double period_per_speed = 0.0;
};
OrbitSpeedTangent orbit_speed_tangent(const PeriodicOrbit& orbit, const OrbitCoordinates& coords);

// Floquet multipliers of `orbit.monodromy` into the orbit's fields (the
// trivial one is the eigenvalue whose eigenvector is most nearly parallel to
// f(x0) among those near 1). `flow_direction` = f(x0).
void classify_floquet_multipliers(PeriodicOrbit& orbit, const Eigen::VectorXd& flow_direction,
                                  double multiplier_tolerance);

// An orbit from a time-domain run: the state at the principal maximum of
// x[amplitude_state] in the run's last complete cycle, and the period from
// that maximum to the one before. A cycle runs from one upward crossing of
// the mid-range (max + min) / 2 of x[amplitude_state] to the next; its
// principal maximum is the highest of its maxima (x[section_state], the
// rate, falling through 0; interpolated between samples). Flange hunting
// has a second, lower maximum in each cycle where the flange throws the
// wheelset back (the S1002 vehicle above 105 m/s): counting every maximum
// would give a period of a bounce, not of the cycle. The periods and the
// principal maxima of all complete cycles measure how periodic the motion
// was. Throws std::runtime_error when the run holds fewer than two cycles.
struct OrbitGuess {
  Eigen::VectorXd start;
  double period_s = 0.0;
  int cycles = 0;               // complete cycles in the samples
  double period_min_s = 0.0, period_max_s = 0.0;  // between successive principal maxima
  double excursion_min = 0.0, excursion_max = 0.0;  // the principal maxima of x[amplitude_state]
  double half_range = 0.0;      // (max - min) / 2 of x[amplitude_state] over the samples
  // The larger of the periods' spread (max - min) over their mean and the
  // principal maxima's spread over half_range: 0 for a periodic motion
  // sampled finely.
  double spread() const;
};
OrbitGuess orbit_guess_from_samples(const std::vector<double>& times_s,
                                    const std::vector<Eigen::VectorXd>& states,
                                    const OrbitCoordinates& coords);

}  // namespace railstab
