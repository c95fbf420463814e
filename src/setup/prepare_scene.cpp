#include "setup/prepare_scene.hpp"

#include "io/scene_loader.hpp"

namespace railstab {

SceneSpec load_scene_with_overrides(const std::string& path, const SceneOverrides& overrides) {
  SceneSpec spec = load_scene_file(path);
  if (overrides.speed_m_per_s) spec.speed_m_per_s = *overrides.speed_m_per_s;
  if (overrides.t_end_s) spec.simulation.t_end_s = *overrides.t_end_s;
  if (overrides.reference_arc_length_m)
    spec.reference_arc_length_m = *overrides.reference_arc_length_m;
  validate_scene(spec);
  return spec;
}

PreparedScene prepare_scene(const std::string& path, const SceneOverrides& overrides) {
  return prepare_scene(load_scene_with_overrides(path, overrides));
}

PreparedScene prepare_scene(SceneSpec spec) {
  Model model = build_model(spec);
  const double V = spec.speed_m_per_s;
  EquilibriumResult eq = solve_equilibrium(model, V, lowered_nominal_state(model, V));
  return PreparedScene{std::move(spec), std::move(model), V, std::move(eq)};
}

Eigen::VectorXd perturbed_initial_state(const PreparedScene& scene) {
  const Model& model = scene.model;
  const int n = model.n_coordinates;
  Eigen::VectorXd x = scene.equilibrium.state;
  for (int k = 0; k < n; ++k) {
    const auto [b, c] = model.coordinate_of_state[k];
    const BodySpec& spec = scene.spec.bodies[b];
    x(k) += spec.initial_offset[c];
    x(n + k) += spec.initial_rate[c];
  }
  return x;
}

}  // namespace railstab
