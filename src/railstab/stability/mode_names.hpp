#pragma once
// Mode names that say what moves, from the mode shape (stability/mode_shape.hpp).
//
// Body roles come from the topology, not from names: a wheelset is a body of
// kind wheelset; a bogie frame is a rigid body joined by a force element to a
// wheelset; every other rigid body is a car body. A running-gear unit is a
// bogie frame with the wheelsets joined to it, or a wheelset joined to no
// frame.
//
// Rules, on the kinetic-energy shares T_i of the mode:
//  1. The car bodies or the running gear (wheelsets and frames), whichever
//     holds more kinetic energy, name the mode.
//  2. Car body: the plane (longitudinal x; vertical z, pitch; lateral y,
//     roll, yaw) with the most energy, then within it: "yaw" when yaw holds
//     at least as much as lateral and roll together; "roll" when lateral
//     holds under a tenth of lateral + roll; otherwise a sway named by the
//     roll centre, the height h = Re(y / roll) above the centre of mass
//     where the lateral motion y - h roll vanishes (a point at height h
//     moves laterally by y - h roll for a small roll about x, frames/rotations.hpp):
//     above it (h > 0) "lower sway", below it "upper sway". "bounce" or
//     "pitch" in the vertical plane.
//  3. Running gear: the motion with the most energy over all its bodies:
//     lateral + yaw, roll, vertical ("vertical" on a wheelset, "bounce" on a
//     frame), frame pitch, wheelset spin (its pitch), longitudinal.
//     Lateral + yaw is "hunting" only when the wheelsets move as a rolling
//     wheelset does (kinematic hunting, Klingel): yaw psi and lateral shift y
//     of the wheelset with the most lateral + yaw energy related by
//     dy/dt = V psi, i.e. psi / y = i omega / V for lambda = sigma + i omega:
//     the phase of psi / y within kKinematicPhaseToleranceDeg of +90 deg and
//     |psi / y| within a factor kKinematicRatioFactor of omega / V (hunting
//     frequencies: f = V / wavelength). Otherwise "lateral/yaw" (an
//     oscillating mode at standstill, a 12 Hz wheelset mode, a real one).
//     Who moves: the unit holding at least 3/4 of the running gear's energy
//     (and inside it a wheelset holding 3/4 of the unit's: then that
//     wheelset; a frame holding under 1/4 of its unit's: "<frame>
//     wheelsets"), by its scene name; else, two units sharing it:
//     "bogie hunting, bogies in phase" or "anti-phase" when the phase
//     theta = arg(conj(a) b) of their representative displacements (the
//     frame's, or the lone wheelset's, in the motion's main coordinate; a
//     the unit first in scene order) is within kPhaseToleranceDeg of 0 or
//     180 deg, else "bogie2 70 deg behind bogie1" (theta < 0) or "ahead of"
//     (theta > 0), rounded to 10 deg; more units: "..., coupled".
//  4. A non-oscillatory (real) mode gets ", aperiodic" unless its motion
//     word already says so; a neutral mode is "neutral (rigid-body/cyclic)".
// Names are made unique within one set of modes by make_names_unique, in
// words: the dominant body, then the frequency.
#include <railstab/model/model.hpp>
#include <railstab/stability/mode_shape.hpp>

#include <complex>
#include <string>
#include <vector>

namespace railstab {

enum class BodyRole { wheelset, bogie_frame, car_body };

struct BodyRoles {
  std::vector<BodyRole> role;  // per body
  // Per body: the running-gear unit it belongs to, named by its frame's body
  // index (a wheelset joined to no frame is its own unit); -1 for car bodies.
  std::vector<int> unit;
  int n_car_bodies = 0;
};

BodyRoles body_roles(const Model& model);

inline constexpr double kPhaseToleranceDeg = 30.0;
inline constexpr double kKinematicPhaseToleranceDeg = 45.0;
inline constexpr double kKinematicRatioFactor = 2.0;

// speed_m_per_s: the speed of the linearisation (hunting needs V > 0).
std::string mode_name_from_shape(const Model& model, const BodyRoles& roles, const ModeShape& shape,
                                 std::complex<double> lambda, double speed_m_per_s);

// The body with the most kinetic energy in the mode ("" for none).
std::string dominant_body(const Model& model, const ModeShape& shape);

// Makes the names of one analysis unique in words: every entry of a group
// of equal names gets its qualifiers, level by level (", mostly wheelset2",
// then ", 3.1 Hz"), until the group's names differ; what is still equal
// after the last level (in ascending `order_key`, e.g. damping; in the order
// given when order_key is empty) gets " (2)", " (3)", ... Entries marked in
// `copies_of` (>= 0: the index whose name this entry repeats, e.g. the
// conjugate partner of a complex mode) take that entry's final name and do
// not count. `qualifiers` may be empty (then counters only) or hold one list
// per entry.
void make_names_unique(std::vector<std::string>& names, const std::vector<int>& copies_of,
                       const std::vector<double>& order_key = {},
                       const std::vector<std::vector<std::string>>& qualifiers = {});

// The qualifiers of a mode for make_names_unique: "mostly <body>" and the
// frequency ("3.1 Hz", two significant digits) or, for a real mode, its
// rate ("rate -12 1/s").
std::vector<std::string> mode_qualifiers(const std::string& dominant_body,
                                         std::complex<double> lambda);

}  // namespace railstab
