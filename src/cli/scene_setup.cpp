#include "cli/scene_setup.hpp"

#include "io/scene_loader.hpp"

#include <algorithm>
#include <cmath>

namespace railstab {

namespace {

// The same vehicle on straight, level track at the same speed: where the
// preloads are defined (gravity only, no curving or cant forces).
SceneSpec straight_twin(const SceneSpec& spec) {
  SceneSpec twin = spec;
  double reach = 0.0;
  for (const BodySpec& b : spec.bodies) reach = std::max(reach, std::abs(b.track_offset_m));
  twin.track = TrackSpec{};
  twin.track.rail_contact_distance_m = spec.track.rail_contact_distance_m;
  twin.reference_arc_length_m = reach + 10.0;
  twin.track.segments.push_back({TrackSegmentKind::tangent, 2.0 * reach + 20.0, 0.0, 0.0});
  return twin;
}

}  // namespace

PreparedScene prepare_scene(const std::string& path, const SceneOverrides& overrides) {
  SceneSpec spec = load_scene_file(path);
  if (overrides.speed_m_per_s) spec.speed_m_per_s = *overrides.speed_m_per_s;
  if (overrides.t_end_s) spec.simulation.t_end_s = *overrides.t_end_s;
  if (overrides.reference_arc_length_m)
    spec.reference_arc_length_m = *overrides.reference_arc_length_m;
  validate_scene(spec);
  Model model = build_model(spec);
  if (spec.preload == PreloadMode::balance_gravity_at_nominal) {
    Model twin = build_model(straight_twin(spec));
    balance_gravity_at_nominal(twin, 0.0);
    for (size_t e = 0; e < model.elements.size(); ++e)
      model.elements[e].preload = twin.elements[e].preload;
  }
  EquilibriumResult eq = solve_equilibrium(model, lowered_nominal_state(model));
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
