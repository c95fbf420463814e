// eigen_dense's shortcuts against the plain computation, bit for bit
// (values and vectors; the residuals to round-off, being formed by one
// matrix product for all columns):
//  - the second column of a complex pair taken as the conjugate of the
//    first's eigenpair (value, phased vector, residual) instead of being
//    computed from its own column;
//  - the canonical phase's peak found from squared moduli with only the
//    near-largest ones compared by modulus.
// The reference is the column-by-column computation eigen_dense did before
// (EigenSolver's eigenvectors, each column phased and its residual formed
// from A), on the coach's state matrix (82 states; unlike the thesis
// vehicle's it does not decouple into blocks, so eigen_dense runs one QR on
// all of it, as the reference does) and on a synthetic damped system.
#include <railstab/eigen/eigen_analysis.hpp>
#include "eigen/synthetic_systems.hpp"
#include <railstab/linear/linearization.hpp>
#include <railstab/setup/prepare_scene.hpp>

#include "support/column_by_column_eigen.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <complex>
#include <string>
#include <vector>

using namespace railstab;

namespace {

using Complex = std::complex<double>;

void expect_bit_identical(const std::vector<EigenPair>& got, const std::vector<EigenPair>& want) {
  ASSERT_EQ(got.size(), want.size());
  int complex_pairs = 0;
  for (size_t i = 0; i < got.size(); ++i) {
    EXPECT_EQ(got[i].value, want[i].value) << i;
    EXPECT_TRUE(got[i].vector == want[i].vector) << "vector " << i << " (" << want[i].value << ")";
    // The residual is formed from A V for all columns at once (a matrix
    // product, another summation order than the reference's per-column
    // product): both are round-off, ~n eps at most.
    EXPECT_NEAR(got[i].residual, want[i].residual, 1e-14) << i;
    EXPECT_LT(got[i].residual, 1e-13) << i;
    if (want[i].value.imag() > 0.0) ++complex_pairs;
  }
  EXPECT_GT(complex_pairs, 0);  // the conjugate shortcut was exercised
}

}  // namespace

TEST(EigenDensePairs, CoachMatchesColumnByColumn) {
  const PreparedScene scene =
      prepare_scene(std::string(RAILSTAB_CASES_DIR) + "/coach_tangent.toml", {});
  const LinearModel lin = linearize(scene.model, scene.speed_m_per_s, scene.equilibrium.state);
  ASSERT_EQ(lin.A.rows(), 82);
  expect_bit_identical(eigen_dense(lin.A), test::column_by_column_eigen(lin.A));
}

TEST(EigenDensePairs, SyntheticSystemMatchesColumnByColumn) {
  const Eigen::MatrixXd A = test::damped_mechanical_system(20, 3);
  expect_bit_identical(eigen_dense(A), test::column_by_column_eigen(A));
}
