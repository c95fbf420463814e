#include <railstab/eigen/balance.hpp>

#include <cmath>

namespace railstab {

BalancedMatrix balance(const Eigen::MatrixXd& A) {
  const Eigen::Index n = A.rows();
  BalancedMatrix out{A, Eigen::VectorXd::Ones(n)};
  Eigen::MatrixXd& B = out.matrix;
  // Scaling row i by 1/f and column i by f changes the sum c + r of the
  // off-diagonal column and row norms to c f + r / f, which is smallest
  // near f = sqrt(r / c); f is the power of two that brings c f^2 within
  // [r / 2, 2 r). A step is taken only if it reduces c + r by 5 % (dgebal's
  // criterion), so the sweeps stop; each sweep's exponents are bounded, and
  // the sweeps are capped for safety.
  //
  // The off-diagonal row and column sums are formed once (contiguous
  // column-wise passes) and kept up to date as rows and columns are scaled:
  // scaling column i by f adds (f - 1) |B(j, i)| to row j's sum, scaling row
  // i by 1/f adds (1/f - 1) |B(i, j)| to column j's. They only steer the
  // choice of D; B itself is scaled exactly.
  constexpr int kMaxSweeps = 100;
  const Eigen::MatrixXd magnitude = B.cwiseAbs();
  Eigen::VectorXd col_sum = magnitude.colwise().sum().transpose() - magnitude.diagonal();
  Eigen::VectorXd row_sum = magnitude.rowwise().sum() - magnitude.diagonal();
  for (int sweep = 0; sweep < kMaxSweeps; ++sweep) {
    bool changed = false;
    for (Eigen::Index i = 0; i < n; ++i) {
      const double c = col_sum(i), r = row_sum(i);
      if (!(c > 0.0) || !(r > 0.0)) continue;
      // f = 2^e with c 4^e in [r / 2, 2 r): e from the exponents directly
      // (no loop that could run long on extreme ratios).
      int e = int(std::floor(0.5 * std::log2(r / c) + 0.5));
      // Keep D's entries far from overflow and underflow.
      const int current = std::ilogb(out.scaling(i));
      if (current + e > 300) e = 300 - current;
      if (current + e < -300) e = -300 - current;
      if (e == 0) continue;
      const double f = std::ldexp(1.0, e);
      if ((c * f + r / f) >= 0.95 * (c + r)) continue;
      for (Eigen::Index j = 0; j < n; ++j) {
        if (j == i) continue;
        row_sum(j) += (f - 1.0) * std::abs(B(j, i));
        col_sum(j) += (1.0 / f - 1.0) * std::abs(B(i, j));
      }
      B.col(i) *= f;
      B.row(i) /= f;
      col_sum(i) = c * f;
      row_sum(i) = r / f;
      out.scaling(i) *= f;
      changed = true;
    }
    if (!changed) break;
  }
  return out;
}

}  // namespace railstab
