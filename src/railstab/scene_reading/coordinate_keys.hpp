#pragma once
// The keys of a body's initial_offset and initial_rate tables, named once
// for the bodies reader and the checker.
#include <array>
#include <string_view>

namespace railstab::scene_reading {

// One per coordinate, in the order x, y, z, roll, pitch, yaw.
struct CoordinateKey {
  std::string_view key;
  std::string_view unit;
};
inline constexpr std::array<CoordinateKey, 6> kOffsetKeys = {{{"x_m", "m"},
                                                              {"y_m", "m"},
                                                              {"z_m", "m"},
                                                              {"roll_rad", "rad"},
                                                              {"pitch_rad", "rad"},
                                                              {"yaw_rad", "rad"}}};
inline constexpr std::array<CoordinateKey, 6> kRateKeys = {{{"x_m_per_s", "m/s"},
                                                            {"y_m_per_s", "m/s"},
                                                            {"z_m_per_s", "m/s"},
                                                            {"roll_rad_per_s", "rad/s"},
                                                            {"pitch_rad_per_s", "rad/s"},
                                                            {"yaw_rad_per_s", "rad/s"}}};

}  // namespace railstab::scene_reading
