// The dense Newton matrix's own copy and c A + I
// (integrate/dense_newton_matrix.hpp) must give SUNDIALS' results to the last
// bit: they replace SUNMatCopy_Dense and SUNMatScaleAddI_Dense inside CVODE
// and ARKStep, and every time-domain output depends on them.
#include <railstab/integrate/dense_newton_matrix.hpp>

#include <sundials/sundials_context.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

namespace railstab {
namespace {

struct Context {
  Context() { SUNContext_Create(nullptr, &ctx); }
  ~Context() { SUNContext_Free(&ctx); }
  SUNContext ctx = nullptr;
};

void fill(SUNMatrix A, std::mt19937& rng) {
  // Values over many magnitudes, so that a fused multiply-add or another
  // rounding order would show.
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-12, 12);
  double* a = SUNDenseMatrix_Data(A);
  for (sunindextype k = 0; k < SUNDenseMatrix_LData(A); ++k)
    a[k] = mantissa(rng) * std::ldexp(1.0, exponent(rng));
}

bool bitwise_equal(SUNMatrix A, SUNMatrix B) {
  return SUNDenseMatrix_LData(A) == SUNDenseMatrix_LData(B) &&
         std::memcmp(SUNDenseMatrix_Data(A), SUNDenseMatrix_Data(B),
                     sizeof(double) * size_t(SUNDenseMatrix_LData(A))) == 0;
}

TEST(DenseNewtonMatrix, ScaleAddIdentityAndCopyAreSundialsToTheLastBit) {
  Context c;
  std::mt19937 rng(7);
  for (const long n : {1L, 5L, 82L}) {
    SUNMatrix fast = make_dense_newton_matrix(n, c.ctx);
    SUNMatrix plain = SUNDenseMatrix(n, n, c.ctx);
    ASSERT_NE(fast, nullptr);
    ASSERT_EQ(SUNMatGetID(fast), SUNMATRIX_DENSE);
    for (const double gamma : {0.0, 1e-4, 3.7e-3, 0.25, 1.0 / 3.0}) {
      fill(fast, rng);
      ASSERT_EQ(SUNMatCopy_Dense(fast, plain), SUNMAT_SUCCESS);
      ASSERT_EQ(SUNMatScaleAddI(-gamma, fast), SUNMAT_SUCCESS);  // through the ops table
      ASSERT_EQ(SUNMatScaleAddI_Dense(-gamma, plain), SUNMAT_SUCCESS);
      EXPECT_TRUE(bitwise_equal(fast, plain)) << "n " << n << ", gamma " << gamma;
    }
    // Copy both ways through the ops table (CVODE: A -> saved J after a new
    // Jacobian, saved J -> A when it reuses it).
    SUNMatrix saved = SUNMatClone(fast);
    ASSERT_NE(saved, nullptr);
    fill(fast, rng);
    ASSERT_EQ(SUNMatCopy(fast, saved), SUNMAT_SUCCESS);
    EXPECT_TRUE(bitwise_equal(fast, saved));
    fill(fast, rng);
    ASSERT_EQ(SUNMatCopy(saved, fast), SUNMAT_SUCCESS);
    EXPECT_TRUE(bitwise_equal(fast, saved));
    SUNMatDestroy(saved);
    SUNMatDestroy(plain);
    SUNMatDestroy(fast);
  }
}

TEST(DenseNewtonMatrix, ClonesKeepTheFastOperationsAndShapesAreChecked) {
  Context c;
  SUNMatrix A = make_dense_newton_matrix(4, c.ctx);
  SUNMatrix B = SUNMatClone(A);
  ASSERT_NE(B, nullptr);
  EXPECT_EQ(B->ops->copy, A->ops->copy);
  EXPECT_EQ(B->ops->scaleaddi, A->ops->scaleaddi);
  EXPECT_EQ(B->ops->clone, A->ops->clone);
  EXPECT_NE(A->ops->copy, &SUNMatCopy_Dense);
  SUNMatrix other = make_dense_newton_matrix(3, c.ctx);
  EXPECT_EQ(SUNMatCopy(A, other), SUNMAT_ILL_INPUT);
  SUNMatDestroy(other);
  SUNMatDestroy(B);
  SUNMatDestroy(A);
}

}  // namespace
}  // namespace railstab
