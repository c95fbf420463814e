#include <railstab/setup/build_model.hpp>

#include <railstab/equilibrium/equilibrium.hpp>
#include <railstab/model/equations_of_motion.hpp>
#include <railstab/setup/contact_tables.hpp>
#include <railstab/setup/model_error_context.hpp>

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <variant>

namespace railstab {

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

// Elements that take no part in the gravity sag (kInGravitySag false: a
// series spring-damper carries nothing at any equilibrium) are left out of
// it and get no preload. Leaving the series elements out also keeps the
// solve fast: with a stiff series spring (k_s ~ 1e9 N/m) the quadratic
// change of its length with the 0.1-0.2 m sag of a soft secondary
// suspension makes Newton crawl. A traction rod takes part linearised about
// its nominal line (elements/traction_rod.hpp): it carries the share of the
// weight its line carries (a hanger, an inclined rod), and a rod across the
// sag none, rather than fighting the sag through the second-order change of
// its length.
GravityTwin gravity_twin(const SceneSpec& scene) {
  GravityTwin twin{straight_twin(scene), {}};
  twin.spec.elements.clear();
  for (size_t i = 0; i < scene.elements.size(); ++i)
    if (std::visit([](const auto& e) { return std::decay_t<decltype(e)>::kInGravitySag; },
                   scene.elements[i])) {
      twin.kept.push_back(i);
      twin.spec.elements.push_back(scene.elements[i]);
      if (auto* rod = std::get_if<TractionRod<double>>(&twin.spec.elements.back()))
        rod->linearised_about_nominal_line = true;
    }
  return twin;
}

std::vector<Eigen::Vector3d> solve_gravity_preloads(const SceneSpec& scene) {
  const GravityTwin gravity = gravity_twin(scene);
  const std::vector<size_t>& kept = gravity.kept;
  const Model twin = assemble_model(gravity.spec);
  const double V = scene.speed_m_per_s;
  EvaluationPlace place{"static sag on straight, level track for the suspension preloads "
                        "(preload = 'balance_gravity_at_nominal')",
                        V};
  place.on_scene_track = false;
  const EquilibriumResult sagged = with_model_context(
      twin, place, [&] { return solve_equilibrium(twin, V, lowered_nominal_state(twin, V)); });
  Workspace<double> ws(twin);
  compute_all_body_motions<double>(twin, ws, 0.0, V, sagged.state);
  std::vector<Eigen::Vector3d> preloads(scene.elements.size(), Eigen::Vector3d::Zero());
  for (size_t j = 0; j < twin.elements.size(); ++j)
    preloads[kept[j]] = std::visit(
        [&](const auto& e) {
          const auto [a1, a2] = element_attachments(e.ends, ws);
          return e.elastic_load(a1, a2);
        },
        twin.elements[j]);
  return preloads;
}

Model build_model(const SceneSpec& scene) {
  // A scene loaded by a caller (a test, a benchmark) rather than by
  // prepare_scene may not have its profile contact tables yet.
  if (lacks_contact_tables(scene)) {
    SceneSpec with_tables = scene;
    build_contact_tables(with_tables);
    return build_model(with_tables);
  }
  if (scene.preload == PreloadMode::balance_gravity_at_nominal)
    return assemble_model(scene, solve_gravity_preloads(scene));
  return assemble_model(scene);
}

}  // namespace railstab
