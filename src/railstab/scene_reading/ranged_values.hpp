#pragma once
// Numbers read with their physical range (scene/physical_ranges.hpp): the
// reader refuses a value outside it under the key it came from, e.g.
// "elements[2].stiffness_N_per_m[1]: expected a stiffness in [0, 1e+11] N/m, got -5".
#include <railstab/scene/physical_ranges.hpp>
#include <railstab/scene_reading/table_reader.hpp>

#include <Eigen/Dense>

#include <optional>
#include <string_view>

namespace railstab::scene_reading {

// A number in its physical range, optionally with a default for a missing key.
double ranged(const TableReader& t, std::string_view key, const PhysicalRange& range,
              std::optional<double> fallback = std::nullopt);
// Three numbers, each in the range; the message names the component.
Eigen::Vector3d ranged_each(const TableReader& t, std::string_view key, const PhysicalRange& range,
                            std::optional<Eigen::Vector3d> fallback = std::nullopt);

}  // namespace railstab::scene_reading
