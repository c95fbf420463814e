#include <railstab/integrate/eigen_dense_solver.hpp>

#include <nvector/nvector_serial.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <railstab/linalg/dense_decompositions.hpp>

#include <new>

namespace railstab {

namespace {

struct EigenDenseContent {
  explicit EigenDenseContent(long n) : lu(Eigen::Index(n)) {}
  Eigen::PartialPivLU<Eigen::MatrixXd> lu;
  Eigen::MatrixXd block, block_solution;  // a right-hand side of n k entries, n x k
  sunindextype last_flag = 0;
};

EigenDenseContent& content(SUNLinearSolver S) { return *static_cast<EigenDenseContent*>(S->content); }

SUNLinearSolver_Type get_type(SUNLinearSolver) { return SUNLINEARSOLVER_DIRECT; }
SUNLinearSolver_ID get_id(SUNLinearSolver) { return SUNLINEARSOLVER_CUSTOM; }
int initialize(SUNLinearSolver S) {
  content(S).last_flag = SUNLS_SUCCESS;
  return SUNLS_SUCCESS;
}

int setup(SUNLinearSolver S, SUNMatrix A) {
  EigenDenseContent& c = content(S);
  const Eigen::Index n = SUNDenseMatrix_Rows(A);
  const Eigen::Map<const Eigen::MatrixXd> a(SUNDenseMatrix_Data(A), n, n);  // column-major
  if (!a.allFinite()) return int(c.last_flag = SUNLS_LUFACT_FAIL);
  c.lu.compute(a);
  // PartialPivLU does not report singularity: a zero pivot shows on U's diagonal.
  if (c.lu.matrixLU().diagonal().cwiseAbs().minCoeff() == 0.0)
    return int(c.last_flag = SUNLS_LUFACT_FAIL);
  return int(c.last_flag = SUNLS_SUCCESS);
}

// b of length n: one solve. b of length n k (the variational equations'
// matrix Y, n x k column-major, whose Newton matrix is I - gamma J in every
// column): the k columns in one blocked solve.
int solve(SUNLinearSolver S, SUNMatrix, N_Vector x, N_Vector b, realtype) {
  EigenDenseContent& c = content(S);
  const Eigen::Index n = c.lu.rows(), length = N_VGetLength(b);
  if (n == 0 || length % n != 0) return int(c.last_flag = SUNLS_ILL_INPUT);
  if (length == n) {
    Eigen::Map<Eigen::VectorXd> xv(N_VGetArrayPointer(x), n);
    const Eigen::Map<const Eigen::VectorXd> bv(N_VGetArrayPointer(b), n);
    xv = c.lu.solve(bv);
  } else {
    // Through an Eigen-owned (aligned) copy: the blocked solve's kernels then
    // sum in the same order whatever the N_Vector's address.
    c.block = Eigen::Map<const Eigen::MatrixXd>(N_VGetArrayPointer(b), n, length / n);
    c.block_solution = c.lu.solve(c.block);
    Eigen::Map<Eigen::MatrixXd>(N_VGetArrayPointer(x), n, length / n) = c.block_solution;
  }
  return int(c.last_flag = SUNLS_SUCCESS);
}

sunindextype last_flag(SUNLinearSolver S) { return content(S).last_flag; }

int free_solver(SUNLinearSolver S) {
  if (!S) return SUNLS_SUCCESS;
  delete static_cast<EigenDenseContent*>(S->content);
  S->content = nullptr;
  SUNLinSolFreeEmpty(S);
  return SUNLS_SUCCESS;
}

}  // namespace

SUNLinearSolver make_eigen_dense_solver(long n, SUNContext ctx) {
  SUNLinearSolver S = SUNLinSolNewEmpty(ctx);
  if (!S) return nullptr;
  S->content = new (std::nothrow) EigenDenseContent(n);
  if (!S->content) {
    SUNLinSolFreeEmpty(S);
    return nullptr;
  }
  S->ops->gettype = get_type;
  S->ops->getid = get_id;
  S->ops->initialize = initialize;
  S->ops->setup = setup;
  S->ops->solve = solve;
  S->ops->lastflag = last_flag;
  S->ops->free = free_solver;
  return S;
}

}  // namespace railstab
