#pragma once
// Scene keys of a traction_rod (elements/traction_rod.hpp).
#include <railstab/elements/traction_rod.hpp>
#include <railstab/scene_reading/element_readers/element_reader.hpp>
#include <railstab/scene_reading/ranged_values.hpp>

#include <array>

namespace railstab::scene_reading {

template <> struct ElementReader<TractionRod<double>> {
  static constexpr std::array<std::string_view, 2> kKeys = {"stiffness_N_per_m",
                                                            "damping_N_s_per_m"};
  static constexpr bool kPointsRequired = true;
  static TractionRod<double> read(const TableReader& t) {
    TractionRod<double> e;
    e.stiffness_N_per_m =
        ranged(t, "stiffness_N_per_m", physical_ranges::positive_stiffness_N_per_m);
    e.damping_N_s_per_m = ranged(t, "damping_N_s_per_m", physical_ranges::damping_N_s_per_m, 0.0);
    return e;
  }
};

}  // namespace railstab::scene_reading
