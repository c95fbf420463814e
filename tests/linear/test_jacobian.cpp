// The AD Jacobian equals central differences on every shipped scene.
#include <railstab/setup/prepare_scene.hpp>
#include <railstab/linear/jacobian.hpp>

#include <gtest/gtest.h>

#include <filesystem>

using namespace railstab;

class JacobianOnCase : public ::testing::TestWithParam<std::string> {};

// The 5-point central differences have truncation and round-off errors near
// 1e-9 of a row's largest entry here; 1e-6 of it (rows mix m/s^2 and rad/s^2
// scales) leaves room for that and still catches any wrong derivative.
TEST_P(JacobianOnCase, AdEqualsCentralDifferences) {
  const PreparedScene scene =
      prepare_scene(std::string(RAILSTAB_CASES_DIR) + "/" + GetParam() + ".toml", {});
  Eigen::VectorXd x = perturbed_initial_state(scene);
  // Off the symmetric point, laterally only: the wheel penetrations (~80 um)
  // must stay large against the difference step (6 um) for delta^1.5.
  for (int k = 0; k < scene.model.n_coordinates; ++k) {
    const int c = scene.model.coordinate_of_state[k].second;
    if (c == int(CoordinateIndex::y) || c == int(CoordinateIndex::yaw)) x(k) += 2e-4;
  }
  const Eigen::MatrixXd ad = rhs_jacobian_ad(scene.model, scene.speed_m_per_s, 0.3, x);
  const Eigen::MatrixXd cd = rhs_jacobian_central_difference(scene.model, scene.speed_m_per_s, 0.3, x);
  for (Eigen::Index r = 0; r < ad.rows(); ++r) {
    const double scale = std::max(ad.row(r).cwiseAbs().maxCoeff(), 1e-12);
    const double err = (ad.row(r) - cd.row(r)).cwiseAbs().maxCoeff();
    EXPECT_LT(err, 1e-6 * scale) << "row " << scene.model.state_name(int(r));
  }
}

INSTANTIATE_TEST_SUITE_P(Cases, JacobianOnCase,
                         ::testing::Values("thesis_bogie_tangent", "thesis_bogie_curve",
                                           "thesis_vehicle_tangent", "thesis_vehicle_curve",
                                           "textbook_wheelset", "textbook_bogie"));
