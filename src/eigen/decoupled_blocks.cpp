#include "eigen/decoupled_blocks.hpp"

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

}  // namespace

std::vector<std::vector<int>> decoupled_blocks(const Eigen::MatrixXd& B) {
  const int n = int(B.rows());
  std::vector<int> every_state(static_cast<size_t>(n));
  std::iota(every_state.begin(), every_state.end(), 0);
  const double norm = B.norm();
  if (n < 2 || !(norm > 0.0) || !std::isfinite(norm)) return {every_state};
  const double negligible = 0.5 * std::numeric_limits<double>::epsilon() * norm;
  std::vector<int> parent = every_state;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      if (i != j && std::abs(B(i, j)) > negligible) {
        const int a = root_of(parent, i), b = root_of(parent, j);
        if (a != b) parent[size_t(std::max(a, b))] = std::min(a, b);
      }
  // Blocks in the order of their smallest index (a root is its block's
  // smallest index: unions keep the smaller root).
  std::vector<int> block_of(size_t(n), -1);
  std::vector<std::vector<int>> blocks;
  for (int i = 0; i < n; ++i) {
    const int r = root_of(parent, i);
    if (block_of[size_t(r)] < 0) {
      block_of[size_t(r)] = int(blocks.size());
      blocks.emplace_back();
    }
    blocks[size_t(block_of[size_t(r)])].push_back(i);
  }
  if (blocks.size() == 1) return blocks;
  // What the split drops: every entry between two blocks.
  double dropped_squared = 0.0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      if (block_of[size_t(root_of(parent, i))] != block_of[size_t(root_of(parent, j))])
        dropped_squared += B(i, j) * B(i, j);
  if (!(std::sqrt(dropped_squared) <= negligible)) return {every_state};
  return blocks;
}

}  // namespace railstab
