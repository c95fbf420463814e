#pragma once
// Scene keys of a series_spring_damper (elements/series_spring_damper.hpp).
#include <railstab/elements/series_spring_damper.hpp>
#include <railstab/scene_reading/element_readers/element_reader.hpp>
#include <railstab/scene_reading/ranged_values.hpp>

#include <array>

namespace railstab::scene_reading {

template <> struct ElementReader<SeriesSpringDamper<double>> {
  static constexpr std::array<std::string_view, 4> kKeys = {
      "series_stiffness_N_per_m", "damping_N_s_per_m", "damper_force_velocity_table",
      "damper_force_scale"};
  static constexpr bool kPointsRequired = true;
  static SeriesSpringDamper<double> read(const TableReader& t) {
    SeriesSpringDamper<double> e;
    e.series_stiffness_N_per_m =
        ranged(t, "series_stiffness_N_per_m", physical_ranges::positive_stiffness_N_per_m);
    const ForceCharacteristic<double> damper = read_force_characteristic(
        t, "damping_N_s_per_m", physical_ranges::damping_N_s_per_m, "damper_force_velocity_table",
        physical_ranges::table_velocity_m_per_s, "damper_force_scale");
    // The internal state is the damper's velocity as a function of its force.
    if (!damper.strictly_increasing())
      t.fail(damper.is_table ? "damper_force_velocity_table" : "damping_N_s_per_m",
             "a damper whose force strictly increases with velocity (the series element "
             "needs its velocity as a function of force)",
             damper.is_table ? "a table with a flat or falling step" : "zero damping");
    e.set_damper(damper);
    return e;
  }
};

}  // namespace railstab::scene_reading
