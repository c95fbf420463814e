// The time domain's sparse Newton matrix (integrate/sparse_newton.hpp,
// SUNLinSol_KLU on the AD Jacobian's pattern):
//  - the CSC layout holds the pattern plus the diagonal, each entry once,
//    rows sorted in each column, and every pattern entry's position points
//    at its (row, column);
//  - a run with the sparse Newton matrix follows the dense run within the
//    integrator's own error (the same Newton systems, solved by another LU):
//    the thesis vehicle (ARKODE SDIRK and CVODE BDF order 2) and the four-car
//    train; and the callback fills the matrix with the AD Jacobian bit for bit.
#include <railstab/integrate/integrator.hpp>
#include <railstab/integrate/sparse_newton.hpp>
#include <railstab/linear/jacobian.hpp>
#include <railstab/setup/prepare_scene.hpp>

#include <railstab/integrate/model_callbacks.hpp>
#include <railstab/integrate/root_functions.hpp>

#include <sundials/sundials_context.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include "support/test_files.hpp"

using namespace railstab;

namespace {

using railstab::test::case_path;

Trajectory run(const PreparedScene& s, IntegratorKind kind, NewtonMatrixKind newton, double t_end,
               double tolerance_scale = 1.0) {
  IntegrationOptions o = integration_options_for(s.spec.simulation);
  o.kind = kind;
  o.t_end_s = t_end;
  o.output_interval_s = 0.01;
  o.relative_tolerance *= tolerance_scale;
  o.absolute_tolerance *= tolerance_scale;
  o.newton_matrix = newton;
  // BDF capped at order 2 (A-stable): at orders 3-5 the nearly undamped
  // contact modes make the step sequence erratic (README, "Error against
  // run time"), and two runs then differ by more than the tolerance.
  if (kind == IntegratorKind::cvode_bdf) o.order = 2;
  return integrate(s.model, s.speed_m_per_s, perturbed_initial_state(s), o);
}

// Largest difference of two runs over the common output times, per state
// scaled by rtol |x| + atol (the integrator's error weights).
double worst_weighted_difference(const Trajectory& a, const Trajectory& b, double rtol, double atol) {
  double worst = 0.0;
  const size_t n = std::min(a.states.size(), b.states.size());
  for (size_t i = 0; i < n; ++i)
    for (Eigen::Index k = 0; k < a.states[i].size(); ++k)
      worst = std::max(worst, std::abs(a.states[i](k) - b.states[i](k)) /
                                  (rtol * std::abs(a.states[i](k)) + atol));
  return worst;
}

}  // namespace

TEST(SparseNewton, LayoutIsThePatternPlusTheDiagonal) {
  SparsityPattern p;
  p.rows = p.cols = 4;
  p.columns_of_row = {{1, 3}, {0, 1}, {}, {0, 2}};
  const SparseJacobianLayout l = sparse_jacobian_layout(p);
  // Columns: 0 {0 (diag), 1, 3}, 1 {0, 1}, 2 {2 (diag), 3}, 3 {0, 3 (diag)}.
  EXPECT_EQ(l.column_starts, (std::vector<sunindextype>{0, 3, 5, 7, 9}));
  EXPECT_EQ(l.row_indices, (std::vector<sunindextype>{0, 1, 3, 0, 1, 2, 3, 0, 3}));
  for (int r = 0; r < 4; ++r)
    for (size_t k = 0; k < p.columns_of_row[size_t(r)].size(); ++k) {
      const int c = p.columns_of_row[size_t(r)][k];
      const sunindextype pos = l.position_of[size_t(r)][k];
      EXPECT_EQ(l.row_indices[size_t(pos)], r);
      EXPECT_GE(pos, l.column_starts[size_t(c)]);
      EXPECT_LT(pos, l.column_starts[size_t(c) + 1]);
    }
  SparsityPattern rectangular;
  rectangular.rows = 2;
  rectangular.cols = 3;
  rectangular.columns_of_row = {{}, {}};
  EXPECT_THROW(sparse_jacobian_layout(rectangular), std::invalid_argument);
}

TEST(SparseNewton, AutomaticChoiceBySize) {
  EXPECT_FALSE(uses_sparse_newton(NewtonMatrixKind::automatic, kSparseNewtonFromStates - 1));
  EXPECT_TRUE(uses_sparse_newton(NewtonMatrixKind::automatic, kSparseNewtonFromStates));
  EXPECT_TRUE(uses_sparse_newton(NewtonMatrixKind::sparse, 10));
  EXPECT_FALSE(uses_sparse_newton(NewtonMatrixKind::dense, 100000));
}

// The Jacobian callback fills the sparse Newton matrix with exactly the
// coloured AD Jacobian (bit for bit), explicit zeros on the diagonal where
// the Jacobian has none.
TEST(SparseNewton, CallbackFillsTheAdJacobianBitForBit) {
  const PreparedScene s = prepare_scene(case_path("thesis_vehicle_tangent"), {});
  const RootFunctionSet roots(s.model, s.speed_m_per_s);
  ModelCallbackData data(s.model, s.speed_m_per_s, roots, 0.0);
  data.sparse_layout = sparse_jacobian_layout(data.jacobian_plan.pattern);
  const Eigen::VectorXd x = perturbed_initial_state(s);
  const Eigen::MatrixXd reference = rhs_jacobian_ad(s.model, data.jacobian_plan, s.speed_m_per_s, 0.3, x);
  SUNContext ctx = nullptr;
  ASSERT_EQ(SUNContext_Create(nullptr, &ctx), 0);
  const long n = s.model.state_size();
  N_Vector y = N_VNew_Serial(n, ctx);
  as_eigen(y) = x;
  SUNMatrix J = SUNSparseMatrix(n, n, data.sparse_layout.nonzeros(), CSC_MAT, ctx);
  EXPECT_EQ(full_jacobian_callback(0.3, y, nullptr, J, &data, nullptr, nullptr, nullptr), 0);
  Eigen::MatrixXd filled = Eigen::MatrixXd::Zero(n, n);
  const sunindextype* starts = SUNSparseMatrix_IndexPointers(J);
  const sunindextype* rows = SUNSparseMatrix_IndexValues(J);
  const double* values = SUNSparseMatrix_Data(J);
  int diagonal = 0;
  for (long c = 0; c < n; ++c)
    for (sunindextype k = starts[c]; k < starts[c + 1]; ++k) {
      filled(rows[k], c) = values[k];
      diagonal += rows[k] == c ? 1 : 0;
    }
  EXPECT_EQ(diagonal, n);
  int differing = 0;
  for (long i = 0; i < n; ++i)
    for (long j = 0; j < n; ++j) differing += filled(i, j) == reference(i, j) ? 0 : 1;
  EXPECT_EQ(differing, 0);
  SUNMatDestroy(J);
  N_VDestroy(y);
  SUNContext_Free(&ctx);
}

class SparseNewtonRun
    : public ::testing::TestWithParam<std::tuple<std::string, IntegratorKind, double, double>> {};

TEST_P(SparseNewtonRun, FollowsTheDenseRunWithinTheTolerance) {
  const auto& [scene, kind, t_end, tightening] = GetParam();
  const PreparedScene s = prepare_scene(case_path(scene), {});
  // The two Newton solvers (Eigen's dense LU, KLU) solve the same systems to
  // round-off, but step-size control turns round-off into different steps,
  // so two runs differ by up to the integrator's error, not by round-off.
  // At tolerances `tightening` times the scene's (SDIRK order 4: 1/100;
  // BDF order 2, whose global error is larger per unit of tolerance:
  // 1/1000), that error is below the scene's tolerance: the runs must agree
  // within one unit of the scene's error weights rtol |x| + atol.
  const Trajectory dense = run(s, kind, NewtonMatrixKind::dense, t_end, tightening);
  const Trajectory sparse = run(s, kind, NewtonMatrixKind::sparse, t_end, tightening);
  ASSERT_EQ(dense.states.size(), sparse.states.size());
  ASSERT_NEAR(sparse.times_s.back(), t_end, 1e-12);
  EXPECT_GT(sparse.stats.jacobian_evaluations, 0);
  const SimulationSpec& sim = s.spec.simulation;
  EXPECT_LE(worst_weighted_difference(dense, sparse, sim.relative_tolerance, sim.absolute_tolerance),
            1.0);
  // A wrong Newton matrix would still converge, slowly: as many Newton
  // failures as the dense run (+-20 %, +2).
  EXPECT_LE(sparse.stats.nonlinear_failures, 1.2 * dense.stats.nonlinear_failures + 2);
  // And the motion is not trivial: the 1 mm disturbance is there.
  const int k = s.model.bodies[0].state_index[1];
  EXPECT_GT(std::abs(sparse.states.front()(k)), 5e-4);
}

INSTANTIATE_TEST_SUITE_P(
    Cases, SparseNewtonRun,
    ::testing::Values(
        std::make_tuple("thesis_vehicle_tangent", IntegratorKind::arkode_dirk, 0.5, 0.01),
        std::make_tuple("thesis_vehicle_tangent", IntegratorKind::cvode_bdf, 0.5, 0.001),
        std::make_tuple("thesis_train_4", IntegratorKind::arkode_dirk, 0.2, 0.01)));
