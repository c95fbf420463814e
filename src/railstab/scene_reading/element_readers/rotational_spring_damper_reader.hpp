#pragma once
// Scene keys of a rotational_spring_damper (elements/rotational_spring_damper.hpp).
// Its two points are optional (0): the element acts on relative rotation.
#include <railstab/elements/rotational_spring_damper.hpp>
#include <railstab/scene_reading/element_readers/element_reader.hpp>
#include <railstab/scene_reading/ranged_values.hpp>

#include <array>

namespace railstab::scene_reading {

template <> struct ElementReader<RotationalSpringDamper<double>> {
  static constexpr std::array<std::string_view, 3> kKeys = {
      "stiffness_N_m_per_rad", "damping_N_m_s_per_rad", "actuator_moment_N_m"};
  static constexpr bool kPointsRequired = false;
  static RotationalSpringDamper<double> read(const TableReader& t) {
    RotationalSpringDamper<double> e;
    e.stiffness_N_m_per_rad =
        ranged_each(t, "stiffness_N_m_per_rad", physical_ranges::stiffness_N_m_per_rad);
    e.damping_N_m_s_per_rad =
        ranged_each(t, "damping_N_m_s_per_rad", physical_ranges::damping_N_m_s_per_rad);
    e.actuator_moment_N_m = ranged_each(t, "actuator_moment_N_m",
                                        physical_ranges::actuator_moment_N_m,
                                        Eigen::Vector3d::Zero());
    return e;
  }
};

}  // namespace railstab::scene_reading
