// Splitting a state matrix into the diagonal blocks it decouples into
// (eigen/decoupled_blocks.hpp) and eigen_dense on the blocks:
//  - two random blocks, shuffled by a symmetric permutation, with cross
//    entries of 1e-3 u ||B|| (u = unit round-off): the two index sets come
//    back; one cross entry of 10 u ||B||: one block; all 70 cross entries at
//    0.4 u ||B|| (3.3 u ||B|| together, under sqrt(12) u ||B|| = 3.46 u ||B||):
//    two blocks, at 0.5 u ||B|| each (each negligible alone, 4.2 u ||B||
//    together): one block;
//  - eigen_dense of a shuffled block-diagonal matrix of two damped
//    mechanical systems equals the union of the systems' own eigenpairs
//    (values to 1e-12 relative, vectors zero outside their block);
//  - the thesis vehicle's state matrix splits into its lateral (36 states)
//    and vertical/longitudinal (42) parts, and eigen_dense's eigenvalues
//    equal one QR on the whole balanced matrix to 1e-10 relative to
//    max(1, |lambda|) (the whole QR's backward error n u ||B||_F is ~8e-11
//    1/s; measured 1.4e-13), with residuals against the whole A below 1e-13
//    and every eigenvector on one block.
#include <railstab/eigen/balance.hpp>
#include <railstab/eigen/decoupled_blocks.hpp>
#include <railstab/eigen/eigen_analysis.hpp>
#include "eigen/synthetic_systems.hpp"
#include <railstab/linear/linearization.hpp>
#include <railstab/setup/prepare_scene.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <numeric>
#include <random>
#include <string>

using namespace railstab;

namespace {

using Complex = std::complex<double>;
const double kUnitRoundoff = 0.5 * std::numeric_limits<double>::epsilon();

// B = P diag(first, second) P^T for a random permutation P: the states of
// `first` land on positions[0 .. n1-1], those of `second` on the rest.
struct Shuffled {
  Eigen::MatrixXd matrix;
  std::vector<int> positions;  // positions[k]: where block state k went
  std::vector<int> first, second;  // ascending
};

Shuffled shuffled_blocks(const Eigen::MatrixXd& first, const Eigen::MatrixXd& second, unsigned seed) {
  const int n1 = int(first.rows()), n = n1 + int(second.rows());
  Shuffled s;
  s.positions.resize(size_t(n));
  std::iota(s.positions.begin(), s.positions.end(), 0);
  std::mt19937 rng(seed);
  std::shuffle(s.positions.begin(), s.positions.end(), rng);
  Eigen::MatrixXd D = Eigen::MatrixXd::Zero(n, n);
  D.topLeftCorner(n1, n1) = first;
  D.bottomRightCorner(n - n1, n - n1) = second;
  s.matrix.setZero(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) s.matrix(s.positions[size_t(i)], s.positions[size_t(j)]) = D(i, j);
  for (int k = 0; k < n; ++k) (k < n1 ? s.first : s.second).push_back(s.positions[size_t(k)]);
  std::sort(s.first.begin(), s.first.end());
  std::sort(s.second.begin(), s.second.end());
  return s;
}

std::vector<std::vector<int>> expected_blocks(const Shuffled& s) {
  return s.first.front() < s.second.front() ? std::vector<std::vector<int>>{s.first, s.second}
                                            : std::vector<std::vector<int>>{s.second, s.first};
}

}  // namespace

TEST(DecoupledBlocks, FindsShuffledBlocksAndRefusesRealCoupling) {
  std::mt19937 rng(5);
  std::normal_distribution<double> g;
  Eigen::MatrixXd a(5, 5), b(7, 7);
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j) a(i, j) = g(rng);
  for (int i = 0; i < 7; ++i)
    for (int j = 0; j < 7; ++j) b(i, j) = 100.0 * g(rng);
  const Shuffled s = shuffled_blocks(a, b, 11);
  const double norm = s.matrix.norm();
  const int p = s.first[1], q = s.second[2];
  {
    Eigen::MatrixXd B = s.matrix;  // round-off-sized coupling
    B(p, q) = 1e-3 * kUnitRoundoff * norm;
    B(q, p) = -1e-3 * kUnitRoundoff * norm;
    EXPECT_EQ(decoupled_blocks(B), expected_blocks(s));
  }
  {
    Eigen::MatrixXd B = s.matrix;  // one real coupling entry
    B(p, q) = 10.0 * kUnitRoundoff * norm;
    EXPECT_EQ(decoupled_blocks(B).size(), 1u);
  }
  {
    Eigen::MatrixXd B = s.matrix;  // each negligible, together not
    int placed = 0;
    for (int i : s.first)
      for (int j : s.second)
        for (int t = 0; t < 2; ++t, ++placed)
          (t == 0 ? B(i, j) : B(j, i)) = 0.4 * kUnitRoundoff * norm;
    ASSERT_EQ(placed, 70);  // 5 x 7 x 2 entries available
    // 70 entries of 0.4 u ||B||: sqrt(70) x 0.4 = 3.3 u ||B|| <= sqrt(12) u ||B||: accepted.
    EXPECT_EQ(decoupled_blocks(B), expected_blocks(s));
    for (int i : s.first)
      for (int j : s.second) B(i, j) = B(j, i) = 0.5 * kUnitRoundoff * norm;
    // 70 of 0.5 u ||B||: 4.2 u ||B|| together: refused.
    EXPECT_EQ(decoupled_blocks(B).size(), 1u);
  }
  const Eigen::MatrixXd one = Eigen::MatrixXd::Constant(1, 1, 3.0);
  EXPECT_EQ(decoupled_blocks(one), std::vector<std::vector<int>>{{0}});
  EXPECT_EQ(decoupled_blocks(Eigen::MatrixXd::Zero(3, 3)).size(), 1u);
}

TEST(DecoupledBlocks, EigenDenseOnBlocksIsTheUnionOfTheBlocksEigenpairs) {
  const Eigen::MatrixXd a = test::damped_mechanical_system(12, 3);
  const Eigen::MatrixXd b = 50.0 * test::damped_mechanical_system(16, 4);
  const Shuffled s = shuffled_blocks(a, b, 7);
  ASSERT_EQ(decoupled_blocks(balance(s.matrix).matrix).size(), 2u);
  const std::vector<EigenPair> got = eigen_dense(s.matrix);
  std::vector<EigenPair> want = eigen_dense(a);
  for (const EigenPair& p : eigen_dense(b)) want.push_back(p);
  ASSERT_EQ(got.size(), want.size());
  for (const EigenPair& w : want) {
    // The nearest computed eigenvalue, and its vector: zero outside w's
    // block, equal to w's vector up to a unit phase on it.
    size_t best = 0;
    for (size_t i = 1; i < got.size(); ++i)
      if (std::abs(got[i].value - w.value) < std::abs(got[best].value - w.value)) best = i;
    EXPECT_LT(std::abs(got[best].value - w.value), 1e-12 * std::max(1.0, std::abs(w.value)))
        << w.value;
    const bool in_first = w.vector.size() == a.rows();
    const int offset = in_first ? 0 : int(a.rows());
    Eigen::VectorXcd v(w.vector.size());
    for (Eigen::Index k = 0; k < w.vector.size(); ++k)
      v(k) = got[best].vector(s.positions[size_t(offset + k)]);
    EXPECT_NEAR(v.norm(), 1.0, 1e-12);  // all of the unit vector is on the block
    EXPECT_NEAR(std::abs(v.dot(w.vector)), 1.0, 1e-10) << w.value;
    EXPECT_LT(got[best].residual, 1e-13);
  }
}

TEST(DecoupledBlocks, ThesisVehicleSplitsLateralFromVerticalWithTheWholeQRsEigenvalues) {
  const PreparedScene scene =
      prepare_scene(std::string(RAILSTAB_CASES_DIR) + "/thesis_vehicle_tangent.toml", {});
  const LinearModel lin = linearize(scene.model, scene.speed_m_per_s, scene.equilibrium.state);
  const BalancedMatrix balanced = balance(lin.A);
  const std::vector<std::vector<int>> blocks = decoupled_blocks(balanced.matrix);
  ASSERT_EQ(blocks.size(), 2u);
  std::vector<size_t> sizes{blocks[0].size(), blocks[1].size()};
  std::sort(sizes.begin(), sizes.end());
  EXPECT_EQ(sizes, (std::vector<size_t>{36, 42}));
  // Which states: a lateral (y) velocity and a vertical (z) velocity of the
  // car body are in different blocks.
  auto block_of = [&](const std::string& name) {
    for (size_t b = 0; b < blocks.size(); ++b)
      for (int i : blocks[b])
        if (lin.state_names[size_t(i)] == name) return int(b);
    return -1;
  };
  const int lateral = block_of("carbody.y_m/s"), vertical = block_of("carbody.z_m/s");
  ASSERT_GE(lateral, 0);
  ASSERT_GE(vertical, 0);
  EXPECT_NE(lateral, vertical);

  const std::vector<EigenPair> split = eigen_dense(lin.A);
  Eigen::EigenSolver<Eigen::MatrixXd> whole(balanced.matrix, false);
  ASSERT_EQ(split.size(), size_t(lin.A.rows()));
  // Both ways (each whole-QR eigenvalue near a split one and back), so two
  // cannot map onto one.
  double worst = 0.0;
  for (Eigen::Index i = 0; i < whole.eigenvalues().size(); ++i) {
    const Complex w = whole.eigenvalues()(i);
    double nearest = 1e300;
    for (const EigenPair& p : split) nearest = std::min(nearest, std::abs(p.value - w));
    worst = std::max(worst, nearest / std::max(1.0, std::abs(w)));
  }
  for (const EigenPair& p : split) {
    double nearest = 1e300;
    for (Eigen::Index i = 0; i < whole.eigenvalues().size(); ++i)
      nearest = std::min(nearest, std::abs(whole.eigenvalues()(i) - p.value));
    worst = std::max(worst, nearest / std::max(1.0, std::abs(p.value)));
  }
  EXPECT_LT(worst, 1e-10);
  for (const EigenPair& p : split) {
    EXPECT_LT(p.residual, 1e-13) << p.value;
    // Each vector lives on one block.
    int blocks_touched = 0;
    for (const std::vector<int>& b : blocks) {
      double on = 0.0;
      for (int i : b) on += std::norm(p.vector(i));
      blocks_touched += on > 0.0 ? 1 : 0;
    }
    EXPECT_EQ(blocks_touched, 1) << p.value;
  }
}
