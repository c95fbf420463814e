#pragma once
// [[bodies]]: name, type = wheelset | rigid_body, mass_kg, inertia_kg_m2
// (principal Jx, Jy, Jz), position_m (in its track frame), track_offset_m
// (0), free (the moving coordinates, default all six), contact (wheelsets:
// a [contacts.<name>]), initial_offset = {y_m = ..., yaw_rad = ...} and
// initial_rate = {y_m_per_s = ...}.
#include <railstab/scene/scene_spec.hpp>
#include <railstab/scene_reading/coordinate_keys.hpp>
#include <railstab/scene_reading/table_reader.hpp>

#include <vector>

namespace railstab::scene_reading {

// Every [[bodies]] table of the document `top`, in file order.
std::vector<BodySpec> read_bodies(const TableReader& top);

}  // namespace railstab::scene_reading
