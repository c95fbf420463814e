// The one instantiation of Eigen's EigenSolver on MatrixXd (its real Schur
// and Hessenberg steps come with it): dense_decompositions.hpp says why.
#include <railstab/linalg/dense_decompositions.hpp>

namespace Eigen {
template EigenSolver<MatrixXd>& EigenSolver<MatrixXd>::compute<MatrixXd>(const EigenBase<MatrixXd>&,
                                                                         bool);
template EigenSolver<MatrixXd>::EigenvectorsType EigenSolver<MatrixXd>::eigenvectors() const;
}  // namespace Eigen
