#pragma once
// [train], optional: cars, car_spacing_m and [[train.couplers]] (elements
// between consecutive cars): N copies of the vehicle (scene/train.hpp).
// The train is expanded while the file is read, before the checks, so that
// every later stage sees an ordinary scene; what only the file knows
// (coupler bodies are the vehicle's, cars a whole number) is checked
// against the file's keys here.
#include <railstab/scene/scene_spec.hpp>
#include <railstab/scene_reading/table_reader.hpp>

#include <string>
#include <vector>

namespace railstab::scene_reading {

// If the document `top` has a [train], replaces the vehicle `scene` by the
// train and `element_paths` (the key path of each vehicle element) by those
// of the train's elements; otherwise leaves both as they are.
void read_train(const TableReader& top, SceneSpec& scene, std::vector<std::string>& element_paths);

}  // namespace railstab::scene_reading
