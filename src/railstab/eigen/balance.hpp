#pragma once
// Diagonal balancing of a real square matrix before the QR algorithm
// (Parlett & Reinsch 1969; the scaling half of LAPACK's dgebal, without its
// permutations): B = D^-1 A D with D = diag(2^e_i) chosen so that, for every
// i, the off-diagonal 1-norms of row i and column i of B are within a factor
// of about 2 of each other.
//
// Why: the QR algorithm's eigenvalues carry a backward error of order
// eps ||A||. A vehicle's state matrix mixes rows of 1 (dq/dt = u) with rows
// of stiffness/mass (1e7 N/m over 1e3 kg: 1e4 1/s^2, contact rows more):
// ||A||_F ~ 5e6 for the thesis vehicle, ~9e3 balanced. The eigenvalues of
// the slow, lightly damped modes that decide stability are then resolved
// against a norm 500x smaller, at about the same cost
// (thesis vehicle: 0.93-0.98x the time of EigenSolver on A, balancing included; the coach 1.03x, measured by
// analysis/bench_jacobian).
//
// Powers of two make the similarity exact in floating point: B has exactly
// A's eigenvalues, and an eigenvector v of B gives A's as D v (exact too).
#include <Eigen/Dense>

namespace railstab {

struct BalancedMatrix {
  Eigen::MatrixXd matrix;   // B = D^-1 A D
  Eigen::VectorXd scaling;  // the diagonal of D (powers of two)
};

// A must be square and finite (not checked here: eigen_dense checks).
// Rows or columns whose off-diagonal part is zero are left unscaled.
BalancedMatrix balance(const Eigen::MatrixXd& A);

}  // namespace railstab
