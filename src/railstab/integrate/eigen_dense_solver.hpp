#pragma once
// A SUNDIALS dense direct linear solver on Eigen's partial-pivoting LU.
//
// Why: SUNDIALS' own dense solver (SUNLinSol_Dense) is unblocked scalar code;
// on the 82-state thesis vehicle its factorisation and solves were 35-55 %
// of the implicit integrators' time (perf). Eigen's blocked, vectorised LU
// does the same work several times faster. Same contract: setup factors the
// SUNDIALS dense matrix SUNDIALS assembled (I - gamma J), solve applies it;
// an exactly singular or non-finite matrix is a recoverable failure.
// A right-hand side of length n k is solved as an n x k matrix, column by
// column with the one factorisation (the periodic orbits' variational
// equations, nonlinear/variational_pass.hpp, whose Newton matrix is the
// state's I - gamma J in every column).
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>

namespace railstab {

// Free with SUNLinSolFree.
SUNLinearSolver make_eigen_dense_solver(long n, SUNContext ctx);

}  // namespace railstab
