#pragma once
// The simulation's data files (CSV). Commands write them into an OutputSet
// (io/output_set.hpp), which makes the whole set of a run all-or-nothing.
#include <railstab/integrate/integrator.hpp>
#include <railstab/model/model.hpp>

#include <functional>
#include <ostream>
#include <string>

namespace railstab {

// The CSV header rows below: names quoted per RFC 4180 (io/csv.hpp), so a
// header may span more than one physical line (csv_physical_lines).
std::string trajectory_csv_header(const Model& model);
std::string absolute_roll_csv_header(const Model& model);

// Both writers print `digits` significant digits: 10 in the files; 17 reads
// back as the same double (the Python module's channels).

// CSV: time_s, then <body>.<coordinate> for all six coordinates of every body
// (relative to the body's track frame). Throws, naming the value, if one is
// not finite.
void write_trajectory_csv(std::ostream& out, const Model& model, double speed_m_per_s,
                          const Trajectory& traj, int digits = 10);

// CSV: time_s, then <body>.absolute_roll_rad: the roll of each body relative
// to the horizontal (W), i.e. track cant roll plus the body's own roll;
// exactly asin of the z-component of the body's y axis (Z-X-Y angles in W).
void write_absolute_roll_csv(std::ostream& out, const Model& model, double speed_m_per_s,
                             const Trajectory& traj, int digits = 10);

}  // namespace railstab
