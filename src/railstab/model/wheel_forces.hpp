#pragma once
// Wheel forces Y and Q and the derailment quotient Y/Q of every wheel at a
// state, against Nadal's limit (EN 14363's flange-climbing criterion).
//
// Per wheel, summed over its contact points (tread and flange), in the
// wheelset's track frame T (x along the track, y left, z normal to the
// track plane):
//   Q = the force the wheel presses on its rail along -z_T (> 0 in contact),
//   Y = the force the wheel pushes its rail sideways, positive towards the
//       rail's field side (outwards: +y for the left rail, -y for the right),
// so a flanging wheel has Y > 0. Nadal's limit for flange climbing,
//   (Y/Q)_lim = (tan(beta) - mu) / (1 + mu tan(beta)),
// with beta the wheel's steepest flange angle (profiles only; a cone or a
// linear conicity has no flange: no limit) and mu the contact's friction
// coefficient (Shen-Hedrick-Elkins' mu, Polach's mu_0 at zero slip: the
// larger friction, the lower and so the conservative limit; linear Kalker
// has none: mu = 0.36 then, the value usually paired with Nadal's formula
// in derailment assessments). EN 14363's Y/Q limit of 0.8 for the
// flanging wheel is a separate, tighter acceptance criterion (not applied).
#include <railstab/model/model.hpp>

#include <Eigen/Dense>

#include <optional>
#include <string>
#include <vector>

namespace railstab {

// Friction coefficient for Nadal's limit where the creep law has none.
inline constexpr double kNadalDefaultFrictionCoefficient = 0.36;

struct WheelForces {
  int body = 0;          // index into Model::bodies (a wheelset)
  int side = 1;          // +1 left, -1 right
  double Y_N = 0.0;      // lateral, outwards positive
  double Q_N = 0.0;      // vertical (track normal), downwards on the rail
  double max_contact_angle_rad = 0.0;  // of the loaded contact points
  // Y / Q where Q > 0 (a lifted wheel has none).
  std::optional<double> y_over_q;
  // Nadal's limit for this wheel (profiles only) and the mu it used.
  std::optional<double> nadal_limit;
  double nadal_friction_coefficient = 0.0;
  double flange_angle_rad = 0.0;
  std::string name(const Model& model) const;  // "wheelset1 right wheel"
};

// All wheels of all wheelsets at (t, V, x); throws what the model's
// evaluation throws (evaluate_rhs).
std::vector<WheelForces> wheel_forces(const Model& model, double speed_m_per_s, double t_s,
                                      const Eigen::VectorXd& x);

// The wheel with the largest Y/Q over its Nadal limit, where it exceeds it
// (profiles only); nullopt when every wheel is within its limit.
std::optional<WheelForces> wheel_beyond_nadal_limit(const std::vector<WheelForces>& wheels);

// "wheelset1 right wheel Y/Q 0.93 exceeds Nadal's limit 0.81 (flange angle
// 70.0 deg, mu 0.40): flange climbing, derailment risk"
std::string nadal_warning(const Model& model, const WheelForces& wheel);

}  // namespace railstab
