#pragma once
// [scene]: name, speed_m_per_s, reference_arc_length_m, gravity_m_per_s2
// (9.81), preload ("balance_gravity_at_nominal" or "none").
#include <railstab/scene/scene_spec.hpp>
#include <railstab/scene_reading/table_reader.hpp>

namespace railstab::scene_reading {

// Reads the [scene] table of the document `top` into `scene`.
void read_scene_section(const TableReader& top, SceneSpec& scene);

}  // namespace railstab::scene_reading
