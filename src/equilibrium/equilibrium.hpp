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
#include "model/model.hpp"

#include <Eigen/Dense>

#include <string>
#include <vector>

namespace railstab {

struct EquilibriumOptions {
  double time_s = 0.0;                    // where along the track (frames at s(t))
  double acceleration_tolerance = 1e-7;   // max |acceleration| (m/s^2, rad/s^2)
  int max_iterations = 60;
};

struct EquilibriumResult {
  Eigen::VectorXd state;       // full state x = [q; u] at the equilibrium
  int iterations = 0;
  double max_acceleration = 0.0;
  std::string worst_state;     // name of the largest residual
};

// Throws std::runtime_error ("no equilibrium ...: residual of <state> ...")
// when Newton does not converge.
EquilibriumResult solve_equilibrium(const Model& model, double speed_m_per_s,
                                    const Eigen::VectorXd& guess,
                                    const EquilibriumOptions& options = {});

// Nominal state: every body at its nominal position, no offsets, wheelsets
// spinning at V/r0, everything else at rest relative to its track frame,
// element internal states zero.
Eigen::VectorXd nominal_state(const Model& model, double speed_m_per_s);
// The nominal state lowered by 0.1 mm so every wheel starts in contact (the
// Hertz stiffness is zero at zero penetration): the Newton start.
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
