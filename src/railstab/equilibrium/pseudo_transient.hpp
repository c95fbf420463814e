#pragma once
// Pseudo-transient continuation (Kelley and Keyes, SIAM J. Numer. Anal. 35,
// 1998): the globalisation of the equilibrium solver where Newton from the
// nominal guess fails. It follows the vehicle's own motion towards its steady
// state: linearly implicit Euler steps in a pseudo-time tau on
//
//   dx/dtau = f(x)      (the model's state derivative, frames frozen at t),
//
//   (I / delta - J(x_k)) dx = f(x_k),   x_{k+1} = x_k + dx,
//
// over every state except the wheelset spin angles (cyclic: they do not act
// back on f). The step delta grows by switched evolution relaxation (SER),
// delta_{k+1} = delta_k |f(x_{k-1})| / |f(x_k)|, by at least 1.5x per
// accepted step; a step that more than doubles |f| is retried with delta / 4.
// So the iteration is a damped
// time integration while the vehicle is in transit (e.g. sliding into a
// curve's flange contact from the centred position, across the jumps of a
// real profile pair's contact) and Newton's method (delta -> infinity) near
// the steady state. Large steps damp every mode, so the steady state found is
// also the one of a vehicle above its critical speed (implicit Euler's
// amplification 1/(1 - lambda delta) is below 1 for large delta).
#include <railstab/model/model.hpp>

#include <Eigen/Dense>

#include <string>

namespace railstab {

struct PseudoTransientOptions {
  double time_s = 0.0;              // where along the track (frames frozen at s(t))
  double initial_step_s = 1e-3;     // first pseudo-time step delta_0
  double max_step_s = 1e8;          // SER growth cap (Newton's method beyond ~1e4 s)
  int max_steps = 600;              // work limit
  // A step that multiplies |f| by more than this is rejected and retried
  // with delta / 4 (it left the vehicle's path).
  double max_growth = 2.0;
  // Stop when the largest |f| over the states (velocities and accelerations,
  // internal-state rates) is below this (the caller polishes with Newton).
  double tolerance = 1e-6;
};

struct PseudoTransientResult {
  Eigen::VectorXd state;
  bool converged = false;
  int steps = 0;
  double pseudo_time_s = 0.0;
  double max_rate = 0.0;        // largest |f| at `state`
  std::string worst_state;      // its name
  std::string failure;          // why it stopped, when not converged
};

// Never throws for a model that cannot be evaluated at a trial point: the
// step is shortened (delta / 4); stops after options.max_steps or when delta
// falls below 1e-9 s.
PseudoTransientResult settle_by_pseudo_transient(const Model& model, double speed_m_per_s,
                                                 const Eigen::VectorXd& start,
                                                 const PseudoTransientOptions& options = {});

}  // namespace railstab
