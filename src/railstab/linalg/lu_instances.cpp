// The one instantiation of Eigen's LU factorisations on the library's matrix
// types: dense_decompositions.hpp says why. Only the factorising members: a
// whole-class instantiation compiles every member (determinant, inverse,
// reconstruction) and took twice as long.
#include <railstab/linalg/dense_decompositions.hpp>

namespace Eigen {
template PartialPivLU<MatrixXd>::PartialPivLU(Index);
template void PartialPivLU<MatrixXd>::compute();
template void PartialPivLU<MatrixXcd>::compute();
template void FullPivLU<MatrixXd>::computeInPlace();
}  // namespace Eigen
