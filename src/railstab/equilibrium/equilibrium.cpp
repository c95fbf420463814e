#include <railstab/equilibrium/equilibrium.hpp>

#include <railstab/contact/wheel_rail.hpp>
#include <railstab/equilibrium/pseudo_transient.hpp>
#include <railstab/linear/jacobian.hpp>
#include <railstab/model/equations_of_motion.hpp>
#include <railstab/model/workspace.hpp>

#include <algorithm>
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

// The equations: rows of the state derivative that must vanish
// (accelerations and internal-state rates).
std::vector<int> equation_rows(const Model& model, const std::vector<int>& only_positions) {
  std::vector<int> rows;
  if (only_positions.empty())
    for (int k = model.n_coordinates; k < model.state_size(); ++k) rows.push_back(k);
  else
    for (int k : only_positions) rows.push_back(model.n_coordinates + k);
  return rows;
}

// The state with every velocity zeroed except the spin rates: at rest
// relative to the track frames, as at an equilibrium.
Eigen::VectorXd with_zero_relative_velocities(const Model& model, Eigen::VectorXd x) {
  const int n = model.n_coordinates;
  for (int k = 0; k < n; ++k)
    if (!is_spin_angle(model, k)) x(n + k) = 0.0;
  return x;
}

}  // namespace

RhsJacobianPlan equilibrium_jacobian_plan(const Model& model,
                                          const std::vector<int>& only_positions) {
  return plan_rhs_jacobian(model, equation_rows(model, only_positions),
                           only_positions.empty() ? equilibrium_unknowns(model) : only_positions);
}

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
  // Every body lowered alike, so that each wheel overlaps its rail by about
  // 0.1 mm: by 0.1 mm, plus the largest gap of a wheelset at its nominal
  // height (profiles: the nominal centre height r0 need not touch exactly).
  double lowering = 1e-4;
  for (const Body& body : model.bodies)
    if (const WheelsetKind* w = body.wheelset())
      lowering = std::max(lowering, 1e-4 + centred_wheel_gap_m(model.contacts[size_t(w->contact)],
                                                               body.nominal_q(int(CoordinateIndex::z))));
  for (int k = 0; k < model.n_coordinates; ++k)
    if (model.coordinate_of_state[k].second == int(CoordinateIndex::z)) guess(k) -= lowering;
  // On irregular track each wheelset is set onto its own displaced rails
  // (at t = 0): their mean lateral and vertical displacement and the roll of
  // their cross level over the rail contact distance. A wheelset left at the
  // design height can hang in the air over a dip of several mm, where no
  // contact force, and so no Jacobian, pulls Newton towards the rail.
  if (model.track.irregularities() != nullptr) {
    Workspace<double> ws;
    ws.update_frames(model, 0.0, speed_m_per_s);
    const double D = model.track.spec().rail_contact_distance_m;
    for (size_t b = 0; b < model.bodies.size(); ++b) {
      const Body& body = model.bodies[b];
      if (!body.wheelset()) continue;
      const RailDisplacement& left = ws.frames[b].rail(+1);
      const RailDisplacement& right = ws.frames[b].rail(-1);
      const double shift[3] = {0.5 * (left.lateral_m + right.lateral_m),
                               0.5 * (left.vertical_m + right.vertical_m),
                               (left.vertical_m - right.vertical_m) / D};
      const CoordinateIndex coordinate[3] = {CoordinateIndex::y, CoordinateIndex::z,
                                             CoordinateIndex::roll};
      for (int c = 0; c < 3; ++c)
        if (const int k = body.state_index[int(coordinate[c])]; k >= 0) guess(k) += shift[c];
    }
  }
  return guess;
}

namespace {

// Newton's method with a backtracking line search and a Levenberg-Marquardt
// fallback, from `guess`. Throws EquilibriumError when it does not converge
// or the model cannot be evaluated at an accepted iterate.
EquilibriumResult newton_equilibrium(const Model& model, double speed_m_per_s,
                                     const Eigen::VectorXd& guess,
                                     const EquilibriumOptions& options,
                                     const std::vector<int>& unknowns,
                                     const std::vector<int>& rows,
                                     const RhsJacobianPlan& jacobian_plan) {
  const double t = options.time_s;
  const double V = speed_m_per_s;
  const int m = int(unknowns.size());
  auto residual = [&](const Eigen::VectorXd& state) {
    const Eigen::VectorXd xdot = rhs(model, V, t, state);
    Eigen::VectorXd r(m);
    for (int i = 0; i < m; ++i) r(i) = xdot(rows[i]);
    return r;
  };
  Eigen::VectorXd x = with_zero_relative_velocities(model, guess);

  EquilibriumResult result;
  // Errors of the model at an accepted iterate end the solve; the iterate
  // goes with the error so the caller can say where the vehicle was.
  auto fail = [&](const std::string& message) -> EquilibriumError {
    return EquilibriumError(message, x, result.worst_state);
  };
  auto at_iterate = [&](const char* what, auto&& evaluate) {
    try {
      return evaluate();
    } catch (const std::bad_alloc&) {
      throw;
    } catch (const std::exception& e) {
      std::ostringstream msg;
      msg << "no equilibrium found for scene '" << model.name << "' at speed " << V
          << " m/s: the model cannot be evaluated (" << what << ") after " << result.iterations
          << " Newton iterations: " << e.what();
      throw fail(msg.str());
    }
  };
  Eigen::VectorXd r = at_iterate("residual", [&] { return residual(x); });
  for (int it = 0; it <= options.max_iterations; ++it) {
    Eigen::Index worst = 0;
    result.max_acceleration = m > 0 ? r.cwiseAbs().maxCoeff(&worst) : 0.0;
    result.iterations = it;
    result.worst_state = m > 0 ? model.state_name(rows[size_t(worst)]) : "";
    if (result.max_acceleration <= options.acceleration_tolerance) {
      result.state = x;
      return result;
    }
    if (it == options.max_iterations) break;
    const Eigen::MatrixXd J =
        at_iterate("Jacobian", [&] { return rhs_jacobian_ad(model, jacobian_plan, V, t, x); });
    // Minimum-norm step: a neutral direction (e.g. an unrestrained
    // longitudinal drift) does not stop the solve.
    const Eigen::VectorXd step = J.completeOrthogonalDecomposition().solve(-r);
    // Backtracking line search on the residual norm.
    double alpha = 1.0;
    const double r0 = r.norm();
    Eigen::VectorXd x_try = x;
    Eigen::VectorXd r_try;
    bool accepted = false;
    for (int ls = 0; ls < 30 && step.allFinite(); ++ls) {
      x_try = x;
      for (int j = 0; j < m; ++j) x_try(unknowns[j]) += alpha * step(j);
      try {
        r_try = residual(x_try);
        if (r_try.norm() < (1.0 - 1e-4 * alpha) * r0) {
          accepted = true;
          break;
        }
      } catch (const std::bad_alloc&) {
        throw;
      } catch (const std::exception&) {
        // A trial point the model cannot evaluate (non-finite, a wheel
        // whose contact is undefined there): shorten the step.
      }
      alpha *= 0.5;
    }
    // Where the Newton direction does not decrease the residual (the model
    // is only C1, or strongly non-linear, along it: a wheel's contact jumping
    // between tread points, a curve entered from the centred position),
    // Levenberg-Marquardt steps (J^T J + mu I) s = -J^T r, from a short one
    // along the gradient towards the Newton step as mu decreases.
    if (!accepted && step.allFinite()) {
      const Eigen::MatrixXd JtJ = J.transpose() * J;
      const Eigen::VectorXd g = J.transpose() * r;
      const double scale = std::max(JtJ.diagonal().maxCoeff(), 1e-300);
      for (double mu = 1.0; mu >= 1e-8 && !accepted; mu *= 0.1) {
        const Eigen::VectorXd lm =
            (JtJ + mu * scale * Eigen::MatrixXd::Identity(m, m)).ldlt().solve(-g);
        if (!lm.allFinite()) continue;
        x_try = x;
        for (int j = 0; j < m; ++j) x_try(unknowns[j]) += lm(j);
        try {
          r_try = residual(x_try);
          accepted = r_try.norm() < (1.0 - 1e-6) * r0;
        } catch (const std::bad_alloc&) {
          throw;
        } catch (const std::exception&) {
        }
      }
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
  throw fail(msg.str());
}

}  // namespace

EquilibriumResult solve_equilibrium(const Model& model, double speed_m_per_s,
                                    const Eigen::VectorXd& guess,
                                    const EquilibriumOptions& options) {
  // A decelerating track frame has no steady state (its bodies feel m dV/dt).
  if (model.speed_rate_m_per_s2 != 0.0)
    throw std::invalid_argument(
        "equilibrium solver: the model has a speed rate (a speed ramp, " +
        std::to_string(model.speed_rate_m_per_s2) +
        " m/s^2); steady states are of the constant-speed model");
  for (int k : options.only_positions)
    if (!model.is_position(k) || is_spin_angle(model, k))
      throw std::invalid_argument("equilibrium solver: only_positions holds state " +
                                  std::to_string(k) + ", not a non-spin position");
  if (guess.size() != model.state_size())
    throw std::invalid_argument("equilibrium solver: guess has " + std::to_string(guess.size()) +
                                " entries, the model " + std::to_string(model.state_size()) +
                                " states");
  const std::vector<int> unknowns =
      options.only_positions.empty() ? equilibrium_unknowns(model) : options.only_positions;
  const std::vector<int> rows = equation_rows(model, options.only_positions);
  // d(equations)/d(unknowns) only: the columns Newton solves for, coloured.
  const RhsJacobianPlan own_plan =
      options.jacobian_plan ? RhsJacobianPlan{} : plan_rhs_jacobian(model, rows, unknowns);
  const RhsJacobianPlan& jacobian_plan = options.jacobian_plan ? *options.jacobian_plan : own_plan;
  if (jacobian_plan.rows != rows || jacobian_plan.columns != unknowns)
    throw std::invalid_argument(
        "equilibrium solver: options.jacobian_plan is not the plan of this model's equilibrium "
        "equations and unknowns (use equilibrium_jacobian_plan)");
  try {
    return newton_equilibrium(model, speed_m_per_s, guess, options, unknowns, rows,
                              jacobian_plan);
  } catch (const EquilibriumError& newton_error) {
    // A partial equilibrium holds states fixed: it has no motion to follow.
    if (!options.only_positions.empty() || !options.pseudo_transient_fallback) throw;
    // Newton from the guess failed (a real profile pair's contact jumps, a
    // curve entered from the centred position): let the vehicle settle by
    // pseudo-transient continuation from the guess, then polish by Newton.
    PseudoTransientOptions pto;
    pto.time_s = options.time_s;
    pto.tolerance = std::max(options.acceleration_tolerance, 1e-6);
    const PseudoTransientResult settled = settle_by_pseudo_transient(
        model, speed_m_per_s, with_zero_relative_velocities(model, guess), pto);
    if (settled.converged) {
      try {
        EquilibriumResult polished = newton_equilibrium(model, speed_m_per_s, settled.state, options,
                                                        unknowns, rows, jacobian_plan);
        polished.pseudo_transient_steps = settled.steps;
        return polished;
      } catch (const EquilibriumError&) {
      }
    }
    std::ostringstream msg;
    msg << newton_error.what() << "; pseudo-transient continuation from the guess: "
        << (settled.converged ? "settled, but Newton's method did not converge from there"
                              : settled.failure)
        << " after " << settled.steps << " steps (" << settled.pseudo_time_s
        << " s of pseudo-time), largest rate " << settled.max_rate << " (state "
        << settled.worst_state << ")";
    throw EquilibriumError(msg.str(), newton_error.last_state, newton_error.worst_state);
  }
}

}  // namespace railstab
