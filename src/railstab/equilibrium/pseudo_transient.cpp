#include <railstab/equilibrium/pseudo_transient.hpp>

#include <railstab/equilibrium/equilibrium.hpp>
#include <railstab/linear/jacobian.hpp>
#include <railstab/model/equations_of_motion.hpp>
#include <railstab/linalg/dense_decompositions.hpp>

#include <algorithm>
#include <cmath>
#include <new>
#include <vector>

namespace railstab {

PseudoTransientResult settle_by_pseudo_transient(const Model& model, double speed_m_per_s,
                                                 const Eigen::VectorXd& start,
                                                 const PseudoTransientOptions& options) {
  const double V = speed_m_per_s;
  const double t = options.time_s;
  // Every state but the spin angles, as rows of f and columns of x alike.
  std::vector<int> states;
  for (int k = 0; k < model.state_size(); ++k)
    if (!is_spin_angle(model, k)) states.push_back(k);
  const int m = int(states.size());
  const RhsJacobianPlan plan = plan_rhs_jacobian(model, states, states);

  PseudoTransientResult out;
  out.state = start;
  // f on the chosen rows; empty optional (nullopt-like: false) where the
  // model cannot be evaluated or returns non-finite numbers.
  auto rates = [&](const Eigen::VectorXd& x, Eigen::VectorXd& r) -> bool {
    try {
      const Eigen::VectorXd f = rhs(model, V, t, x);
      r.resize(m);
      for (int i = 0; i < m; ++i) r(i) = f(states[size_t(i)]);
      return r.allFinite();
    } catch (const std::bad_alloc&) {
      throw;
    } catch (const std::exception&) {
      return false;
    }
  };
  auto record = [&](const Eigen::VectorXd& r) {
    Eigen::Index worst = 0;
    out.max_rate = m > 0 ? r.cwiseAbs().maxCoeff(&worst) : 0.0;
    out.worst_state = m > 0 ? model.state_name(states[size_t(worst)]) : "";
  };

  Eigen::VectorXd r;
  if (!rates(out.state, r)) {
    out.failure = "the model cannot be evaluated at the start";
    return out;
  }
  record(r);
  double delta = options.initial_step_s;
  const Eigen::MatrixXd identity = Eigen::MatrixXd::Identity(m, m);
  for (; out.steps < options.max_steps; ++out.steps) {
    if (out.max_rate <= options.tolerance) {
      out.converged = true;
      return out;
    }
    Eigen::MatrixXd J;
    try {
      J = rhs_jacobian_ad(model, plan, V, t, out.state);
    } catch (const std::bad_alloc&) {
      throw;
    } catch (const std::exception& e) {
      out.failure = std::string("the Jacobian cannot be evaluated: ") + e.what();
      return out;
    }
    // One linearly implicit Euler step; a step the model cannot evaluate
    // (a wheel off its contact table, non-finite forces) is retried shorter.
    bool accepted = false;
    Eigen::VectorXd x_try, r_try;
    while (!accepted && delta >= 1e-9) {
      const Eigen::VectorXd dx = (identity / delta - J).partialPivLu().solve(r);
      if (dx.allFinite()) {
        x_try = out.state;
        for (int i = 0; i < m; ++i) x_try(states[size_t(i)]) += dx(i);
        // A step that more than doubles |f| left the path of the motion
        // (the linearisation does not hold over it: creep saturating, a
        // contact jumping): retried shorter.
        accepted = rates(x_try, r_try) && r_try.norm() <= options.max_growth * r.norm();
      }
      if (!accepted) delta *= 0.25;
    }
    if (!accepted) {
      out.failure = "the pseudo-time step fell below 1e-9 s (the model cannot be evaluated "
                    "along the vehicle's motion)";
      return out;
    }
    out.pseudo_time_s += delta;
    // Switched evolution relaxation, delta_{k+1} = delta_k |f_k| / |f_{k+1}|,
    // with growth of at least 1.5 per accepted step: where the vehicle is in
    // transit |f| does not fall (sliding into a curve, crossing a contact
    // jump), and pure SER would hold delta at a transient's time scale; the
    // rejection above shortens a step that grew too long.
    const double ratio = r.norm() / std::max(r_try.norm(), 1e-300);
    delta = std::min(options.max_step_s, delta * std::clamp(ratio, 1.5, 10.0));
    out.state = x_try;
    r = r_try;
    record(r);
  }
  out.converged = out.max_rate <= options.tolerance;
  if (!out.converged) out.failure = "no steady state within the step limit";
  return out;
}

}  // namespace railstab
