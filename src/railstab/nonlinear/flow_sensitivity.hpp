#pragma once
// The flow phi(t; x0, V) of a FlowSystem over a time span and its exact
// first derivatives (the variational equations):
//
//   x'   = f(x; V),                 x(0)   = x0,
//   X'   = J(x; V) X,               X(0)   = I      (X = d phi / d x0),
//   s_V' = J(x; V) s_V + df/dV,     s_V(0) = 0      (s_V = d phi / dV),
//
// J = df/dx exact (AD for the railway model). X(T) at the period T is the
// monodromy matrix of a periodic orbit (periodic_orbit.hpp). The state is
// integrated by CVODES (BDF, orders 1-5, dense Newton with J). X and s_V
// (FlowOptions::variational):
//  - alongside (the default): CVODES's forward sensitivity module,
//    staggered corrector:
//    the n + 1 sensitivity systems are linear and share the state's Newton
//    matrix, so each step costs one extra solve per sensitivity with the
//    factorisation already made, and J is evaluated once per step (cached on
//    (t, x): CVODES asks for the sensitivity right-hand sides repeatedly at
//    the same converged state). Every step of the state's carries them, and
//    their error test makes the state's steps finer too: the small orbits
//    near a smooth model's Hopf point, whose speed cubic terms set to
//    1e-6 m/s, need that accuracy (docs/nonlinear.md).
//  - second_pass: after the state, along its recorded steps, by a CVODES run
//    of their own at their own tolerances (variational_pass.hpp). Their steps
//    follow their tolerance, not the state's: on the S1002 thesis vehicle's
//    orbits the flow with derivatives costs 1.8 s instead of 3.3 s and gives
//    the same multipliers to 6 digits (docs/performance.md). The bifurcation
//    analysis uses it on profile contact (bifurcation_analysis.hpp).
// Either way the sensitivities are in the local error test with their own,
// looser tolerances: X(0) = I excites every mode, among them the nearly
// undamped Hertz contact modes (158 Hz, zeta 0.008 on the thesis vehicles)
// that the orbit itself leaves quiet; resolving those in X at the state's
// rtol 1e-8 took 20,800 steps per hunting period on the thesis vehicle. X at
// rtol 1e-5 costs a Newton iteration nothing in convergence (the Newton
// matrix only needs a few digits) and gives the multipliers to about 1e-5.
// Left out of the error test entirely (alongside, sensitivity_error_control
// false), X is not reliable: BDF of order 3-5 is not stable for those modes
// at the orbit's step sizes.
#include <railstab/nonlinear/flow_system.hpp>

#include <Eigen/Dense>

#include <stdexcept>
#include <vector>

namespace railstab {

struct FlowOptions {
  double relative_tolerance = 1e-8;
  double absolute_tolerance = 1e-11;
  bool sensitivities = true;              // X and s_V; false: the state only
  // How X and s_V are integrated. alongside: with the state, by CVODES's
  // sensitivity module (staggered corrector, the state's steps, an AD
  // Jacobian at every step). second_pass: after the state, along its
  // recorded steps, with steps of their own (variational_pass.hpp).
  enum class Variational { alongside, second_pass };
  Variational variational = Variational::alongside;
  bool sensitivity_error_control = true;  // alongside only (the second pass always controls them)
  double sensitivity_relative_tolerance = 1e-5;
  double sensitivity_absolute_tolerance = 1e-8;  // X entries are O(1) and larger
  int samples = 0;                        // states kept at samples + 1 equal intervals
  long max_steps = 200000;                // over the whole span
};

struct FlowResult {
  Eigen::VectorXd end_state;              // phi(T; x0, V)
  Eigen::MatrixXd state_sensitivity;      // X(T) = d phi / d x0 (empty without sensitivities)
  Eigen::VectorXd speed_sensitivity;      // s_V(T) = d phi / dV
  double sensitivity_relative_tolerance = 0.0;  // theirs (0 without sensitivities)
  std::vector<double> sample_times_s;     // 0, T/samples, ..., T
  std::vector<Eigen::VectorXd> samples;
  // Summed over the state and (second_pass) the variational equations' run.
  long steps = 0, rhs_evaluations = 0, jacobian_evaluations = 0, error_test_failures = 0;
  long variational_steps = 0;             // the second pass's steps (0 alongside)
  double cpu_seconds = 0.0;
};

// Throws std::runtime_error with CVODES's reason (and the time reached) when
// the integration fails, and std::invalid_argument for a non-positive span or
// a state of the wrong size.
FlowResult integrate_flow(const FlowSystem& system, const Eigen::VectorXd& x0,
                          double speed_m_per_s, double duration_s, const FlowOptions& options);

}  // namespace railstab
