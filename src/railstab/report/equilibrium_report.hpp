#pragma once
// The steady state of a prepared scene (setup/prepare_scene.hpp) as a JSON
// file and a summary for the terminal: every body's offsets from its
// nominal position (a wheelset's spin rate instead of its spin angle) and,
// per wheel, the load, creepages and creep forces of that state.
#include <railstab/io/output_set.hpp>
#include <railstab/setup/prepare_scene.hpp>

#include <string>

namespace railstab {

// Throws std::runtime_error naming the body and coordinate when a
// coordinate or rate of the state is not finite ("no output written").
void check_finite_equilibrium(const Model& model, double speed_m_per_s,
                              const Eigen::MatrixXd& q6, const Eigen::MatrixXd& qd6);

// Adds <stem>_equilibrium_<V>mps.json to `outputs` (staged; the caller commits) and
// returns the summary text (offsets in mm and mrad, wheel loads), rendered
// with the JSON so that neither exists unless every number is finite.
std::string write_equilibrium_results(const PreparedScene& scene, OutputSet& outputs,
                                      const std::string& stem);

}  // namespace railstab
