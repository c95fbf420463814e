#pragma once
// Scene keys of a line_spring_damper (elements/line_spring_damper.hpp): a
// spring and a damper along the line between the points, each linear or a
// table, each optional.
#include <railstab/elements/line_spring_damper.hpp>
#include <railstab/scene_reading/element_readers/element_reader.hpp>

#include <array>

namespace railstab::scene_reading {

template <> struct ElementReader<LineSpringDamper<double>> {
  static constexpr std::array<std::string_view, 6> kKeys = {
      "stiffness_N_per_m",         "spring_force_deflection_table", "spring_force_scale",
      "damping_N_s_per_m",         "damper_force_velocity_table",   "damper_force_scale"};
  static constexpr bool kPointsRequired = true;
  static LineSpringDamper<double> read(const TableReader& t) {
    LineSpringDamper<double> e;
    e.spring = read_force_characteristic(t, "stiffness_N_per_m", physical_ranges::stiffness_N_per_m,
                                         "spring_force_deflection_table",
                                         physical_ranges::table_deflection_m, "spring_force_scale",
                                         false);
    e.damper = read_force_characteristic(t, "damping_N_s_per_m", physical_ranges::damping_N_s_per_m,
                                         "damper_force_velocity_table",
                                         physical_ranges::table_velocity_m_per_s, "damper_force_scale",
                                         false);
    return e;
  }
};

}  // namespace railstab::scene_reading
