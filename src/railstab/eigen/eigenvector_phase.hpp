#pragma once
// The EigenPair::vector convention (eigen/eigen_analysis.hpp), shared by the
// solvers that build eigenpairs (eigen_analysis.cpp, band_eigen.cpp).
#include <Eigen/Dense>

namespace railstab {

// v scaled to unit 2-norm with its largest-magnitude component real and
// positive (zero stays zero).
Eigen::VectorXcd with_canonical_phase(Eigen::VectorXcd v);

}  // namespace railstab
