#pragma once
// The one error type of scene reading. Every message reads
//   "<file>: <key path>: <what was expected>, got <what was found>"
// e.g. "cases/x.toml: bodies[2].mass_kg: expected a positive number (kg), got -3"
// (scene_reading/scene_messages.hpp writes them).
#include <stdexcept>

namespace railstab {

struct SceneError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace railstab
