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
//     lateral + yaw ("hunting" when oscillatory, "lateral/yaw" when not), roll,
//     vertical ("vertical" on a wheelset, "bounce" on a frame), frame pitch,
//     wheelset spin (its pitch), longitudinal. Who moves: the unit holding at
//     least 3/4 of the running gear's energy (and inside it a wheelset
//     holding 3/4 of the unit's: then that wheelset; a frame holding under
//     1/4 of its unit's: "<frame> wheelsets"), by its scene name;
//     else, two units sharing it: "bogie hunting, bogies in phase" or
//     "anti-phase" from the sign of Re(conj(a) b) of their representative
//     displacements (the frame's, or the lone wheelset's, in the motion's
//     main coordinate); more units: "..., coupled".
//  4. A non-oscillatory (real) mode gets ", aperiodic" unless its motion
//     word already says so; a neutral mode is "neutral (rigid-body/cyclic)".
// Names are made unique within one set of modes by make_names_unique.
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

std::string mode_name_from_shape(const Model& model, const BodyRoles& roles, const ModeShape& shape,
                                 std::complex<double> lambda);

// Makes the names of one analysis unique: the second, third, ... mode with
// the same name (in ascending `order_key`, e.g. frequency; in the order
// given when order_key is empty) gets " (2)", " (3)", ... Entries marked in
// `copies_of` (>= 0: the index whose name this entry repeats, e.g. the
// conjugate partner of a complex mode) take that entry's final name and do
// not count.
void make_names_unique(std::vector<std::string>& names, const std::vector<int>& copies_of,
                       const std::vector<double>& order_key = {});

}  // namespace railstab
