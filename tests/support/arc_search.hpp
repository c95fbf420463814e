#pragma once
// A critical-speed search of a shipped curve case with the reference point
// in its arc (arc length 2000 m): the set-up the curve stability tests share.
#include <railstab/setup/prepare_scene.hpp>
#include <railstab/stability/speed_analysis.hpp>

#include <optional>
#include <string>

namespace railstab::test {

inline SceneOverrides in_arc(double speed_m_per_s) {
  SceneOverrides o;
  o.speed_m_per_s = speed_m_per_s;
  o.reference_arc_length_m = 2000.0;
  return o;
}

inline CriticalSpeedResult search_in_arc(const std::string& scene, double from, double to,
                                         double step) {
  const PreparedScene s = prepare_scene(scene, in_arc(from));
  CriticalSpeedOptions o;
  o.from_m_per_s = from;
  o.to_m_per_s = to;
  o.grid_step_m_per_s = step;
  return find_critical_speed(s.model, s.equilibrium.state, s.speed_m_per_s, o);
}

}  // namespace railstab::test
