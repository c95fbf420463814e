// The one instantiation of Eigen's SVDs on MatrixXd (BDCSVD hands small
// matrices to JacobiSVD): dense_decompositions.hpp says why.
#include <railstab/linalg/dense_decompositions.hpp>

namespace Eigen {
template class JacobiSVD<MatrixXd>;
template class BDCSVD<MatrixXd>;
}  // namespace Eigen
