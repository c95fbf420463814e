// The a posteriori error estimate that every `simulate` run reports (the same
// run at 100x tighter tolerances) against the true error (a reference at
// rtol 1e-10 with a different method).
#include <railstab/setup/prepare_scene.hpp>
#include <railstab/integrate/error_estimate.hpp>
#include <railstab/integrate/work_precision.hpp>

#include <gtest/gtest.h>

using namespace railstab;

TEST(ErrorEstimate, TracksTheTrueErrorOfTheDefaultIntegrator) {
  SceneOverrides o;
  o.speed_m_per_s = 20.0;
  const PreparedScene scene =
      prepare_scene(std::string(RAILSTAB_CASES_DIR) + "/thesis_bogie_tangent.toml", o);
  const Eigen::VectorXd x0 = perturbed_initial_state(scene);
  IntegrationOptions opt = integration_options_for(scene.spec.simulation);
  opt.t_end_s = 3.0;
  ASSERT_EQ(opt.kind, IntegratorKind::arkode_dirk);  // the scene's default
  const Trajectory run = integrate(scene.model, scene.speed_m_per_s, x0, opt);
  const ErrorEstimate e = estimate_integration_error(scene.model, scene.speed_m_per_s, x0, opt, run);

  IntegrationOptions exact = opt;
  exact.kind = IntegratorKind::cvode_bdf;
  exact.order = 0;
  exact.relative_tolerance = 1e-10;
  exact.absolute_tolerance = 1e-13;
  const Trajectory ref = integrate(scene.model, scene.speed_m_per_s, x0, exact);
  const double true_error = trajectory_position_error(scene.model, run, ref);
  std::printf("[error estimate] estimated %.3g, true %.3g (rtol %.0e)\n", e.position_error,
              true_error, opt.relative_tolerance);
  // The tight run's own error is ~100^(-4/5) ~ 1/40 of the loose one's, so
  // the estimate is within a few percent; 25 % leaves room for error
  // cancellation between the two runs.
  EXPECT_GT(true_error, 0.0);
  EXPECT_NEAR(e.position_error, true_error, 0.25 * true_error);
  EXPECT_LE(e.lateral_error, e.position_error);
}
