#pragma once
// From a validated scene to the model every analysis evaluates, with the
// element preloads the scene asks for solved into it (the model is not
// changed afterwards).
//
// preload = balance_gravity_at_nominal (ERRATA 13): the preloads are the
// elastic loads of the sagged static equilibrium of the same vehicle on
// straight, level track at the scene's speed (the "straight twin": gravity
// only, no curving or cant forces), so the nominal configuration is that
// twin's equilibrium. Elements without a preload (bump stops, series
// spring-dampers: nothing static passes through them) keep none; series
// spring-dampers (force zero at every equilibrium) are left out of the sag
// solve, bump stops take part in it.
#include <railstab/model/model.hpp>
#include <railstab/scene/scene_spec.hpp>

#include <vector>

namespace railstab {

// Builds the profile contact tables the scene lacks (setup/contact_tables.hpp)
// on a copy; prepare_scene builds them into its scene first, so that models
// built again from PreparedScene::spec share them.
Model build_model(const SceneSpec& scene);

// The same vehicle on straight, level track at the same speed.
SceneSpec straight_twin(const SceneSpec& scene);

// The vehicle whose sag defines the preloads: the straight twin without the
// elements that take no part in the sag; kept[j] is the scene index of its
// element j.
struct GravityTwin {
  SceneSpec spec;
  std::vector<size_t> kept;
};
GravityTwin gravity_twin(const SceneSpec& scene);

// The preloads of ERRATA 13 (one per element, scene order).
std::vector<Eigen::Vector3d> solve_gravity_preloads(const SceneSpec& scene);

}  // namespace railstab
