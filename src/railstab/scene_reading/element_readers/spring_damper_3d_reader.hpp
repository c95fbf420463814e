#pragma once
// Scene keys of a spring_damper_3d (elements/spring_damper_3d.hpp).
#include <railstab/elements/spring_damper_3d.hpp>
#include <railstab/scene_reading/element_readers/element_reader.hpp>
#include <railstab/scene_reading/ranged_values.hpp>

#include <array>

namespace railstab::scene_reading {

template <> struct ElementReader<SpringDamper3d<double>> {
  static constexpr std::array<std::string_view, 3> kKeys = {
      "stiffness_N_per_m", "damping_N_s_per_m", "actuator_force_N"};
  static constexpr bool kPointsRequired = true;
  static SpringDamper3d<double> read(const TableReader& t) {
    SpringDamper3d<double> e;
    e.stiffness_N_per_m = ranged_each(t, "stiffness_N_per_m", physical_ranges::stiffness_N_per_m);
    e.damping_N_s_per_m = ranged_each(t, "damping_N_s_per_m", physical_ranges::damping_N_s_per_m);
    e.actuator_force_N = ranged_each(t, "actuator_force_N", physical_ranges::actuator_force_N,
                                     Eigen::Vector3d::Zero());
    return e;
  }
};

}  // namespace railstab::scene_reading
