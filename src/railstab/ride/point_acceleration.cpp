#include <railstab/ride/point_acceleration.hpp>

#include <railstab/core/nested_dual.hpp>
#include <railstab/frames/rotations.hpp>
#include <railstab/model/equations_of_motion.hpp>
#include <railstab/model/workspace.hpp>

namespace railstab {

std::vector<AccelerationPoint> acceleration_points(const Model& model) {
  std::vector<AccelerationPoint> points;
  for (size_t b = 0; b < model.bodies.size(); ++b)
    if (!model.bodies[b].wheelset()) points.push_back({model.bodies[b].name, int(b), {0, 0, 0}});
  for (const MeasurePoint& p : model.measure_points)
    points.push_back({model.bodies[size_t(p.body)].name + "." + p.name, p.body, p.position_B_m});
  return points;
}

std::vector<Eigen::Vector3d> point_accelerations(const Model& model, double speed_m_per_s,
                                                 double t_s, const Eigen::VectorXd& x,
                                                 const std::vector<AccelerationPoint>& points) {
  Workspace<double> ws(model);
  Eigen::VectorXd xdot;
  evaluate_rhs<double>(model, ws, t_s, speed_m_per_s, x, xdot);
  // All six coordinates, rates and accelerations of every body. A frozen
  // coordinate of a rigid body is constant or moves at a constant rate
  // (model/model.hpp): its acceleration is zero.
  Eigen::MatrixXd q6, qd6;
  model.full_coordinates(t_s, speed_m_per_s, x, q6, qd6);
  std::vector<Eigen::Vector3d> accelerations;
  accelerations.reserve(points.size());
  for (const AccelerationPoint& point : points) {
    const Body& body = model.bodies[size_t(point.body)];
    Eigen::Matrix<Dual2, 6, 1> q;
    for (int c = 0; c < 6; ++c) {
      const int k = body.state_index[c];
      const double qdd = k >= 0 ? xdot(model.n_coordinates + k) : 0.0;
      const double qd = qd6(c, point.body);
      q(c) = Dual2(Dual1(q6(c, point.body), qd), Dual1(qd, qdd));
    }
    const Vec3<Dual2> r_B = point.position_B_m.cast<Dual2>();
    const Vec3<Dual2> rho = Vec3<Dual2>(q(0), q(1), q(2)) + rot_z(q(5)) * rot_x(q(3)) * rot_y(q(4)) * r_B;
    Eigen::Vector3d p, dp, ddp;
    for (int i = 0; i < 3; ++i) {
      p(i) = rho(i).v.v;
      dp(i) = rho(i).v.d;
      ddp(i) = rho(i).d.d;
    }
    const TrackFrameKinematics& T = ws.frames[size_t(point.body)];
    accelerations.push_back(T.a_WT_T + T.alpha_WT_T.cross(p) + T.w_WT_T.cross(T.w_WT_T.cross(p)) +
                            2.0 * T.w_WT_T.cross(dp) + ddp);
  }
  return accelerations;
}

}  // namespace railstab
