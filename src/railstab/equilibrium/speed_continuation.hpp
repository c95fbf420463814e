#pragma once
// Steady states followed in speed (natural continuation): the steady state at
// one speed is Newton's guess at the next, with the wheelsets' spin rates
// scaled with the speed. Where Newton misses, the step is halved, so the
// solution stays on the branch it started on. Used where a steady state at
// a high speed cannot be reached from the nominal position in one solve,
// e.g. steady curving on real profiles at high cant deficiency (Newton from
// the centred wheelsets does not find the two-point contact, and
// pseudo-transient continuation can settle on another, unstable, branch).
#include <railstab/equilibrium/equilibrium.hpp>

namespace railstab {

// x (a state at from_m_per_s) with every free wheelset spin rate scaled by
// to / from: the steady rolling guess at the new speed.
Eigen::VectorXd rescaled_to_speed(const Model& model, const Eigen::VectorXd& x,
                                  double from_m_per_s, double to_m_per_s);

// From the steady state `state` at from_m_per_s to to_m_per_s: the whole
// step first; a failed step is halved, a successful one moves on and the
// next step doubles (up to what is left), so a hard stretch costs small
// steps only where it is hard. Steps never go below the whole distance /
// 2^max_halvings, or kSmallestSpeedStep_m_per_s if that is smaller (a long
// way, e.g. from the scene's speed to the start of a sweep, may hold a
// stretch as hard as a short one: 2.5 m/s / 2^6 = 0.04 m/s is what the
// sweep's grid steps allow). `options` as for solve_equilibrium (its pseudo-transient
// fallback is switched off here: it would leave the branch). Throws
// EquilibriumError (the last Newton failure) when a step would have to be
// smaller.
inline constexpr double kSmallestSpeedStep_m_per_s = 0.04;

EquilibriumResult continue_equilibrium_in_speed(const Model& model, double from_m_per_s,
                                                const Eigen::VectorXd& state, double to_m_per_s,
                                                EquilibriumOptions options, int max_halvings = 6);

}  // namespace railstab
