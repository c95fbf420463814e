#pragma once
// Shared first steps of every command: read the scene, apply command-line
// overrides, build the model, solve preloads and the static/steady equilibrium.
#include "equilibrium/equilibrium.hpp"
#include "model/model.hpp"
#include "scene/scene_spec.hpp"

#include <optional>
#include <string>

namespace railstab {

struct SceneOverrides {
  std::optional<double> speed_m_per_s;
  std::optional<double> t_end_s;
  // Where the reference point is at t = 0 (e.g. inside an arc for steady
  // curving); the scene's reference_arc_length_m otherwise.
  std::optional<double> reference_arc_length_m;
};

struct PreparedScene {
  SceneSpec spec;
  Model model;
  EquilibriumResult equilibrium;  // at t = 0 (steady rolling / curving at the scene speed)
};

PreparedScene prepare_scene(const std::string& path, const SceneOverrides& overrides);

// Equilibrium state plus the scene's initial offsets and rates.
Eigen::VectorXd perturbed_initial_state(const PreparedScene& scene);

}  // namespace railstab
