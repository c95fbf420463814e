#include <railstab/integrate/sparse_newton.hpp>

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace railstab {

SparseJacobianLayout sparse_jacobian_layout(const SparsityPattern& pattern) {
  if (pattern.rows != pattern.cols)
    throw std::invalid_argument("sparse_jacobian_layout: the Jacobian's pattern must be square");
  const int n = pattern.rows;
  // Rows of each column: the pattern's, and the diagonal.
  std::vector<std::vector<int>> rows_of_column(static_cast<size_t>(n));
  for (int r = 0; r < n; ++r) {
    for (int c : pattern.columns_of_row[size_t(r)]) rows_of_column[size_t(c)].push_back(r);
    rows_of_column[size_t(r)].push_back(r);
  }
  SparseJacobianLayout layout;
  layout.n = n;
  layout.column_starts.assign(size_t(n) + 1, 0);
  for (int c = 0; c < n; ++c) {
    std::vector<int>& rows = rows_of_column[size_t(c)];
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    layout.column_starts[size_t(c) + 1] = layout.column_starts[size_t(c)] + sunindextype(rows.size());
    layout.row_indices.insert(layout.row_indices.end(), rows.begin(), rows.end());
  }
  layout.position_of.resize(size_t(n));
  for (int r = 0; r < n; ++r)
    for (int c : pattern.columns_of_row[size_t(r)]) {
      const auto first = layout.row_indices.begin() + layout.column_starts[size_t(c)];
      const auto last = layout.row_indices.begin() + layout.column_starts[size_t(c) + 1];
      layout.position_of[size_t(r)].push_back(
          sunindextype(std::lower_bound(first, last, sunindextype(r)) - layout.row_indices.begin()));
    }
  return layout;
}

}  // namespace railstab
