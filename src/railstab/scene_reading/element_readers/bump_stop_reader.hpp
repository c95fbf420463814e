#pragma once
// Scene keys of a bump_stop (elements/bump_stop.hpp).
#include <railstab/elements/bump_stop.hpp>
#include <railstab/scene_reading/element_readers/element_reader.hpp>
#include <railstab/scene_reading/ranged_values.hpp>

#include <array>

namespace railstab::scene_reading {

template <> struct ElementReader<BumpStop<double>> {
  static constexpr std::array<std::string_view, 5> kKeys = {
      "axis", "clearance_m", "stiffness_N_per_m", "progressive_stiffness_N_per_m3",
      "contact_smoothing_m"};
  static constexpr bool kPointsRequired = true;
  static BumpStop<double> read(const TableReader& t) {
    BumpStop<double> e;
    const Eigen::Vector3d axis = t.vector3("axis", "");
    if (!(axis.norm() > 0.0) || !axis.allFinite())
      t.fail("axis", "a non-zero direction in body 1's frame", format_vector(axis));
    e.axis = axis.normalized();
    e.clearance_m = ranged(t, "clearance_m", physical_ranges::clearance_m);
    e.stiffness_N_per_m =
        ranged(t, "stiffness_N_per_m", physical_ranges::positive_stiffness_N_per_m);
    e.progressive_stiffness_N_per_m3 = ranged(
        t, "progressive_stiffness_N_per_m3", physical_ranges::progressive_stiffness_N_per_m3, 0.0);
    e.contact_smoothing_m =
        ranged(t, "contact_smoothing_m", physical_ranges::smoothing_length_m, 5e-4);
    return e;
  }
  // The mirrored stop acts along the mirrored axis.
  static void mirror_lateral(BumpStop<double>& e) { e.axis.y() = -e.axis.y(); }
};

}  // namespace railstab::scene_reading
