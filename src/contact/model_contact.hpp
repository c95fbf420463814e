#pragma once
// A wheel-rail contact model as the model holds it: the scene's description
// and what is derived from it once (combined elastic constants, rail
// curvature).
#include "contact/hertz.hpp"
#include "scene/scene_spec.hpp"

namespace railstab {

struct ModelContact {
  ContactSpec spec;
  ElasticPair materials{};
  double rail_curvature_B_per_m = 0.0;  // B = 1 / (2 R_rail), transverse
};

}  // namespace railstab
