// Every case scene runs; the thesis results of chapter 5 are reproduced
// qualitatively (ERRATA 15).
#include <railstab/setup/prepare_scene.hpp>
#include <railstab/integrate/integrator.hpp>

#include <gtest/gtest.h>
#include "support/test_files.hpp"

using namespace railstab;

namespace {

using railstab::test::case_path;

Trajectory run(const PreparedScene& scene, double t_end) {
  // The scene's integrator and tolerances: the defaults users run.
  IntegrationOptions opt = integration_options_for(scene.spec.simulation);
  opt.t_end_s = t_end;
  opt.output_interval_s = 0.01;
  return integrate(scene.model, scene.speed_m_per_s, perturbed_initial_state(scene), opt);
}

double max_abs_lateral(const PreparedScene& s, const Trajectory& traj, const std::string& body,
                       double from_s) {
  const int k = s.model.bodies[s.model.find_body(body)].state_index[1];
  double m = 0.0;
  for (size_t i = 0; i < traj.times_s.size(); ++i)
    if (traj.times_s[i] >= from_s) m = std::max(m, std::abs(traj.states[i](k)));
  return m;
}

}  // namespace

class CaseRuns : public ::testing::TestWithParam<std::string> {};

// Static equilibrium converges and a short run stays finite.
TEST_P(CaseRuns, EquilibriumAndShortRun) {
  const PreparedScene scene = prepare_scene(case_path(GetParam()), {});
  EXPECT_LE(scene.equilibrium.max_acceleration, 1e-7);
  const Trajectory traj = run(scene, 0.5);
  EXPECT_TRUE(traj.stopped_early.empty()) << traj.stopped_early;
  for (const Eigen::VectorXd& x : traj.states) ASSERT_TRUE(x.allFinite());
}

INSTANTIATE_TEST_SUITE_P(Cases, CaseRuns,
                         ::testing::Values("thesis_bogie_tangent", "thesis_bogie_curve",
                                           "thesis_vehicle_tangent", "thesis_vehicle_curve",
                                           "textbook_wheelset", "textbook_bogie"));

// Thesis 5.5.1.1: 1 mm initial offset of the leading wheelset decays at
// 20 m/s (to below 5 % in the last 3 s of 20 s) ...
TEST(ThesisBogie, DecaysAt20) {
  const PreparedScene scene = prepare_scene(case_path("thesis_bogie_tangent"), {20.0, 20.0, {}, {}, {}});
  const Trajectory traj = run(scene, 20.0);
  EXPECT_LT(max_abs_lateral(scene, traj, "wheelset1", 17.0), 0.05e-3);
}

// ... and grows at 40 m/s until the flange clearance (the model's validity
// limit) is reached.
TEST(ThesisBogie, GrowsAt40) {
  const PreparedScene scene = prepare_scene(case_path("thesis_bogie_tangent"), {40.0, 20.0, {}, {}, {}});
  const Trajectory traj = run(scene, 20.0);
  EXPECT_NE(traj.stopped_early.find("flange clearance"), std::string::npos);
  EXPECT_GT(max_abs_lateral(scene, traj, "wheelset1", 0.0), 5e-3);
}

// Thesis 5.5.1.2: entering the left-hand curve the wheelsets shift towards
// the outer (right, -y) rail and settle in the arc.
TEST(ThesisBogie, ShiftsOutwardsInCurve) {
  const PreparedScene scene = prepare_scene(case_path("thesis_bogie_curve"), {});
  const Trajectory traj = run(scene, 16.0);
  const int k = scene.model.bodies[scene.model.find_body("wheelset1")].state_index[1];
  const double y_end = traj.states.back()(k);
  EXPECT_LT(y_end, -3e-3);  // beyond the pure-rolling shift r0 e0/(lambda R) = 3.4 mm
  EXPECT_TRUE(traj.stopped_early.empty()) << traj.stopped_early;
}
