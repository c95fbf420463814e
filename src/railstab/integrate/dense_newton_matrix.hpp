#pragma once
// The dense SUNMatrix of the Newton matrix I - gamma J (CVODE, ARKStep),
// with faster copy and I + c A than SUNDIALS' own.
//
// Why: at every Newton matrix setup without a new Jacobian, CVODE and
// ARKStep copy the saved Jacobian into the matrix (SUNMatCopy) and form
// A := c A + I in place (SUNMatScaleAddI, c = -gamma) before the LU. SUNDIALS'
// dense versions index every element through its column pointer and test
// i == j in the inner loop; on the S1002 thesis vehicle in flange hunting
// (82 states, a setup every step for arkode_dirk) the two were 10 % of the
// run (perf, docs/performance.md), as much as the LU itself. Here: one
// memcpy, and one contiguous scaling pass followed by the diagonal.
//
// Same numbers to the last bit: the element operations are SUNDIALS' (a
// product a c rounded, then + 1 on the diagonal rounded; the scaling and
// the addition are separate passes, so no fused multiply-add can merge them).
// Clones (CVODE's and ARKStep's saved Jacobian) get the same operations.
#include <sundials/sundials_context.h>
#include <sundials/sundials_matrix.h>

namespace railstab {

// An n x n SUNDIALS dense matrix (SUNDenseMatrix layout, column-major);
// free with SUNMatDestroy. nullptr when SUNDIALS cannot allocate it.
SUNMatrix make_dense_newton_matrix(long n, SUNContext ctx);

}  // namespace railstab
