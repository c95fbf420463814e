#include <railstab/eigen/decoupled_blocks.hpp>

#include <cmath>
#include <limits>
#include <numeric>

namespace railstab {

namespace {

// Union-find over the states: i and j join when b_ij or b_ji couples them.
int root_of(std::vector<int>& parent, int i) {
  while (parent[size_t(i)] != i) {
    parent[size_t(i)] = parent[size_t(parent[size_t(i)])];  // path halving
    i = parent[size_t(i)];
  }
  return i;
}

// The blocks of an n x n matrix of Frobenius norm `norm` whose entries
// for_each_entry(f) visits as f(i, j, b_ij).
template <class ForEachEntry>
std::vector<std::vector<int>> blocks_of(int n, double norm, ForEachEntry&& for_each_entry) {
  std::vector<int> every_state(static_cast<size_t>(n));
  std::iota(every_state.begin(), every_state.end(), 0);
  if (n < 2 || !(norm > 0.0) || !std::isfinite(norm)) return {every_state};
  const double negligible = 0.5 * std::numeric_limits<double>::epsilon() * norm;
  std::vector<int> parent = every_state;
  for_each_entry([&](int i, int j, double b) {
    if (i == j || !(std::abs(b) > negligible)) return;
    const int ri = root_of(parent, i), rj = root_of(parent, j);
    if (ri != rj) parent[size_t(std::max(ri, rj))] = std::min(ri, rj);
  });
  // Blocks in the order of their smallest index (a root is its block's
  // smallest index: unions keep the smaller root).
  std::vector<int> block_of(static_cast<size_t>(n), -1), block_of_state(static_cast<size_t>(n));
  std::vector<std::vector<int>> blocks;
  for (int i = 0; i < n; ++i) {
    const int r = root_of(parent, i);
    if (block_of[size_t(r)] < 0) {
      block_of[size_t(r)] = int(blocks.size());
      blocks.emplace_back();
    }
    block_of_state[size_t(i)] = block_of[size_t(r)];
    blocks[size_t(block_of[size_t(r)])].push_back(i);
  }
  if (blocks.size() == 1) return blocks;
  // What the split drops: every entry between two blocks.
  double dropped_squared = 0.0;
  for_each_entry([&](int i, int j, double b) {
    if (block_of_state[size_t(i)] != block_of_state[size_t(j)]) dropped_squared += b * b;
  });
  if (!(std::sqrt(dropped_squared) <= std::sqrt(double(n)) * negligible)) return {every_state};
  return blocks;
}

}  // namespace

std::vector<std::vector<int>> decoupled_blocks(const Eigen::MatrixXd& B) {
  return blocks_of(int(B.rows()), B.norm(), [&](auto&& f) {
    for (Eigen::Index j = 0; j < B.cols(); ++j)
      for (Eigen::Index i = 0; i < B.rows(); ++i) f(int(i), int(j), B(i, j));
  });
}

std::vector<std::vector<int>> decoupled_blocks(const Eigen::SparseMatrix<double>& B) {
  return blocks_of(int(B.rows()), B.norm(), [&](auto&& f) {
    for (Eigen::Index j = 0; j < B.outerSize(); ++j)
      for (Eigen::SparseMatrix<double>::InnerIterator it(B, j); it; ++it)
        f(int(it.row()), int(it.col()), it.value());
  });
}

}  // namespace railstab
