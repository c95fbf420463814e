#pragma once
// The plausible range of every kind of number a scene file holds, in one
// place. The scene reader (scene_reading/) refuses a value outside its
// range with the range in the message, e.g.
//   "cases/x.toml: bodies[0].mass_kg: expected a mass in [0.1, 1e6] kg, got 1e-300".
//
// Why ranges at all: a value such as a mass of 1e-300 kg, a stiffness of
// 1e20 N/m or E = 1 Pa is finite, so it passed the earlier "finite and
// positive" checks, and then failed deep in the model (NaN in the eigen-
// solver, a Hertz ellipse with negative curvature) or made the integrator
// take billions of steps. The ranges are deliberately wide: a value outside
// one is one a railway engineer would call "certainly an input error" (a
// unit slip by 1e3 or more, a missing exponent), not merely unusual. They
// cover everything from a light tram wheelset on a 10 m test rig to a
// 200 t locomotive on a high-speed line, with room on both sides.
//
// Limits are inclusive unless `low_open` (then the value must be > low;
// used where 0 means "not physical" but tiny positive values are fine).
// Keys that may be 0 (dampings, stiffnesses of a free direction) have
// low = 0, closed.
#include <cstddef>
#include <string_view>

namespace railstab {

struct PhysicalRange {
  std::string_view noun;  // "a mass": the message reads "expected <noun> in [..] <unit>"
  double low, high;
  std::string_view unit;  // "kg", "N/m"; empty for a ratio
  bool low_open = false;
  bool contains(double value) const {
    return (low_open ? value > low : value >= low) && value <= high;
  }
};

namespace physical_ranges {

// --- bodies -------------------------------------------------------------------
// A wheelset is ~1 t, a car body ~40 t, a locomotive ~120 t; 0.1 kg admits
// rig models and test bodies, 1e6 kg (1000 t) is more than any single body.
inline constexpr PhysicalRange mass_kg{"a mass", 0.1, 1e6, "kg"};
// Principal moments: a car body's Jz is ~2.5e6 kg m2; 1e8 is a 100 m long
// 300 t body. Below 1e-4 kg m2 a body of >= 0.1 kg would be smaller than a coin.
inline constexpr PhysicalRange inertia_kg_m2{"a principal moment of inertia", 1e-4, 1e8,
                                             "kg m2"};
// A body's nominal centre of mass in its track frame, and element attachment
// points in body frames: a vehicle is < 30 m long and < 5 m high.
inline constexpr PhysicalRange coordinate_m{"a coordinate", -100.0, 100.0, "m"};
// A measure point from its body's CM: within a car body's half length.
inline constexpr PhysicalRange measure_point_m{"a measure point position", -50.0, 50.0, "m"};
// alpha of Prud'homme's limit: 0.85 (freight) and 1.0 (others) in EN 14363.
inline constexpr PhysicalRange prudhomme_factor{"a Prud'homme factor alpha", 0.0, 2.0, "", true};
// track_offset_m: a train of several vehicles spans < 1 km.
inline constexpr PhysicalRange track_offset_m{"a track offset", -1e4, 1e4, "m"};
// initial_offset: a perturbation, not a new position (flange clearance ~10 mm;
// 1 m or 1 rad is far outside any linear or flangeless model).
inline constexpr PhysicalRange offset_m{"an initial offset", -1.0, 1.0, "m"};
inline constexpr PhysicalRange offset_rad{"an initial offset", -1.0, 1.0, "rad"};
inline constexpr PhysicalRange rate_m_per_s{"an initial rate", -100.0, 100.0, "m/s"};
inline constexpr PhysicalRange rate_rad_per_s{"an initial rate", -1000.0, 1000.0, "rad/s"};

// --- force elements -------------------------------------------------------------
// Primary springs are 1e5-1e8 N/m, a rigid traction rod ~1e9 N/m; 1e11 N/m
// is stiffer than the steel of the rail in contact.
inline constexpr PhysicalRange stiffness_N_per_m{"a stiffness", 0.0, 1e11, "N/m"};
inline constexpr PhysicalRange positive_stiffness_N_per_m{"a stiffness", 0.0, 1e11, "N/m",
                                                          true};
inline constexpr PhysicalRange progressive_stiffness_N_per_m3{"a progressive stiffness", 0.0,
                                                              1e16, "N/m^3"};
// Anti-roll bars and yaw springs: ~1e6 N m/rad; a secondary roll stiffness of
// a whole car ~1e7.
inline constexpr PhysicalRange stiffness_N_m_per_rad{"a rotational stiffness", 0.0, 1e11,
                                                     "N m/rad"};
inline constexpr PhysicalRange positive_stiffness_N_m_per_rad{"a rotational stiffness", 0.0,
                                                              1e11, "N m/rad", true};
// Yaw dampers are ~1e6 N s/m (effective, before blow-off), vertical dampers
// ~1e4; 1e8 N s/m is a rigid link for any vehicle motion. (The issue's
// contact damping of 1e12 N s/m made the integrator stall.)
inline constexpr PhysicalRange damping_N_s_per_m{"a damping", 0.0, 1e8, "N s/m"};
inline constexpr PhysicalRange damping_N_m_s_per_rad{"a rotational damping", 0.0, 1e9,
                                                     "N m s/rad"};
// Actuators: a tilt or active-steering actuator gives ~1e5 N; 1 GN (the issue)
// is 1000 times a locomotive's tractive effort.
inline constexpr PhysicalRange actuator_force_N{"an actuator force", -1e7, 1e7, "N"};
inline constexpr PhysicalRange actuator_moment_N_m{"an actuator moment", -1e7, 1e7, "N m"};
// Force tables: deflections and damper velocities, and the forces in them.
inline constexpr PhysicalRange table_deflection_m{"a deflection", -10.0, 10.0, "m"};
inline constexpr PhysicalRange table_velocity_m_per_s{"a velocity", -100.0, 100.0, "m/s"};
inline constexpr PhysicalRange table_force_N{"a force", -1e8, 1e8, "N"};
// The scale factor of a table's forces (spring_force_scale,
// damper_force_scale): a study or a sensitivity varies a table damper by it.
// 0 is refused (a series damper's velocity is the inverse table at F / scale);
// 100 times a measured characteristic is certainly a unit slip.
inline constexpr PhysicalRange table_force_scale{"a scale factor", 0.0, 100.0, "", true};
// Bump-stop clearances and smoothing lengths, anti-roll-bar link spacing.
inline constexpr PhysicalRange clearance_m{"a clearance", 0.0, 1.0, "m"};
inline constexpr PhysicalRange smoothing_length_m{"a smoothing length", 1e-7, 0.1, "m"};
inline constexpr PhysicalRange link_half_spacing_m{"a link half-spacing", 0.01, 10.0, "m", false};

// --- wheel-rail contact -----------------------------------------------------------
// Steel is 2.1e11 Pa; 1e8 Pa admits polymer tyres; up to 1e14 Pa admits
// stiff-contact studies (cases/extreme_stiff_contact.toml: 100 x steel).
inline constexpr PhysicalRange young_modulus_Pa{"a Young's modulus", 1e8, 1e14, "Pa"};
// Wheel radii: 0.15 m (light rail, freight bogie small wheels) to 1.25 m
// (steam driving wheels); 0.05 to 3 m.
inline constexpr PhysicalRange rolling_radius_m{"a rolling radius", 0.05, 3.0, "m"};
// Rail head transverse radii 0.08-0.3 m; up to 1000 m admits a flat rail head.
inline constexpr PhysicalRange rail_head_radius_m{"a rail head radius", 1e-3, 1e3, "m"};
// Half the distance between the contact points: 0.3 m (600 mm gauge) to
// 0.85 m (1676 mm gauge); 0.1 to 2 m.
inline constexpr PhysicalRange half_contact_distance_m{"a half contact distance", 0.1, 2.0, "m"};
inline constexpr PhysicalRange rail_contact_distance_m{"a rail contact distance", 0.2, 4.0, "m"};
// Nominal flange clearance ~5-10 mm; up to 0.2 m for models without flanges.
inline constexpr PhysicalRange flange_clearance_m{"a flange clearance", 0.0, 0.2, "m", true};
inline constexpr PhysicalRange conicity{"a conicity", 0.0, 1.0, "", true};
// Knife-edge cone angle gamma (conicity tan(gamma)): new treads are 1:40 to
// 1:20 (0.025-0.05 rad), equivalent conicities of worn wheels reach ~0.4
// (EN 14363's highest reference conicity for stability tests is 0.4 below
// 160 km/h). Below 0.01 rad the kinematic wavelength 2 pi sqrt(r0 e0 / gamma)
// exceeds 100 m (a cylinder, not a cone); above 0.4 rad (23 degrees) the
// "cone" is a flange flank (~1.2 rad), which a knife-edge tread model cannot
// represent. Both ends are input errors (a degree given as rad, 0 for "none").
inline constexpr PhysicalRange cone_angle_rad{"a knife-edge cone angle", 0.01, 0.4, "rad"};
// A wheel load: 1e5 N under a 20 t axle load; 1e6 N would be a 200 t axle.
inline constexpr PhysicalRange wheel_load_N{"a wheel load", 0.0, 1e6, "N", true};
// Kalker coefficients at the largest wheel loads: f11, f22 ~ 1e7 N,
// f23 ~ 1e5 N m, f33 ~ 1e3 N m2.
inline constexpr PhysicalRange creep_coefficient_N{"a creep coefficient", 0.0, 1e10, "N"};
inline constexpr PhysicalRange creep_coefficient_N_m{"a creep coefficient", -1e9, 1e9, "N m"};
inline constexpr PhysicalRange creep_coefficient_N_m2{"a creep coefficient", 0.0, 1e8, "N m2"};

// --- track ---------------------------------------------------------------------------
inline constexpr PhysicalRange segment_length_m{"a segment length", 1e-3, 1e6, "m"};
// Tram curves go down to ~15 m radius; 5 m is a turntable.
inline constexpr PhysicalRange curve_radius_m{"a curve radius", 5.0, 1e8, "m"};
inline constexpr PhysicalRange curvature_per_m{"a curvature", -0.2, 0.2, "1/m"};
// Track coordinates of the start: a line on Earth is within 1e7 m.
inline constexpr PhysicalRange track_position_m{"a track position", -1e7, 1e7, "m"};
inline constexpr PhysicalRange heading_rad{"a heading", -100.0, 100.0, "rad"};
inline constexpr PhysicalRange arc_length_m{"an arc length", 0.0, 1e7, "m"};

// --- scene and simulation ----------------------------------------------------------------
// The fastest wheel-rail runs are ~160 m/s; also the CLI's --speed range.
inline constexpr PhysicalRange speed_m_per_s{"a speed", 0.0, 300.0, "m/s"};
inline constexpr PhysicalRange gravity_m_per_s2{"a gravity", 0.0, 100.0, "m/s2"};
// With a Hertz wheel-rail contact the weight makes the wheel loads, and the
// wheel loads the creep coefficients: gravity 0 leaves wheels unloaded
// (axle loads of 1e-7 kN, no creep force). 9.81 on Earth; 1 m/s2 admits
// reduced-gravity studies, anything below is an input error.
inline constexpr PhysicalRange gravity_with_hertz_contact_m_per_s2{
    "a gravity (a Hertz wheel-rail contact carries the weight)", 1.0, 100.0, "m/s2"};
// Lowest speed at which the creep laws are used. Creepages are slip
// velocities divided by V (ERRATA 10): the creep forces' damping f / V grows
// without bound as V -> 0 (at 1e-9 m/s the lateral creep time constant
// m V / f22 of a wheelset is ~1e-16 s, and an integration runs away).
// Kalker's steady-state theory also needs the contact patch (semi-axis
// a ~ 6 mm) to roll over its own length fast against the motion: the
// relaxation time a / V is 0.06 s at 0.1 m/s, a tenth of a 1.6 Hz period.
// Below it a transient creep model (or none) would be needed.
inline constexpr double kMinimumCreepSpeed_m_per_s = 0.1;
inline constexpr PhysicalRange t_end_s{"an end time", 0.0, 1e5, "s", true};
inline constexpr PhysicalRange output_interval_s{"an output interval", 1e-7, 1e3, "s"};
inline constexpr PhysicalRange relative_tolerance{"a relative tolerance", 1e-14, 1.0, ""};
inline constexpr PhysicalRange absolute_tolerance{"an absolute tolerance", 1e-20, 1.0,
                                                  "(state units)"};
// At most this many stored output states per run (t_end_s / output_interval_s);
// the integrator refuses more (integrate/integrator.hpp, max_outputs).
inline constexpr double kMaxOutputs = 1e6;

// --- names ------------------------------------------------------------------------------
// Scene, body, element and contact names: at most this many bytes, and no
// control characters (see scene_reading/scene_messages.cpp, name_problem, for why).
inline constexpr size_t kMaxNameBytes = 100;

}  // namespace physical_ranges
}  // namespace railstab
