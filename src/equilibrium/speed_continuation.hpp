#pragma once
// Steady states followed in speed (natural continuation): the steady state at
// one speed is Newton's guess at the next, with the wheelsets' spin rates
// scaled with the speed. Where Newton misses, the step is halved, so the
// solution stays on the branch it started on. Used where a steady state at
// a high speed cannot be reached from the nominal position in one solve,
// e.g. steady curving on real profiles at high cant deficiency (Newton from
// the centred wheelsets does not find the two-point contact, and
// pseudo-transient continuation can settle on another, unstable, branch).
#include "equilibrium/equilibrium.hpp"

namespace railstab {

// x (a state at from_m_per_s) with every free wheelset spin rate scaled by
// to / from: the steady rolling guess at the new speed.
Eigen::VectorXd rescaled_to_speed(const Model& model, const Eigen::VectorXd& x,
                                  double from_m_per_s, double to_m_per_s);

// From the steady state `state` at from_m_per_s to to_m_per_s: the whole
// step first, then halved steps (each success moves on), at most
// max_halvings halvings in all. `options` as for solve_equilibrium (its
// pseudo-transient fallback is switched off here: it would leave the
// branch). Throws EquilibriumError (the last Newton failure) when the
// halvings run out.
EquilibriumResult continue_equilibrium_in_speed(const Model& model, double from_m_per_s,
                                                const Eigen::VectorXd& state, double to_m_per_s,
                                                EquilibriumOptions options, int max_halvings = 6);

}  // namespace railstab
