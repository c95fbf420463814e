// Diagonal balancing before the dense QR (eigen/balance.hpp):
//  - the similarity is exact: D holds powers of two, B = D^-1 A D entry by
//    entry, and the diagonal is untouched;
//  - it balances: each row's and column's off-diagonal 1-norms end within
//    a factor 7/3 (a step of 2 is taken where r/c >= 2 and it cuts c + r
//    by 5 %: (2c + r/2) <= 0.95 (c + r) from r/c = 7/3 on);
//  - it pays where it should: on a badly scaled matrix with known
//    eigenvalues (A = S T S^-1, S spanning 1e-4..1e4,
//    T = V diag V^-1 well conditioned) eigen_dense recovers the smallest
//    eigenvalue to 1e-9 of its size (eps ||T|| / |lambda| is 2e-10), where
//    the unbalanced QR misses it by more than 1e-7;
//  - on the thesis vehicle's state matrix every eigenpair's residual
//    against A stays at round-off.
#include <railstab/eigen/balance.hpp>
#include <railstab/eigen/eigen_analysis.hpp>
#include <railstab/linear/linearization.hpp>
#include <railstab/setup/prepare_scene.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <string>
#include <vector>

using namespace railstab;

namespace {

Eigen::MatrixXd badly_scaled(Eigen::VectorXd& eigenvalues) {
  // T = V diag(eigenvalues) V^-1 with V = I + an O(0.3) full matrix (well
  // conditioned, so T's eigenvalues are), then a diagonal similarity S that
  // makes A's entries span sixteen orders of magnitude.
  const int n = 12;
  eigenvalues.resize(n);
  Eigen::MatrixXd V = Eigen::MatrixXd::Identity(n, n);
  for (int i = 0; i < n; ++i) {
    eigenvalues(i) = -std::pow(10.0, -3.0 + 6.0 * i / (n - 1));  // -1e-3 .. -1e3
    for (int j = 0; j < n; ++j) V(i, j) += 0.3 * std::sin(1.0 + i + 3.0 * j);
  }
  const Eigen::MatrixXd T = V * eigenvalues.asDiagonal() * V.inverse();
  Eigen::VectorXd s(n);
  for (int i = 0; i < n; ++i) s(i) = std::pow(10.0, 4.0 - 8.0 * ((i * 5) % n) / (n - 1));
  return s.asDiagonal() * T * s.cwiseInverse().asDiagonal();
}

double worst_relative_error(const Eigen::VectorXcd& computed, const Eigen::VectorXd& exact) {
  double worst = 0.0;
  for (Eigen::Index i = 0; i < exact.size(); ++i) {
    double nearest = INFINITY;
    for (Eigen::Index j = 0; j < computed.size(); ++j)
      nearest = std::min(nearest, std::abs(computed(j) - exact(i)));
    worst = std::max(worst, nearest / std::abs(exact(i)));
  }
  return worst;
}

}  // namespace

TEST(Balance, IsAnExactPowerOfTwoSimilarity) {
  Eigen::VectorXd exact;
  const Eigen::MatrixXd A = badly_scaled(exact);
  const BalancedMatrix b = balance(A);
  for (Eigen::Index i = 0; i < A.rows(); ++i) {
    int exponent = 0;
    EXPECT_EQ(std::frexp(b.scaling(i), &exponent), 0.5) << i;  // a power of two
    EXPECT_EQ(b.matrix(i, i), A(i, i));
    for (Eigen::Index j = 0; j < A.cols(); ++j)
      EXPECT_EQ(b.matrix(i, j), A(i, j) * b.scaling(j) / b.scaling(i)) << i << ", " << j;
  }
  EXPECT_GT(b.scaling.maxCoeff() / b.scaling.minCoeff(), 1e3);  // it did scale
}

TEST(Balance, RowAndColumnNormsEndWithinSevenThirds) {
  Eigen::VectorXd exact;
  const BalancedMatrix b = balance(badly_scaled(exact));
  for (Eigen::Index i = 0; i < b.matrix.rows(); ++i) {
    const double c = b.matrix.col(i).lpNorm<1>() - std::abs(b.matrix(i, i));
    const double r = b.matrix.row(i).lpNorm<1>() - std::abs(b.matrix(i, i));
    EXPECT_LE(std::max(c / r, r / c), 7.0 / 3.0 * (1.0 + 1e-12)) << i;
  }
}

TEST(Balance, RecoversSmallEigenvaluesOfABadlyScaledMatrix) {
  Eigen::VectorXd exact;
  const Eigen::MatrixXd A = badly_scaled(exact);
  std::vector<EigenPair> pairs = eigen_dense(A);
  Eigen::VectorXcd balanced(Eigen::Index(pairs.size()));
  for (size_t k = 0; k < pairs.size(); ++k) balanced(Eigen::Index(k)) = pairs[k].value;
  const Eigen::VectorXcd unbalanced = Eigen::EigenSolver<Eigen::MatrixXd>(A, false).eigenvalues();
  const double error_balanced = worst_relative_error(balanced, exact);
  const double error_unbalanced = worst_relative_error(unbalanced, exact);
  // What no method beats: eps ||T|| / |lambda_min| = 2.2e-16 1e3 / 1e-3 =
  // 2.2e-10, times T's modest eigenvalue condition (measured 7e-11).
  EXPECT_LT(error_balanced, 1e-9);
  EXPECT_GT(error_unbalanced, 1e-7);  // the case is one where balancing matters (measured 8e-6)
}

TEST(Balance, ThesisVehicleResidualsStayAtRoundOff) {
  const PreparedScene s = prepare_scene(std::string(RAILSTAB_CASES_DIR) + "/thesis_vehicle_tangent.toml", {});
  const LinearModel lin = linearize(s.model, s.speed_m_per_s, s.equilibrium.state);
  const BalancedMatrix b = balance(lin.A);
  EXPECT_LT(b.matrix.norm(), 1e-2 * lin.A.norm());  // the norm the QR works against
  for (const EigenPair& p : eigen_dense(lin.A)) EXPECT_LT(p.residual, 1e-13) << p.value;
}
