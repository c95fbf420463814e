#pragma once
// eigen_dense (eigen/eigen_analysis.hpp) as it was before issue 11: every
// eigenvector phased, normalised and checked on its own (no use of a
// complex pair's conjugate), sorted least stable first. The reference its
// faster version must match bit for bit (tests/eigen/test_eigen_dense_pairs.cpp)
// and the baseline of its timing (analysis/bench_jacobian.cpp, which also
// asks for the old cost: the eigenvector matrix rebuilt per column).
#include <railstab/eigen/balance.hpp>
#include <railstab/eigen/eigen_analysis.hpp>

#include <Eigen/Dense>

#include <algorithm>
#include <complex>
#include <vector>

namespace railstab::test {

// Canonical phase spelled out: the component of largest modulus |.| real
// and positive, unit norm.
inline Eigen::VectorXcd reference_phase(Eigen::VectorXcd v) {
  const double norm = v.norm();
  if (norm == 0.0) return v;
  Eigen::Index peak = 0;
  v.cwiseAbs().maxCoeff(&peak);
  const std::complex<double> unit_phase = v(peak) / std::abs(v(peak));
  return v * (std::conj(unit_phase) / norm);
}

inline std::vector<EigenPair> column_by_column_eigen(const Eigen::MatrixXd& A,
                                                     bool eigenvectors_per_column = false) {
  using Complex = std::complex<double>;
  // The same balanced QR as eigen_dense (eigen/balance.hpp): what is
  // compared is the post-processing.
  const BalancedMatrix balanced = balance(A);
  Eigen::EigenSolver<Eigen::MatrixXd> solver(balanced.matrix, true);
  const Eigen::VectorXcd D_diagonal = balanced.scaling.cast<std::complex<double>>();
  const auto D = D_diagonal.asDiagonal();
  Eigen::MatrixXcd vectors;
  if (!eigenvectors_per_column) vectors = D * solver.eigenvectors();
  const double norm_A = A.norm();
  std::vector<EigenPair> pairs;
  for (Eigen::Index j = 0; j < A.rows(); ++j) {
    const Eigen::VectorXcd column =
        eigenvectors_per_column ? Eigen::VectorXcd(D * solver.eigenvectors().col(j)) : vectors.col(j);
    EigenPair p{solver.eigenvalues()(j), reference_phase(column), 0.0};
    const Eigen::VectorXd Av_re = A * p.vector.real(), Av_im = A * p.vector.imag();
    const Eigen::VectorXcd Av = Av_re.cast<Complex>() + Complex(0.0, 1.0) * Av_im.cast<Complex>();
    p.residual = (Av - p.value * p.vector).norm() / (norm_A * p.vector.norm());
    pairs.push_back(p);
  }
  std::sort(pairs.begin(), pairs.end(), [](const EigenPair& a, const EigenPair& b) {
    if (a.value.real() != b.value.real()) return a.value.real() > b.value.real();
    return a.value.imag() > b.value.imag();
  });
  return pairs;
}

}  // namespace railstab::test
