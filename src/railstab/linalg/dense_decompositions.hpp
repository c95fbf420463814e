#pragma once
// Eigen's dense decompositions on the library's matrix types, compiled once.
//
// EigenSolver (with its real Schur and Hessenberg steps), the SVDs and the LU
// factorisations are the heaviest templates the library instantiates: a file
// that used EigenSolver<MatrixXd> spent most of its compile time on it, and
// six files did (issue 21, "a fast first run"). The declarations below tell
// every file that includes this header (the precompiled header does, see
// RAILSTAB_PRECOMPILED_HEADERS in CMakeLists.txt) not to instantiate them: the
// files beside this one hold the one explicit instantiation each, split so
// that two cores compile them side by side. The code that runs is Eigen's
// own, unchanged: only where it is compiled moves (outputs stay
// bit-identical, scripts/snapshot_outputs.sh).
//
// A decomposition of another matrix type, or EigenSolver::compute on an
// expression (a Transpose, a block), is still instantiated where it is used:
// pass a MatrixXd to get the shared one.

#include <Eigen/Dense>

namespace Eigen {

// linalg/eigen_solver_instance.cpp: the decomposition and the eigenvectors
// (the members that hold the work; the accessors stay inline).
extern template EigenSolver<MatrixXd>& EigenSolver<MatrixXd>::compute<MatrixXd>(
    const EigenBase<MatrixXd>&, bool);
extern template EigenSolver<MatrixXd>::EigenvectorsType EigenSolver<MatrixXd>::eigenvectors() const;

// linalg/svd_instances.cpp: the whole classes (BDCSVD's constructor is
// inline and calls the rest; as members it would be compiled where used).
extern template class JacobiSVD<MatrixXd>;
extern template class BDCSVD<MatrixXd>;

// linalg/lu_instances.cpp: the factorisations (the solves are member
// templates on the right-hand side's type and stay where they are used).
extern template PartialPivLU<MatrixXd>::PartialPivLU(Index);
extern template void PartialPivLU<MatrixXd>::compute();
extern template void PartialPivLU<MatrixXcd>::compute();
extern template void FullPivLU<MatrixXd>::computeInPlace();

}  // namespace Eigen
