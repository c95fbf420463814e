#include "equilibrium/equilibrium.hpp"

#include "linear/jacobian.hpp"
#include "model/equations_of_motion.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace railstab {

bool is_spin_angle(const Model& model, int k) {
  if (!model.is_position(k)) return false;
  const auto [b, c] = model.coordinate_of_state[k];
  return model.bodies[b].wheelset() && c == int(CoordinateIndex::pitch);
}

// Positions of non-spin coordinates, rates of spin coordinates, internal states.
std::vector<int> equilibrium_unknowns(const Model& model) {
  std::vector<int> idx;
  const int n = model.n_coordinates;
  for (int k = 0; k < n; ++k) idx.push_back(is_spin_angle(model, k) ? n + k : k);
  for (int k = 0; k < model.n_internal_states; ++k) idx.push_back(model.internal_state_offset() + k);
  return idx;
}

namespace {

// The residual: accelerations and internal-state rates.
Eigen::VectorXd residual(const Model& model, double speed, double t, const Eigen::VectorXd& x) {
  return rhs(model, speed, t, x).tail(model.state_size() - model.n_coordinates);
}

}  // namespace

Eigen::VectorXd nominal_state(const Model& model, double speed_m_per_s) {
  Eigen::VectorXd x = Eigen::VectorXd::Zero(model.state_size());
  const int n = model.n_coordinates;
  for (int k = 0; k < n; ++k) {
    const auto [b, c] = model.coordinate_of_state[k];
    x(k) = model.bodies[b].nominal_q(c);
    x(n + k) = model.bodies[b].steady_rate(c, speed_m_per_s);
  }
  return x;
}

Eigen::VectorXd initial_state(const Model& model, double speed_m_per_s) {
  Eigen::VectorXd x = nominal_state(model, speed_m_per_s);
  const int n = model.n_coordinates;
  for (int k = 0; k < n; ++k) {
    const auto [b, c] = model.coordinate_of_state[k];
    x(k) += model.bodies[b].initial_offset(c);
    x(n + k) += model.bodies[b].initial_rate(c);
  }
  return x;
}

Eigen::VectorXd lowered_nominal_state(const Model& model, double speed_m_per_s) {
  Eigen::VectorXd guess = nominal_state(model, speed_m_per_s);
  for (int k = 0; k < model.n_coordinates; ++k)
    if (model.coordinate_of_state[k].second == int(CoordinateIndex::z)) guess(k) -= 1e-4;
  return guess;
}

EquilibriumResult solve_equilibrium(const Model& model, double speed_m_per_s,
                                    const Eigen::VectorXd& guess,
                                    const EquilibriumOptions& options) {
  const int n = model.n_coordinates;
  const double t = options.time_s;
  const double V = speed_m_per_s;
  const std::vector<int> unknowns = equilibrium_unknowns(model);
  const int m = int(unknowns.size());
  Eigen::VectorXd x = guess;
  // Velocities other than spin rates are zero at an equilibrium.
  for (int k = 0; k < n; ++k)
    if (!is_spin_angle(model, k)) x(n + k) = 0.0;

  EquilibriumResult result;
  Eigen::VectorXd r = residual(model, V, t, x);
  for (int it = 0; it <= options.max_iterations; ++it) {
    Eigen::Index worst = 0;
    result.max_acceleration = m > 0 ? r.cwiseAbs().maxCoeff(&worst) : 0.0;
    result.iterations = it;
    result.worst_state = m > 0 ? model.state_name(n + int(worst)) : "";
    if (result.max_acceleration <= options.acceleration_tolerance) {
      result.state = x;
      return result;
    }
    if (it == options.max_iterations) break;
    const Eigen::MatrixXd jac = rhs_jacobian_ad(model, V, t, x);
    Eigen::MatrixXd J(m, m);
    for (int j = 0; j < m; ++j) J.col(j) = jac.block(n, unknowns[j], m, 1);
    // Minimum-norm step: a neutral direction (e.g. an unrestrained
    // longitudinal drift) does not stop the solve.
    const Eigen::VectorXd step = J.completeOrthogonalDecomposition().solve(-r);
    // Backtracking line search on the residual norm.
    double alpha = 1.0;
    const double r0 = r.norm();
    Eigen::VectorXd x_try = x;
    Eigen::VectorXd r_try;
    bool accepted = false;
    for (int ls = 0; ls < 30; ++ls) {
      x_try = x;
      for (int j = 0; j < m; ++j) x_try(unknowns[j]) += alpha * step(j);
      try {
        r_try = residual(model, V, t, x_try);
        if (r_try.norm() < (1.0 - 1e-4 * alpha) * r0) {
          accepted = true;
          break;
        }
      } catch (const std::runtime_error&) {
        // non-finite trial point: shorten the step
      }
      alpha *= 0.5;
    }
    if (!accepted) break;
    x = x_try;
    r = r_try;
  }
  std::ostringstream msg;
  msg << "no equilibrium found for scene '" << model.name << "' at speed " << V
      << " m/s: after " << result.iterations
      << " Newton iterations the largest acceleration residual is " << result.max_acceleration
      << " (state " << result.worst_state << ")";
  throw std::runtime_error(msg.str());
}

}  // namespace railstab
