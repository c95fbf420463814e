#include "setup/build_model.hpp"

#include "equilibrium/equilibrium.hpp"
#include "model/equations_of_motion.hpp"

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

// Elements whose force is set by an internal state that relaxes to zero
// force at rest (a damper in series with a spring: dz/dt = 0 <=> F = 0)
// carry nothing at any equilibrium, so the sag is the same without them.
// They are left out of the sag solve: with a stiff series spring
// (k_s ~ 1e9 N/m) the quadratic change of their length with the 0.1-0.2 m
// sag of a soft secondary suspension makes the Newton solve crawl (hundreds
// of damped iterations) for nothing.
bool relaxes_to_zero_force(const ElementSpec& element) {
  return std::visit([](const auto& e) { return std::decay_t<decltype(e)>::kInternalStates > 0; },
                    element);
}

std::vector<Eigen::Vector3d> solve_gravity_preloads(const SceneSpec& scene) {
  SceneSpec twin_spec = straight_twin(scene);
  std::vector<size_t> kept;  // scene element index of each twin element
  twin_spec.elements.clear();
  for (size_t i = 0; i < scene.elements.size(); ++i)
    if (!relaxes_to_zero_force(scene.elements[i])) {
      kept.push_back(i);
      twin_spec.elements.push_back(scene.elements[i]);
    }
  const Model twin = assemble_model(twin_spec);
  const double V = scene.speed_m_per_s;
  const EquilibriumResult sagged = solve_equilibrium(twin, V, lowered_nominal_state(twin, V));
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
  if (scene.preload == PreloadMode::balance_gravity_at_nominal)
    return assemble_model(scene, solve_gravity_preloads(scene));
  return assemble_model(scene);
}

}  // namespace railstab
