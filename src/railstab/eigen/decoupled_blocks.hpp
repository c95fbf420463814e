#pragma once
// The diagonal blocks a square matrix decouples into.
//
// A state matrix often falls apart: on tangent track a left/right symmetric
// vehicle's lateral motion (lateral, roll, yaw) does not couple with its
// vertical and longitudinal motion (bounce, pitch, surge) in the linear
// model, so that after a symmetric permutation A is block diagonal. Its
// eigenvalues are then the blocks' eigenvalues, and a block's eigenvector
// with zeros on the other states is one of A's: the QR algorithm on the
// blocks costs sum m_b^3 instead of n^3 (thesis vehicle: blocks of 36 and
// 42 of 78 states, 0.25x the flops).
//
// In floating point the linearisation leaves round-off where the exact
// matrix has zeros (AD derivatives of terms that cancel left against right:
// ~3e-18 ||B||_F on the thesis vehicle's balanced matrix B, 1.4e-16 ||A||_F
// on the 16-car train's). Entries count as coupling when |b_ij| > u ||B||_F
// (u = eps / 2, the unit round-off), and a split is accepted only if the
// entries it drops have together a Frobenius norm of at most sqrt(n) u ||B||_F:
// each is at the round-off level of forming B's entries, and together they
// stay below the backward error the solvers already carry (QR on the whole
// matrix ~n u ||B||_F; the sparse LU of A - sigma I ~n u ||A - sigma I||).
// Dropping them moves an eigenvalue of one block only at second order:
// its left and right eigenvectors vanish on the other blocks, so y^H E x = 0
// and the change is ~||E||^2 / (distance to the other blocks' eigenvalues);
// only an eigenvalue two blocks share moves by ~||E||, as it does in a QR
// on the whole matrix. Otherwise the one block is all of B.
#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <vector>

namespace railstab {

// The index sets of the blocks (each ascending; blocks in the order of
// their smallest index); one block 0..n-1 when B does not decouple.
std::vector<std::vector<int>> decoupled_blocks(const Eigen::MatrixXd& B);

// The same for a sparse matrix (its stored entries; the same criterion
// against its Frobenius norm).
std::vector<std::vector<int>> decoupled_blocks(const Eigen::SparseMatrix<double>& B);

}  // namespace railstab
