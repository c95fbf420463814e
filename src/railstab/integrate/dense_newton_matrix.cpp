#include <railstab/integrate/dense_newton_matrix.hpp>

#include <sunmatrix/sunmatrix_dense.h>

#include <cstring>

namespace railstab {

namespace {

bool same_dense_shape(SUNMatrix A, SUNMatrix B) {
  return SUNMatGetID(A) == SUNMATRIX_DENSE && SUNMatGetID(B) == SUNMATRIX_DENSE &&
         SUNDenseMatrix_Rows(A) == SUNDenseMatrix_Rows(B) &&
         SUNDenseMatrix_Columns(A) == SUNDenseMatrix_Columns(B);
}

// B := A (SUNMatCopy's operation: the first argument is the source).
int dense_copy(SUNMatrix A, SUNMatrix B) {
  if (!same_dense_shape(A, B)) return SUNMAT_ILL_INPUT;
  std::memcpy(SUNDenseMatrix_Data(B), SUNDenseMatrix_Data(A),
              sizeof(realtype) * size_t(SUNDenseMatrix_LData(A)));
  return SUNMAT_SUCCESS;
}

// A := c A + I: every element times c, then 1 added to the diagonal, as
// SUNMatScaleAddI_Dense (element by element the same two roundings).
int dense_scale_add_identity(realtype c, SUNMatrix A) {
  if (SUNMatGetID(A) != SUNMATRIX_DENSE) return SUNMAT_ILL_INPUT;
  realtype* a = SUNDenseMatrix_Data(A);
  const sunindextype rows = SUNDenseMatrix_Rows(A);
  const sunindextype columns = SUNDenseMatrix_Columns(A);
  const sunindextype size = SUNDenseMatrix_LData(A);
  for (sunindextype k = 0; k < size; ++k) a[k] *= c;
  for (sunindextype j = 0; j < columns && j < rows; ++j) a[j * rows + j] += 1.0;
  return SUNMAT_SUCCESS;
}

void install_fast_dense_operations(SUNMatrix A);

SUNMatrix dense_clone(SUNMatrix A) {
  SUNMatrix B = SUNMatClone_Dense(A);
  if (B) install_fast_dense_operations(B);
  return B;
}

void install_fast_dense_operations(SUNMatrix A) {
  A->ops->copy = dense_copy;
  A->ops->scaleaddi = dense_scale_add_identity;
  A->ops->clone = dense_clone;
}

}  // namespace

SUNMatrix make_dense_newton_matrix(long n, SUNContext ctx) {
  SUNMatrix A = SUNDenseMatrix(n, n, ctx);
  if (A) install_fast_dense_operations(A);
  return A;
}

}  // namespace railstab
