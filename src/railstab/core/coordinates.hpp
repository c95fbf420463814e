#pragma once
// The six coordinates of a body relative to its track frame (frames and
// conventions: scene/scene_spec.hpp).
#include <array>
#include <string>

namespace railstab {

enum class CoordinateIndex { x = 0, y = 1, z = 2, roll = 3, pitch = 4, yaw = 5 };
inline constexpr int kCoordinatesPerBody = 6;
// CSV / report names of the six coordinates, units in the name.
inline const std::array<std::string, 6> kCoordinateNames = {"x_m", "y_m", "z_m",
                                                            "roll_rad", "pitch_rad", "yaw_rad"};
// Scene-file names of the six coordinates (for `free = [...]`).
inline const std::array<std::string, 6> kCoordinateKeys = {"x", "y", "z", "roll", "pitch", "yaw"};

}  // namespace railstab
