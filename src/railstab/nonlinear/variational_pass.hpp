#pragma once
// The variational equations of a flow, integrated in a second pass after the
// state (FlowOptions::Variational::second_pass):
//
//   Y' = J(x(t); V) Y + [0 | df/dV(x(t); V)],   Y(0) = [I | 0],
//   Y = [X | s_V]  (n x (n + 1), X = d phi / d x0, s_V = d phi / dV),
//
// along the state's recorded trajectory x(t): CVODES's steps of the state's
// flow, (t_k, x_k, x'_k), joined by cubic Hermite interpolation,
//   x(t) = h00(s) x_k + h10(s) h x'_k + h01(s) x_k+1 + h11(s) h x'_k+1,
//   s = (t - t_k) / h, h = t_k+1 - t_k,
//   h00 = 2s^3 - 3s^2 + 1, h10 = s^3 - 2s^2 + s, h01 = 3s^2 - 2s^3, h11 = s^3 - s^2,
// x'_k the derivative of CVODES's interpolating polynomial at t_k. Its error,
// h^4 |x''''| / 384, is of the order of the state's own local error at the
// state's tolerance (rtol 1e-8 in the shooting), far below what J needs for
// X at its tolerance (1e-5).
//
// Why a second pass: integrated alongside the state by CVODES's sensitivity
// module, X takes the state's steps, which the state's tight tolerance
// chooses, and needs an AD Jacobian and n + 1 solves at every one of them
// (the flow then takes about 1.3 times the steps of the state alone, with
// a Jacobian at each instead of one per 58: docs/performance.md). On its
// own, X's steps follow X's own, looser tolerance. CVODES (BDF, orders 1-5) with
// the error test on every entry of Y at sensitivity_relative_tolerance and
// sensitivity_absolute_tolerance; its Newton matrix is I - gamma J in every
// column, so one n x n LU serves all n + 1 columns in a blocked solve
// (integrate/eigen_dense_solver.hpp). J and df/dV are evaluated once per time
// CVODES asks for (the Newton iterations of a step share it).
#include <railstab/nonlinear/flow_sensitivity.hpp>
#include <railstab/nonlinear/flow_system.hpp>

#include <Eigen/Dense>

#include <vector>

namespace railstab {

// A state flow's steps, and the Hermite interpolant through them.
struct RecordedTrajectory {
  std::vector<double> times_s;         // increasing, from 0 to the span's end
  std::vector<Eigen::VectorXd> states, rates;
  // x(t) for t in [times_s.front(), times_s.back()] (clamped outside).
  void state_at(double t_s, Eigen::VectorXd& out) const;
};

struct VariationalResult {
  Eigen::MatrixXd state_sensitivity;   // X(T)
  Eigen::VectorXd speed_sensitivity;   // s_V(T)
  long steps = 0, rhs_evaluations = 0, jacobian_evaluations = 0, error_test_failures = 0;
};

// Y(T) along `trajectory` (T = trajectory.times_s.back()) at the speed V, at
// the options' sensitivity tolerances. Throws std::runtime_error with
// CVODES's reason when the integration fails.
VariationalResult integrate_variational_equations(const FlowSystem& system,
                                                  const RecordedTrajectory& trajectory,
                                                  double speed_m_per_s, const FlowOptions& options);

}  // namespace railstab
