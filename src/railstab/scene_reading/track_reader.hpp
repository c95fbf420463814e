#pragma once
// [track]: start_x_m, start_y_m, start_z_m, start_heading_rad,
// start_curvature_per_m, start_cant_m (all 0), rail_contact_distance_m (1.5),
// and [[track.segments]]: type = tangent | clothoid | arc, length_m,
// end_cant_m (default: the cant the segment starts with); a clothoid takes
// end_radius_m + turn, or end_curvature_per_m; an arc keeps the curvature
// it starts with.
#include <railstab/track/track_spec.hpp>
#include <railstab/scene_reading/table_reader.hpp>

namespace railstab::scene_reading {

// Reads the [track] table of the document `top`.
TrackSpec read_track(const TableReader& top);

}  // namespace railstab::scene_reading
