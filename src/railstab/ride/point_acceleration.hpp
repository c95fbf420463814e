#pragma once
// Accelerations of points fixed in the rigid bodies (bogie frames, car
// bodies) at a state: the centre of mass of every rigid body and the scene's
// [[bodies.measure_points]] (docs/ride_quantities.md).
//
// The acceleration is the point's absolute (inertial) acceleration, gravity
// not included, in the axes of the body's track frame T (x along the track,
// y to the left in the track plane, z normal to it, upwards). With T moving
// along the track (origin acceleration a_O, angular velocity w_T and its
// rate alpha_T, all in T: track/track.hpp),
//   a_P = a_O + alpha_T x rho + w_T x (w_T x rho) + 2 w_T x rho' + rho'',
//   rho(q) = w + R_TI(roll, yaw) R_IB(pitch) r_B,
// rho the point's position from T's origin in T (w the CM's, r_B the point
// in body axes). rho' and rho'' are the derivatives along the motion q(t),
// exact by nested forward mode (core/dual.hpp): seeded with
// q + e1 q' + e2 q' + e1 e2 q'', rho = rho + (e1 + e2) rho' + e1 e2 rho''
// (since d2/dt2 rho(q(t)) = rho''(q)[q', q'] + rho'(q) q'').
// In steady curving this is the centripetal acceleration of the point's own
// circle; an accelerometer fixed to the body would read R_BT (a_P - g).
#include <railstab/model/model.hpp>

#include <Eigen/Dense>

#include <string>
#include <vector>

namespace railstab {

// A point where accelerations are reported: "<body>" for a CM,
// "<body>.<point>" for a measure point.
struct AccelerationPoint {
  std::string label;
  int body = 0;
  Eigen::Vector3d position_B_m = Eigen::Vector3d::Zero();
};

// The CM of every rigid body (not the wheelsets) in body order, then the
// scene's measure points in scene order.
std::vector<AccelerationPoint> acceleration_points(const Model& model);

// a_P in T of every point at (t, V0, x), in the order of `points`. One
// evaluation of the equations of motion gives q''; throws what it throws.
std::vector<Eigen::Vector3d> point_accelerations(const Model& model, double speed_m_per_s,
                                                 double t_s, const Eigen::VectorXd& x,
                                                 const std::vector<AccelerationPoint>& points);

}  // namespace railstab
