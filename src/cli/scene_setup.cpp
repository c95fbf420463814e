#include "cli/scene_setup.hpp"

#include "io/scene_loader.hpp"

namespace railstab {

PreparedScene prepare_scene(const std::string& path, const SceneOverrides& overrides) {
  SceneSpec spec = load_scene_file(path);
  if (overrides.speed_m_per_s) spec.speed_m_per_s = *overrides.speed_m_per_s;
  if (overrides.t_end_s) spec.simulation.t_end_s = *overrides.t_end_s;
  validate_scene(spec);
  Model model = build_model(spec);
  EquilibriumResult eq;
  if (spec.preload == PreloadMode::balance_gravity_at_nominal) {
    eq = balance_gravity_at_nominal(model, 0.0);
  } else {
    Eigen::VectorXd guess = nominal_state(model);
    for (int k = 0; k < model.n_coordinates; ++k)
      if (model.coordinate_of_state[k].second == int(CoordinateIndex::z)) guess(k) -= 1e-4;
    eq = solve_equilibrium(model, guess);
  }
  return PreparedScene{std::move(spec), std::move(model), std::move(eq)};
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
