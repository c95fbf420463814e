#pragma once
// Equilibria of the model by Newton's method with the AD Jacobian: static
// equilibrium under gravity, steady rolling on tangent track and steady
// curving on a constant-radius arc are the same problem (all free
// accelerations zero, all relative velocities zero), solved by one solver.
//
// Unknowns: every free coordinate except wheelset spin angles (cyclic), the
// spin *rates* of free-spinning wheelsets (they settle with the rolling
// radii), and the internal states of force elements. Equations: every free
// coordinate's acceleration is zero, and every internal state's rate.
#include <railstab/linear/jacobian_pattern.hpp>
#include <railstab/model/model.hpp>

#include <Eigen/Dense>

#include <stdexcept>
#include <string>
#include <vector>
#include <utility>

namespace railstab {

// Newton did not converge, or the model failed at an iterate: the message,
// the last iterate (for a diagnosis of where the vehicle went) and the
// state with the largest residual.
struct EquilibriumError : std::runtime_error {
  EquilibriumError(const std::string& message, Eigen::VectorXd last, std::string worst)
      : std::runtime_error(message), last_state(std::move(last)), worst_state(std::move(worst)) {}
  Eigen::VectorXd last_state;
  std::string worst_state;
};

struct EquilibriumOptions {
  double time_s = 0.0;                    // where along the track (frames at s(t))
  double acceleration_tolerance = 1e-7;   // max |acceleration| (m/s^2, rad/s^2)
  int max_iterations = 60;
  // Empty: the full equilibrium (unknowns as described above). Otherwise
  // only these position states are unknown, the rest of the state is held,
  // and the equations are their accelerations: a partial equilibrium, e.g.
  // a wheelset's height and roll for a given lateral offset.
  std::vector<int> only_positions;
  // The coloured Jacobian's plan for these equations and unknowns, from
  // equilibrium_jacobian_plan(model, only_positions), for callers that solve
  // many times on one model (a speed sweep). nullptr: planned per solve.
  const RhsJacobianPlan* jacobian_plan = nullptr;
  // Where Newton from the guess fails, settle by pseudo-transient
  // continuation (pseudo_transient.hpp) and polish by Newton (full
  // equilibrium only).
  bool pseudo_transient_fallback = true;
};

struct EquilibriumResult {
  Eigen::VectorXd state;       // full state x = [q; u] at the equilibrium
  int iterations = 0;
  double max_acceleration = 0.0;
  std::string worst_state;     // name of the largest residual
  int pseudo_transient_steps = 0;  // > 0: Newton needed the pseudo-transient start
};

// Throws EquilibriumError ("no equilibrium ...: residual of <state> ...")
// when neither Newton nor the pseudo-transient fallback converges or the model cannot be evaluated at an
// iterate (e.g. a wheel so far off the rail that its contact is undefined).
// A trial point of the line search that the model cannot evaluate only
// shortens the step.
EquilibriumResult solve_equilibrium(const Model& model, double speed_m_per_s,
                                    const Eigen::VectorXd& guess,
                                    const EquilibriumOptions& options = {});

// The plan of the Jacobian Newton uses: d(equations)/d(unknowns) only (the
// rows and columns it solves for), coloured.
RhsJacobianPlan equilibrium_jacobian_plan(const Model& model,
                                          const std::vector<int>& only_positions = {});

// Nominal state: every body at its nominal position, no offsets, wheelsets
// spinning at V/r0, everything else at rest relative to its track frame,
// element internal states zero.
Eigen::VectorXd nominal_state(const Model& model, double speed_m_per_s);
// The nominal state lowered by 0.1 mm so every wheel starts in contact (the
// Hertz stiffness is zero at zero penetration): the Newton start. On
// irregular track every wheelset also follows its rails' displacement at
// t = 0 (their mean shift and height, the roll of the cross level).
Eigen::VectorXd lowered_nominal_state(const Model& model, double speed_m_per_s);

// The scene's initial state: nominal state plus the bodies' initial offsets
// and rates (no equilibrium solved: for scenes that start from rest).
Eigen::VectorXd initial_state(const Model& model, double speed_m_per_s);

// Indices into x of the equilibrium unknowns (positions except spin angles,
// spin rates, element internal states), in the order of the residual rows
// rhs(x).tail(state_size - n_coordinates).
std::vector<int> equilibrium_unknowns(const Model& model);

// True for the state index of a wheelset's spin angle (cyclic).
bool is_spin_angle(const Model& model, int state);


}  // namespace railstab
