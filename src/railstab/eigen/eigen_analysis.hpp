#pragma once
// Eigenvalues of the linearised state matrix A (real, nonsymmetric): the
// stability of the vehicle at one speed. Two solvers:
//  - eigen_dense: every eigenpair, for small models and as the reference;
//  - eigen_arpack_shift_invert: the few eigenpairs nearest a complex shift
//    (e.g. near the expected hunting frequency), by ARPACK's real
//    nonsymmetric Arnoldi driver in shift-invert mode.
// Plus what a speed sweep needs: frequency and damping ratio of a mode, and
// mode tracking from one speed to the next by eigenvector similarity.
#include <Eigen/Dense>

#include <complex>
#include <vector>

namespace railstab {

struct EigenPair {
  std::complex<double> value;
  // Unit 2-norm, phase fixed so that the largest-magnitude component is real
  // and positive (so vectors of the same mode compare across speeds).
  Eigen::VectorXcd vector;
  // ||A v - lambda v|| / (||A||_F ||v||): backward-error-like, scale free.
  double residual;
};

// All eigenpairs (Eigen::EigenSolver), sorted by descending real part (least
// stable first), ties by descending imaginary part.
std::vector<EigenPair> eigen_dense(const Eigen::MatrixXd& A);

struct ArpackOptions {
  std::complex<double> shift;
  int n_eigenvalues = 12;
  double tolerance = 1e-12;  // ARPACK's relative Ritz-value tolerance on OP
  int max_iterations = 3000;
};

// The opt.n_eigenvalues eigenpairs of A nearest opt.shift, sorted by distance
// to the shift. A conjugate pair equidistant from the shift (real shift) is
// never split: the partner is appended, so one more pair may be returned.
// Method: (A - shift I) is factorised once (complex LU); ARPACK dnaupd/dneupd
// iterate with OP = Re((A - shift I)^-1) (mode 3), and the eigenpairs of A
// are recovered by Rayleigh-Ritz on the converged invariant subspace (the
// Ritz values ARPACK returns for a complex shift are OP's, not A's). ARPACK
// finds OP's largest eigenvalues, which with a complex shift are only
// roughly A's nearest ones, so the result is checked against a bound and the
// Ritz count grown until no unseen eigenvalue can be nearer. Where mode 3
// cannot tell (the wanted disc reaches Re(shift) on the real axis, where
// OP's eigenvalue is 0), it switches to OP = Im((A - shift I)^-1) (mode 4).
// Throws std::invalid_argument for bad input (non-square or non-finite A,
// n_eigenvalues outside [1, n - 2], non-positive iterations, negative
// tolerance, shift on an eigenvalue) and std::runtime_error with ARPACK's
// info code and its meaning if ARPACK fails. Not reentrant inside ARPACK
// (Fortran SAVE state): calls are serialised by an internal mutex.
std::vector<EigenPair> eigen_arpack_shift_invert(const Eigen::MatrixXd& A,
                                                 const ArpackOptions& opt);

struct ModeInfo {
  double frequency_hz;   // |Im lambda| / (2 pi)
  double damping_ratio;  // -Re lambda / |lambda|; 1 real negative, -1 real positive, 0 at 0
  bool oscillatory;      // Im lambda != 0
};
ModeInfo mode_info(std::complex<double> lambda);

// Modal assurance criterion |a^H b|^2 / ((a^H a)(b^H b)), in [0, 1]; 0 if
// either vector is zero.
double modal_assurance(const Eigen::VectorXcd& a, const Eigen::VectorXcd& b);

// Mode tracking between two speeds. Result[i] is the index in `current` of
// the mode that continues previous[i], or -1 if none does. Only oscillatory
// modes take part: those with Im > 0 are paired by an optimal (Hungarian)
// assignment maximising the summed MAC, and each Im < 0 mode follows its
// conjugate partner. Non-oscillatory modes, and modes left over when the
// counts differ (a pair turned real or appeared), get -1.
std::vector<int> match_modes(const std::vector<EigenPair>& previous,
                             const std::vector<EigenPair>& current);

}  // namespace railstab
