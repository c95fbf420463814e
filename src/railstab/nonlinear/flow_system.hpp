#pragma once
// An autonomous vector field x' = f(x; V) with its Jacobian and speed
// derivative: what the periodic-orbit code (periodic_orbit.hpp,
// orbit_continuation.hpp) integrates and differentiates. One interface for
// the railway model and for closed-form test systems (the Hopf normal form,
// van der Pol), so the tests run the product code path.
//
// For the railway model (model_flow_system) the state is the model's state
// without the wheelsets' spin angles: f does not depend on them (an
// axisymmetric wheelset's spin angle is cyclic, linear/linearization.hpp),
// while they grow without bound along any motion, so no orbit is periodic in
// them. The reduced state is embedded in the full one with the spin angles
// at 0; the reduced f is the full f's other rows. The model must be
// autonomous: tangent track or a constant curve (f evaluated at t = time_s
// always; a transition or a track irregularity would make f depend on t).
#include <railstab/model/model.hpp>

#include <Eigen/Dense>

#include <functional>
#include <string>
#include <vector>

namespace railstab {

struct FlowSystem {
  int size = 0;
  std::vector<std::string> state_names;
  // f(x; V) into `out` (sized by the callee).
  std::function<void(const Eigen::VectorXd& x, double speed_m_per_s, Eigen::VectorXd& out)> rhs;
  // df/dx at (x; V), exact.
  std::function<void(const Eigen::VectorXd& x, double speed_m_per_s, Eigen::MatrixXd& out)>
      jacobian;
  // df/dV at (x; V). Empty: central difference with step
  // speed_difference_step_m_per_s (f is smooth in V: truncation error
  // h^2 |f'''| / 6, round-off ~ 1e-16 |f| / h).
  std::function<void(const Eigen::VectorXd& x, double speed_m_per_s, Eigen::VectorXd& out)>
      speed_derivative;
  double speed_difference_step_m_per_s = 1e-4;
};

// df/dV by the system's own derivative or the central difference.
Eigen::VectorXd speed_derivative(const FlowSystem& system, const Eigen::VectorXd& x,
                                 double speed_m_per_s);

// The railway model's reduced system (see above). `reduced_states` (out,
// optional) receives the full-state index of every reduced state.
FlowSystem model_flow_system(const Model& model, double time_s = 0.0,
                             std::vector<int>* reduced_states = nullptr);

// Full state -> reduced (drops the spin angles) and back (spin angles 0).
Eigen::VectorXd reduce_state(const std::vector<int>& reduced_states, const Eigen::VectorXd& full);
Eigen::VectorXd embed_state(const Model& model, const std::vector<int>& reduced_states,
                            const Eigen::VectorXd& reduced);

}  // namespace railstab
