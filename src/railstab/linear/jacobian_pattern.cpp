#include <railstab/linear/jacobian_pattern.hpp>

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>

namespace railstab {

bool SparsityPattern::contains(int r, int c) const {
  const std::vector<int>& cols_r = columns_of_row[std::size_t(r)];
  return std::binary_search(cols_r.begin(), cols_r.end(), c);
}

long SparsityPattern::nonzeros() const {
  long n = 0;
  for (const auto& c : columns_of_row) n += long(c.size());
  return n;
}

int SparsityPattern::max_row_nonzeros() const {
  std::size_t m = 0;
  for (const auto& c : columns_of_row) m = std::max(m, c.size());
  return int(m);
}

namespace {

void sort_unique(std::vector<int>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

void append(std::vector<int>& to, const std::vector<int>& from) {
  to.insert(to.end(), from.begin(), from.end());
}

}  // namespace

SparsityPattern rhs_jacobian_pattern(const Model& model) {
  const int n = model.n_coordinates;
  const int z0 = model.internal_state_offset();
  const std::size_t n_bodies = model.bodies.size();

  // The columns each body's motion reads: its free q (but a wheelset's spin
  // angle, which nothing depends on) and all its free u.
  std::vector<std::vector<int>> body_columns(n_bodies);
  for (int k = 0; k < n; ++k) {
    const auto [b, c] = model.coordinate_of_state[std::size_t(k)];
    const bool spin_angle =
        model.bodies[std::size_t(b)].wheelset() && c == int(CoordinateIndex::pitch);
    if (!spin_angle) body_columns[std::size_t(b)].push_back(k);
    body_columns[std::size_t(b)].push_back(n + k);
  }

  // The columns each element reads: its bodies' and its internal states.
  std::vector<std::vector<int>> element_columns(model.elements.size());
  std::vector<std::vector<int>> body_rows(n_bodies);  // what a body's accelerations read
  for (std::size_t b = 0; b < n_bodies; ++b) body_rows[b] = body_columns[b];
  for (std::size_t e = 0; e < model.elements.size(); ++e) {
    const ElementEnds& ends = ends_of(model.elements[e]);
    std::vector<int>& cols = element_columns[e];
    if (ends.body1 != kTrackBody) append(cols, body_columns[std::size_t(ends.body1)]);
    append(cols, body_columns[std::size_t(ends.body2)]);
    const int first = model.element_first_state[e];
    if (first >= 0)
      for (int k = 0; k < internal_states_of(model.elements[e]); ++k) cols.push_back(z0 + first + k);
    sort_unique(cols);
    // The element's force acts on both its bodies (a track end takes none).
    if (ends.body1 != kTrackBody) append(body_rows[std::size_t(ends.body1)], cols);
    append(body_rows[std::size_t(ends.body2)], cols);
  }
  for (auto& r : body_rows) sort_unique(r);

  SparsityPattern p;
  p.rows = p.cols = model.state_size();
  p.columns_of_row.resize(std::size_t(p.rows));
  for (int k = 0; k < n; ++k) {
    p.columns_of_row[std::size_t(k)] = {n + k};  // dq/dt = u
    p.columns_of_row[std::size_t(n + k)] =
        body_rows[std::size_t(model.coordinate_of_state[std::size_t(k)].first)];
  }
  for (int i = 0; i < model.n_internal_states; ++i) {
    const int e = model.element_of_internal_state[std::size_t(i)].first;
    p.columns_of_row[std::size_t(z0 + i)] = element_columns[std::size_t(e)];
  }
  return p;
}

SparsityPattern sub_pattern(const SparsityPattern& full, const std::vector<int>& rows,
                            const std::vector<int>& columns) {
  // Local index of each full column (-1: not selected).
  std::vector<int> local(std::size_t(full.cols), -1);
  for (std::size_t j = 0; j < columns.size(); ++j) {
    const int c = columns[j];
    if (c < 0 || c >= full.cols || local[std::size_t(c)] >= 0)
      throw std::invalid_argument("sub_pattern: column " + std::to_string(c) +
                                  " outside 0.." + std::to_string(full.cols - 1) +
                                  " or repeated");
    local[std::size_t(c)] = int(j);
  }
  SparsityPattern p;
  p.rows = int(rows.size());
  p.cols = int(columns.size());
  p.columns_of_row.resize(rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const int r = rows[i];
    if (r < 0 || r >= full.rows)
      throw std::invalid_argument("sub_pattern: row " + std::to_string(r) + " outside 0.." +
                                  std::to_string(full.rows - 1));
    for (int c : full.columns_of_row[std::size_t(r)])
      if (local[std::size_t(c)] >= 0) p.columns_of_row[i].push_back(local[std::size_t(c)]);
    std::sort(p.columns_of_row[i].begin(), p.columns_of_row[i].end());
  }
  return p;
}

namespace {

// Rows of each column (the transpose of the pattern).
std::vector<std::vector<int>> rows_of_columns(const SparsityPattern& p) {
  std::vector<std::vector<int>> rows(std::size_t(p.cols));
  for (int r = 0; r < p.rows; ++r)
    for (int c : p.columns_of_row[std::size_t(r)]) rows[std::size_t(c)].push_back(r);
  return rows;
}

ColumnColouring greedy_colouring(const SparsityPattern& p,
                                 const std::vector<std::vector<int>>& rows_of_column,
                                 const std::vector<int>& order) {
  ColumnColouring result;
  result.colour_of_column.assign(std::size_t(p.cols), -1);
  // forbidden[c] == column j marks colour c as taken by a neighbour of j.
  std::vector<int> forbidden(std::size_t(p.cols) + 1, -1);
  for (int j : order) {
    for (int r : rows_of_column[std::size_t(j)])
      for (int other : p.columns_of_row[std::size_t(r)]) {
        const int c = result.colour_of_column[std::size_t(other)];
        if (c >= 0) forbidden[std::size_t(c)] = j;
      }
    int colour = 0;
    while (forbidden[std::size_t(colour)] == j) ++colour;
    result.colour_of_column[std::size_t(j)] = colour;
    result.colours = std::max(result.colours, colour + 1);
  }
  return result;
}

// The rows that constrain a colouring: those with two or more columns, each
// distinct column set once (all acceleration rows of a body read the same
// columns; a kinematic row reads one). Same colourings, far less work.
SparsityPattern constraining_rows(const SparsityPattern& p) {
  SparsityPattern c;
  c.rows = 0;
  c.cols = p.cols;
  for (const std::vector<int>& row : p.columns_of_row)
    if (row.size() >= 2) c.columns_of_row.push_back(row);
  std::sort(c.columns_of_row.begin(), c.columns_of_row.end());
  c.columns_of_row.erase(std::unique(c.columns_of_row.begin(), c.columns_of_row.end()),
                         c.columns_of_row.end());
  c.rows = int(c.columns_of_row.size());
  return c;
}

}  // namespace

ColumnColouring colour_columns(const SparsityPattern& pattern) {
  const SparsityPattern p = constraining_rows(pattern);
  const std::vector<std::vector<int>> rows_of_column = rows_of_columns(p);
  std::vector<int> natural(std::size_t(p.cols));
  std::iota(natural.begin(), natural.end(), 0);
  ColumnColouring best = greedy_colouring(p, rows_of_column, natural);

  // Largest first: columns with the most neighbours (the sum of their rows'
  // lengths, an upper bound that orders the same way on block patterns).
  std::vector<long> degree(std::size_t(p.cols), 0);
  for (int j = 0; j < p.cols; ++j)
    for (int r : rows_of_column[std::size_t(j)])
      degree[std::size_t(j)] += long(p.columns_of_row[std::size_t(r)].size());
  std::vector<int> largest_first = natural;
  std::stable_sort(largest_first.begin(), largest_first.end(),
                   [&](int a, int b) { return degree[std::size_t(a)] > degree[std::size_t(b)]; });
  ColumnColouring lf = greedy_colouring(p, rows_of_column, largest_first);
  if (lf.colours < best.colours) best = std::move(lf);
  return best;
}

bool is_valid_colouring(const SparsityPattern& p, const ColumnColouring& colouring) {
  if (int(colouring.colour_of_column.size()) != p.cols) return false;
  for (int c : colouring.colour_of_column)
    if (c < 0 || c >= colouring.colours) return false;
  std::vector<int> seen(std::size_t(colouring.colours), -1);
  for (int r = 0; r < p.rows; ++r)
    for (int c : p.columns_of_row[std::size_t(r)]) {
      int& s = seen[std::size_t(colouring.colour_of_column[std::size_t(c)])];
      if (s == r) return false;
      s = r;
    }
  return true;
}

}  // namespace railstab
