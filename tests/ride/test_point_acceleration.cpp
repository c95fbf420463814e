// Point accelerations (ride/point_acceleration.hpp) against second
// differences of the points' positions along a time-domain run: the
// positions come from the model's own kinematics (kinematics/body_motion.hpp),
// the accelerations from nested forward mode and the frame's transport terms,
// two independent routes.
#include <gtest/gtest.h>

#include "support/state_index.hpp"
#include "support/test_files.hpp"

#include <railstab/integrate/integrator.hpp>
#include <railstab/model/equations_of_motion.hpp>
#include <railstab/model/workspace.hpp>
#include <railstab/ride/point_acceleration.hpp>
#include <railstab/setup/prepare_scene.hpp>

#include <cmath>

namespace railstab {
namespace {

// The point's position in W at output i.
Eigen::Vector3d position_W(const Model& model, double V, const Trajectory& traj, size_t i,
                           const AccelerationPoint& p) {
  Workspace<double> ws(model);
  compute_all_body_motions<double>(model, ws, traj.times_s[i], V, traj.states[i]);
  const BodyMotion<double>& m = ws.motions[size_t(p.body)];
  return m.p_W + m.R_WF * p.position_B_m;
}

void check_against_second_differences(const std::string& case_name, double arc_length_m) {
  SceneOverrides o;
  o.reference_arc_length_m = arc_length_m;
  PreparedScene s = prepare_scene(test::case_path(case_name), o);
  Model& model = s.model;
  const int carbody = model.find_body("carbody"), bogie = model.find_body("bogie1");
  model.measure_points.push_back({carbody, "corner", {6.0, 1.2, 0.8}});
  model.measure_points.push_back({bogie, "axle_box", {1.25, -1.0, -0.3}});
  const double V = s.speed_m_per_s;
  // Set the bodies swinging: lateral, roll and yaw rates of every rigid body.
  Eigen::VectorXd x0 = s.equilibrium.state;
  for (const char* body : {"carbody", "bogie1", "bogie2"}) {
    x0(test::state_index(model, std::string(body) + ".y_m/s")) += 0.05;
    x0(test::state_index(model, std::string(body) + ".roll_rad/s")) += 0.02;
    x0(test::state_index(model, std::string(body) + ".yaw_rad/s")) += 0.01;
  }
  IntegrationOptions opt;
  opt.kind = IntegratorKind::cvode_bdf;
  opt.t_end_s = 0.3;
  const double h = 5e-4;
  opt.output_interval_s = h;
  opt.relative_tolerance = 1e-11;
  opt.absolute_tolerance = 1e-13;
  const Trajectory traj = integrate(model, V, x0, opt);
  ASSERT_GE(traj.times_s.size(), 600u);
  const std::vector<AccelerationPoint> points = acceleration_points(model);
  ASSERT_EQ(points.size(), 5u);  // three CMs and two measure points
  // Past the first steps, whose start transients need a finer h.
  for (size_t i : {size_t(200), size_t(400), size_t(560)}) {  // t = 0.1, 0.2, 0.28 s
    const std::vector<Eigen::Vector3d> a_T = point_accelerations(model, V, traj.times_s[i], traj.states[i], points);
    Workspace<double> ws(model);
    ws.update_frames(model, traj.times_s[i], V);
    for (size_t p = 0; p < points.size(); ++p) {
      const Eigen::Vector3d a_W = ws.frames[size_t(points[p].body)].R_WT * a_T[p];
      auto at = [&](size_t k) { return position_W(model, V, traj, k, points[p]); };
      // Fourth-order central second difference: its error is h^4 a^(6)/90;
      // measured, it falls 16-fold per halving of h (4e-3 s: 9e-4 m/s2,
      // 2e-3 s: 6e-5, 1e-3 s: 4e-6, 5e-4 s: 2.5e-7 at t = 0.1 s on straight
      // track), so the accelerations are exact to the differences' error. A
      // missing transport term is far larger: the Coriolis term 2 w_T x rho'
      // alone is ~2e-3 m/s2 in the arc. Rounding of positions ~2e3 m from W's
      // origin: 2.2e-16 * 2e3 * (64 / 12) / h^2 = 1e-5 m/s2.
      const Eigen::Vector3d difference =
          (-at(i + 2) + 16.0 * at(i + 1) - 30.0 * at(i) + 16.0 * at(i - 1) - at(i - 2)) / (12.0 * h * h);
      const double tolerance = 1e-5 * a_W.norm() + 1e-5;
      EXPECT_NEAR((a_W - difference).norm(), 0.0, tolerance)
          << case_name << " " << points[p].label << " at t = " << traj.times_s[i] << ": a_W "
          << a_W.transpose() << ", second difference " << difference.transpose();
    }
  }
}

TEST(PointAcceleration, EqualsSecondDifferencesOfThePositionOnStraightTrack) {
  check_against_second_differences("thesis_vehicle_tangent", 100.0);
}

TEST(PointAcceleration, EqualsSecondDifferencesOfThePositionInTheCantedArc) {
  // The frames turn (1/R) and are canted: the transport terms enter.
  check_against_second_differences("thesis_vehicle_curve", 2000.0);
}

}  // namespace
}  // namespace railstab
