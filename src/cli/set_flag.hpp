#pragma once
// `--set KEY=VALUE` (repeatable) on every command that reads a scene: a
// numeric scene value replaced by its key path (scene_reading/scene_set_values.hpp).
// The form and the number are checked while parsing ("--set: expected a
// finite number as the value of bodies.carbody.mass_kg, got 'abc'"); the key
// when the scene is read.
#include <railstab/scene_reading/scene_set_values.hpp>

#include <CLI/CLI.hpp>

#include <vector>

namespace railstab {

void add_set_flag(CLI::App* cmd, std::vector<SceneValueSetting>& values);

}  // namespace railstab
