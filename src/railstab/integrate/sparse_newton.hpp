#pragma once
// The time domain's Newton matrix stored sparse, for large models (trains):
// SUNDIALS assembles I - gamma J in a compressed-sparse-column SUNMatrix and
// SUNLinSol_KLU (SuiteSparse KLU) factorises it. KLU rather than Eigen's
// SparseLU here because SUNDIALS ships the wrapper (SUNLinSol_KLU) with the
// symbolic analysis done once and numeric refactorisation on every setup,
// which is what a Newton matrix with a fixed pattern and changing values
// needs.
//
// KLU reuses its symbolic analysis, so the matrix's pattern must never
// change: it is the coloured AD Jacobian's structural pattern
// (linear/jacobian_pattern.hpp) plus the diagonal (for the I of I - gamma J),
// with explicit zeros where an entry happens to vanish.
#include <railstab/linear/jacobian_pattern.hpp>

#include <sundials/sundials_types.h>

#include <vector>

namespace railstab {

struct SparseJacobianLayout {
  int n = 0;
  std::vector<sunindextype> column_starts;  // n + 1 (CSC)
  std::vector<sunindextype> row_indices;    // nonzeros
  // position_of[r][k]: index into the CSC arrays of entry
  // (r, pattern.columns_of_row[r][k]).
  std::vector<std::vector<sunindextype>> position_of;
  sunindextype nonzeros() const { return sunindextype(row_indices.size()); }
};

// The layout of (pattern plus diagonal); pattern must be square.
SparseJacobianLayout sparse_jacobian_layout(const SparsityPattern& pattern);

}  // namespace railstab
