#pragma once
// The railway model's periodic orbits: which states the shooting's section
// and excursion use, and the Hopf start of the branch in the reduced state
// (flow_system.hpp: the model's state without the wheelsets' spin angles).
#include <railstab/integrate/integrator.hpp>
#include <railstab/nonlinear/hopf_criticality.hpp>
#include <railstab/nonlinear/orbit_continuation.hpp>

#include <string>
#include <vector>

namespace railstab {

// The section is the named wheelset's lateral velocity (state
// "<wheelset>.y_m/s"), the excursion its lateral displacement ("<wheelset>.y_m"),
// both as reduced-state indices. Empty name: the first wheelset of the model.
// Throws std::invalid_argument when there is no such wheelset or its lateral
// coordinate is not free.
OrbitCoordinates wheelset_orbit_coordinates(const Model& model,
                                            const std::vector<int>& reduced_states,
                                            const std::string& wheelset_name = "");

// The Hopf start from hopf_criticality's result: its steady state (at the
// evaluation speed, full state) and eigenvector (over the linear model's
// kept states) mapped into the reduced state; the excursion law of the
// amplitude state. Throws std::invalid_argument when a reduced state is not
// among the linear model's kept states (the linearisation removed more than
// the spin angles: their eigenvector entries are unknown).
HopfStart model_hopf_start(const Model& model, const std::vector<int>& reduced_states,
                           const Eigen::VectorXd& equilibrium_full, const HopfCriticality& hopf,
                           const OrbitCoordinates& coords);

// The start of a branch from a time-domain cycle: `equilibrium_full` (the
// steady state at speed_m_per_s, full state) with the amplitude state moved
// by disturbance_m, run for settle_time_s by integrate() with `options`
// (its t_end_s replaced; output every 1 ms unless options say finer); the
// second half of the run gives the orbit's start (in its last complete
// cycle), period and the cycles' spread (orbit_guess_from_samples).
// Throws std::runtime_error, saying why, when the run stops early, decays
// to below 2 um peak-to-peak in its last second (or half), or holds fewer
// than two complete cycles.
OrbitGuess settled_cycle_guess(const Model& model, double speed_m_per_s,
                               const Eigen::VectorXd& equilibrium_full,
                               const std::vector<int>& reduced_states, const OrbitCoordinates& coords,
                               double disturbance_m, double settle_time_s,
                               IntegrationOptions options = {});

}  // namespace railstab
