#include <railstab/integrate/stepper.hpp>

#include <railstab/integrate/dense_newton_matrix.hpp>
#include <railstab/integrate/eigen_dense_solver.hpp>

#include <sunlinsol/sunlinsol_klu.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include <cstdlib>
#include <stdexcept>

namespace railstab {

Stepper::Stepper(const Eigen::VectorXd& x0) {
  check_sundials(SUNContext_Create(nullptr, &ctx_), "SUNContext_Create");
  y_ = N_VNew_Serial(x0.size(), ctx_);
  if (!y_) {
    SUNContext_Free(&ctx_);
    throw std::runtime_error("SUNDIALS N_VNew_Serial failed");
  }
  as_eigen(y_) = x0;
}

Stepper::~Stepper() {
  if (y_) N_VDestroy(y_);
  if (ctx_) SUNContext_Free(&ctx_);
}

IntegratorMemory::IntegratorMemory(void* m, void (*f)(void**)) : mem(m), free(f) {
  if (!mem) throw std::runtime_error("SUNDIALS integrator creation failed");
}

IntegratorMemory::~IntegratorMemory() {
  if (mem) free(&mem);
}

NewtonLinearSolver::NewtonLinearSolver(N_Vector y, SUNContext ctx, const ModelCallbackData& data) {
  const sunindextype n = N_VGetLength(y);
  if (data.sparse_newton()) {
    A = SUNSparseMatrix(n, n, data.sparse_layout.nonzeros(), CSC_MAT, ctx);
    if (A) LS = SUNLinSol_KLU(y, A, ctx);
  } else {
    A = make_dense_newton_matrix(n, ctx);
    if (A) LS = make_eigen_dense_solver(n, ctx);
  }
  if (!A || !LS) {
    if (A) SUNMatDestroy(A);
    throw std::runtime_error(std::string("SUNDIALS ") + (data.sparse_newton() ? "sparse (KLU)" : "dense") +
                             " matrix/linear solver creation failed");
  }
}

NewtonLinearSolver::~NewtonLinearSolver() {
  SUNLinSolFree(LS);
  SUNMatDestroy(A);
}

void check_sundials(int flag, const char* call) {
  if (flag < 0)
    throw std::runtime_error(std::string("SUNDIALS ") + call + " failed, flag " +
                             std::to_string(flag));
}

std::string take_sundials_string(char* name) {
  if (name == nullptr) return "unknown SUNDIALS return flag";
  std::string copy(name);
  std::free(name);
  return copy;
}

}  // namespace railstab
