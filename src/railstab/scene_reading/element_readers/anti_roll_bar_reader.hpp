#pragma once
// Scene keys of an anti_roll_bar (elements/anti_roll_bar.hpp).
#include <railstab/elements/anti_roll_bar.hpp>
#include <railstab/scene_reading/element_readers/element_reader.hpp>
#include <railstab/scene_reading/ranged_values.hpp>

#include <array>

namespace railstab::scene_reading {

template <> struct ElementReader<AntiRollBar<double>> {
  static constexpr std::array<std::string_view, 2> kKeys = {"roll_stiffness_N_m_per_rad",
                                                            "link_half_spacing_m"};
  static constexpr bool kPointsRequired = true;
  static AntiRollBar<double> read(const TableReader& t) {
    AntiRollBar<double> e;
    e.roll_stiffness_N_m_per_rad = ranged(t, "roll_stiffness_N_m_per_rad",
                                          physical_ranges::positive_stiffness_N_m_per_rad);
    e.link_half_spacing_m = ranged(t, "link_half_spacing_m", physical_ranges::link_half_spacing_m);
    return e;
  }
};

}  // namespace railstab::scene_reading
