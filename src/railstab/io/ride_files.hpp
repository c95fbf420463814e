#pragma once
// `simulate`'s ride-quantity CSVs (docs/outputs.md, docs/ride_quantities.md),
// written from a RideHistory. Headers quoted per RFC 4180 (io/csv.hpp).
//
// <stem>_wheel_forces.csv: time_s, then per wheelset
//   <ws>.sum_y_N, <ws>.angle_of_attack_rad, and per wheel (left, right)
//   <ws>.<side>.lateral_force_N (Y, outwards), <ws>.<side>.wheel_load_N (Q),
//   <ws>.<side>.y_over_q (empty where the wheel is lifted, Q = 0),
//   <ws>.<side>.delta_q_over_q0.
// <stem>_accelerations.csv: time_s, then per point (ride/point_acceleration.hpp)
//   <point>.longitudinal_acceleration_m_per_s2, .lateral_..., .vertical_...
//   (absolute, gravity excluded, in the body's track frame).
#include <railstab/model/model.hpp>
#include <railstab/ride/ride_history.hpp>

#include <ostream>
#include <string>

namespace railstab {

// Columns per wheelset and per acceleration point (the plots pick them).
inline constexpr int kWheelForceColumnsPerWheelset = 10;
inline constexpr int kAccelerationColumnsPerPoint = 3;

std::string wheel_forces_csv_header(const Model& model, const RideHistory& history);
std::string accelerations_csv_header(const RideHistory& history);

// `digits`: significant digits (as output_files.hpp).
void write_wheel_forces_csv(std::ostream& out, const Model& model, const RideHistory& history,
                            int digits = 10);
void write_accelerations_csv(std::ostream& out, const RideHistory& history,
                             int digits = 10);

}  // namespace railstab
