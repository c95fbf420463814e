#pragma once
// Synthetic damped mechanical systems in first-order form, shared by the
// eigen-solver tests and analysis/bench_eigen (which has tests/ on its
// include path for this header).
#include <Eigen/Dense>

#include <random>

namespace railstab::test {

// x' = A x with x = [q; u]: q' = u, M u' = -K q - C u.
inline Eigen::MatrixXd first_order_form(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K,
                                        const Eigen::MatrixXd& C) {
  const Eigen::Index dofs = M.rows();
  const Eigen::PartialPivLU<Eigen::MatrixXd> mass(M);
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * dofs, 2 * dofs);
  A.topRightCorner(dofs, dofs).setIdentity();
  A.bottomLeftCorner(dofs, dofs) = -mass.solve(K);
  A.bottomRightCorner(dofs, dofs) = -mass.solve(C);
  return A;
}

inline Eigen::MatrixXd random_orthogonal(Eigen::Index n, std::mt19937& rng) {
  std::normal_distribution<double> normal;
  const Eigen::MatrixXd G = Eigen::MatrixXd::NullaryExpr(n, n, [&] { return normal(rng); });
  return Eigen::HouseholderQR<Eigen::MatrixXd>(G).householderQ();
}

// Q diag(d) Q^T with d uniform in [lo, hi]: SPD with a known spread.
inline Eigen::MatrixXd random_spd(Eigen::Index n, double lo, double hi, std::mt19937& rng) {
  std::uniform_real_distribution<double> uniform(lo, hi);
  const Eigen::MatrixXd Q = random_orthogonal(n, rng);
  const Eigen::VectorXd d = Eigen::VectorXd::NullaryExpr(n, [&] { return uniform(rng); });
  return Q * d.asDiagonal() * Q.transpose();
}

// A lightly damped mechanical system with natural frequencies spread over
// roughly 0.2..20 rad/s, so that sigma = 0.5 + 5i sits inside the spectrum.
inline Eigen::MatrixXd damped_mechanical_system(Eigen::Index states, unsigned seed) {
  std::mt19937 rng(seed);
  const Eigen::Index dofs = states / 2;
  const Eigen::MatrixXd M = random_spd(dofs, 1.0, 5.0, rng);
  const Eigen::MatrixXd K = random_spd(dofs, 0.25, 400.0, rng);
  const Eigen::MatrixXd C = 0.01 * K + random_spd(dofs, 0.0, 0.1, rng);
  return first_order_form(M, K, C);
}

}  // namespace railstab::test
