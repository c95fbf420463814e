#include <railstab/scene_reading/scene_section_reader.hpp>

namespace railstab::scene_reading {

namespace {
const Choices<PreloadMode> kPreloadModes = {
    {"balance_gravity_at_nominal", PreloadMode::balance_gravity_at_nominal},
    {"none", PreloadMode::none}};
}  // namespace

void read_scene_section(const TableReader& top, SceneSpec& scene) {
  const TableReader section = top.table(
      "scene", {"name", "speed_m_per_s", "gravity_m_per_s2", "reference_arc_length_m", "preload"});
  scene.name = section.text("name");
  scene.speed_m_per_s = section.number("speed_m_per_s", "m/s");
  scene.gravity_m_per_s2 = section.number_or("gravity_m_per_s2", "m/s2", scene.gravity_m_per_s2);
  scene.reference_arc_length_m = section.number("reference_arc_length_m", "m");
  scene.preload = section.choice_or("preload", kPreloadModes, scene.preload);
}

}  // namespace railstab::scene_reading
