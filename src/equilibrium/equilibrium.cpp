#include "equilibrium/equilibrium.hpp"

#include "elements/spring_damper.hpp"
#include "linear/jacobian.hpp"
#include "model/equations_of_motion.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace railstab {

namespace {

bool is_spin(const Model& model, int k) {
  const auto [b, c] = model.coordinate_of_state[k];
  return model.bodies[b].is_wheelset && c == int(CoordinateIndex::pitch);
}

// Indices into x of the unknowns: positions of non-spin coordinates, rates
// of spin coordinates.
std::vector<int> unknown_indices(const Model& model) {
  std::vector<int> idx;
  const int n = model.n_coordinates;
  for (int k = 0; k < n; ++k) idx.push_back(is_spin(model, k) ? n + k : k);
  return idx;
}

Eigen::VectorXd accelerations(const Model& model, double t, const Eigen::VectorXd& x) {
  return rhs(model, t, x).tail(model.n_coordinates);
}

}  // namespace

Eigen::VectorXd nominal_state(const Model& model) {
  Eigen::VectorXd x = Eigen::VectorXd::Zero(model.state_size());
  const int n = model.n_coordinates;
  for (int k = 0; k < n; ++k) {
    const auto [b, c] = model.coordinate_of_state[k];
    x(k) = model.bodies[b].nominal_q(c);
    if (is_spin(model, k)) {
      const ModelBody& body = model.bodies[b];
      x(n + k) = model.speed_m_per_s / model.contacts[body.contact].spec.nominal_rolling_radius_m;
    }
  }
  return x;
}

Eigen::VectorXd lowered_nominal_state(const Model& model) {
  Eigen::VectorXd guess = nominal_state(model);
  for (int k = 0; k < model.n_coordinates; ++k)
    if (model.coordinate_of_state[k].second == int(CoordinateIndex::z)) guess(k) -= 1e-4;
  return guess;
}

EquilibriumResult solve_equilibrium(const Model& model, const Eigen::VectorXd& guess,
                                    const EquilibriumOptions& options) {
  const int n = model.n_coordinates;
  const double t = options.time_s;
  const std::vector<int> unknowns = unknown_indices(model);
  Eigen::VectorXd x = guess;
  // Velocities other than spin rates are zero at an equilibrium.
  for (int k = 0; k < n; ++k)
    if (!is_spin(model, k)) x(n + k) = 0.0;

  EquilibriumResult result;
  Eigen::VectorXd r = accelerations(model, t, x);
  for (int it = 0; it <= options.max_iterations; ++it) {
    Eigen::Index worst = 0;
    result.max_acceleration = r.cwiseAbs().maxCoeff(&worst);
    result.iterations = it;
    result.worst_state = model.state_name(n + int(worst));
    if (result.max_acceleration <= options.acceleration_tolerance) {
      result.state = x;
      return result;
    }
    if (it == options.max_iterations) break;
    const Eigen::MatrixXd jac = rhs_jacobian_ad(model, t, x);
    Eigen::MatrixXd J(n, n);
    for (int j = 0; j < n; ++j) J.col(j) = jac.block(n, unknowns[j], n, 1);
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
      for (int j = 0; j < n; ++j) x_try(unknowns[j]) += alpha * step(j);
      try {
        r_try = accelerations(model, t, x_try);
        if (r_try.norm() < (1.0 - 1e-4 * alpha) * r0) {
          accepted = true;
          break;
        }
      } catch (const std::runtime_error&) {
        // non-finite trial point: shorten the step
      }
      alpha *= 0.5;
    }
    if (!accepted) {
      // Accept a tiny step when already at round-off level.
      if (step.norm() < 1e-12) break;
      break;
    }
    x = x_try;
    r = r_try;
  }
  std::ostringstream msg;
  msg << "no equilibrium found for scene '" << model.name << "' at speed "
      << model.speed_m_per_s << " m/s: after " << result.iterations
      << " Newton iterations the largest acceleration residual is " << result.max_acceleration
      << " (state " << result.worst_state << ")";
  throw std::runtime_error(msg.str());
}

EquilibriumResult balance_gravity_at_nominal(Model& model, double time_s) {
  for (ModelElement& e : model.elements) e.preload.setZero();
  EquilibriumOptions opt;
  opt.time_s = time_s;
  const EquilibriumResult sagged = solve_equilibrium(model, lowered_nominal_state(model), opt);

  // Elastic forces at the sagged equilibrium become preloads.
  const auto frames = track_frames_at(model, time_s);
  std::vector<BodyMotion<double>> motions;
  compute_all_body_motions<double>(model, time_s, frames, sagged.state, motions);
  for (ModelElement& e : model.elements) {
    const Attachment<double> a1 = e.body1 == kTrackBody ? attachment_of<double>(frames[e.body2])
                                                        : attachment_of(motions[e.body1]);
    const Attachment<double> a2 = attachment_of(motions[e.body2]);
    if (e.kind == ElementKind::spring_damper_3d) {
      const ElementDeflection<double> def = spring_deflection(e, a1, a2);
      e.preload = e.stiffness.cwiseProduct(def.d - e.free_vector_m);
    } else {
      const Eigen::Matrix3d R_12 = a1.R_WF.transpose() * a2.R_WF;
      e.preload = e.stiffness.cwiseProduct(rotation_vector<double>(R_12));
    }
  }
  return solve_equilibrium(model, lowered_nominal_state(model), opt);
}

}  // namespace railstab
