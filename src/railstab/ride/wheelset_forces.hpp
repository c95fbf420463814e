#pragma once
// The forces a wheelset puts into the track and the quantities EN 14363
// judges them by (docs/ride_quantities.md), at a state:
//   Sum Y: the track shift force, the sum of both wheels' lateral forces on
//          the rails along the wheelset's track frame's y axis (to the left,
//          in the track plane), Sum Y = Y_left - Y_right with each wheel's Y
//          outwards positive (model/wheel_forces.hpp);
//   the wheelset's angle of attack: its yaw relative to the track tangent
//          (rad, positive counter-clockwise seen from above, as the yaw
//          coordinate);
//   Delta Q / Q0 per wheel: the wheel unloading (Q0 - Q) / Q0, Q0 the wheel's
//          static load;
//   Prud'homme's limit on Sum Y: alpha (10 kN + P0 / 3), P0 the static axle
//          load in kN (EN 14363; alpha [assessment] prudhomme_factor).
// Static loads are the wheel loads of the same vehicle in its equilibrium on
// straight, level track (static_wheel_loads).
#include <railstab/model/model.hpp>
#include <railstab/model/wheel_forces.hpp>

#include <Eigen/Dense>

#include <vector>

namespace railstab {

// Q0 of each wheel, per wheelset in body order.
struct StaticWheelLoad {
  int body = 0;
  double left_N = 0.0, right_N = 0.0;
  double axle_load_N() const { return left_N + right_N; }
};

// The vehicle's equilibrium on straight, level track at the speed (the same
// model with its track replaced by one tangent; no speed ramp): one Newton
// solve from the nominal position; where that fails (above the critical speed the solver's
// pseudo-transient fallback cannot reach an unstable steady state), solved at
// kStaticLoadStartSpeed_m_per_s (or half the speed if lower) and continued in
// speed. Throws EquilibriumError if it has none.
inline constexpr double kStaticLoadStartSpeed_m_per_s = 10.0;
std::vector<StaticWheelLoad> static_wheel_loads(const Model& model, double speed_m_per_s);

// Prud'homme's limit alpha (10 kN + P0 / 3) in N, P0 the static axle load.
double prudhomme_limit_N(double static_axle_load_N, double prudhomme_factor);

struct WheelsetForces {
  int body = 0;
  double sum_y_N = 0.0;       // track shift force, +y_T (left)
  double axle_load_N = 0.0;   // Q_left + Q_right
  double angle_of_attack_rad = 0.0;
  WheelForces left, right;
  double left_static_load_N = 0.0, right_static_load_N = 0.0;  // Q0
  double left_delta_q_over_q0 = 0.0, right_delta_q_over_q0 = 0.0;
  double static_axle_load_N = 0.0;
  double prudhomme_limit_N = 0.0;
};

// Every wheelset at (t, V0, x), in body order; `loads` from
// static_wheel_loads of the same model.
std::vector<WheelsetForces> wheelset_forces(const Model& model, double speed_m_per_s, double t_s,
                                            const Eigen::VectorXd& x,
                                            const std::vector<StaticWheelLoad>& loads,
                                            double prudhomme_factor);

}  // namespace railstab
