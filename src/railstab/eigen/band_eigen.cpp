#include <railstab/eigen/band_eigen.hpp>
#include <railstab/eigen/decoupled_blocks.hpp>
#include <railstab/eigen/eigenvector_phase.hpp>

#include <Eigen/Eigenvalues>

#include <Eigen/SparseLU>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>

namespace railstab {

namespace {

using Complex = std::complex<double>;
using ComplexSparse = Eigen::SparseMatrix<Complex>;

// The disc is proven free of unseen eigenvalues up to the farthest returned
// one; a hair less, so that an eigenvalue on its rim (as computed by another
// shift, differing at round-off) is never taken as inside.
constexpr double kRimMargin = 1e-6;

void validate_matrix(const Eigen::SparseMatrix<double>& A) {
  if (A.rows() != A.cols() || A.rows() < 4)
    throw std::invalid_argument("eigen_sparse_band: A must be square with at least 4 rows, got " +
                                std::to_string(A.rows()) + " x " + std::to_string(A.cols()));
  for (Eigen::Index k = 0; k < A.nonZeros(); ++k)
    if (!std::isfinite(A.valuePtr()[k]))
      throw std::invalid_argument("eigen_sparse_band: matrix has NaN or infinite entries");
}

void validate(const Eigen::SparseMatrix<double>& A, const BandCoverOptions& o) {
  validate_matrix(A);
  if (!(o.min_real_part_per_s < o.max_real_part_per_s) || !(o.max_frequency_hz > 0.0) ||
      !std::isfinite(o.min_real_part_per_s) || !std::isfinite(o.max_real_part_per_s) ||
      !std::isfinite(o.max_frequency_hz))
    throw std::invalid_argument(
        "eigen_sparse_band: expected min_real_part_per_s < max_real_part_per_s and "
        "max_frequency_hz > 0, all finite");
  if (o.eigenvalues_per_shift < 1 || o.max_shifts < 1)
    throw std::invalid_argument(
        "eigen_sparse_band: eigenvalues_per_shift and max_shifts must be at least 1");
}

// A - sigma I for any sigma: the pattern of A plus the diagonal, analysed
// once; each shift only refactorises the values.
class ShiftedSparseLU {
 public:
  explicit ShiftedSparseLU(const Eigen::SparseMatrix<double>& A) : A_(A) {
    ComplexSparse identity(A.rows(), A.cols());
    identity.setIdentity();
    shifted_ = A.cast<Complex>() + identity;  // the pattern with the whole diagonal
    shifted_.makeCompressed();
    lu_.analyzePattern(shifted_);
  }

  // Factorises A - sigma I; false if it is singular (sigma an eigenvalue).
  // The same sigma again (k doubled at one shift) keeps the factors.
  bool factorise(Complex sigma) {
    if (factorised_ && sigma == sigma_) return true;
    factorised_ = false;
    sigma_ = sigma;
    shifted_ = A_.cast<Complex>();
    ComplexSparse identity(A_.rows(), A_.cols());
    identity.setIdentity();
    shifted_ -= sigma * identity;
    shifted_.makeCompressed();
    lu_.factorize(shifted_);
    factorised_ = lu_.info() == Eigen::Success;
    return factorised_;
  }

  void solve(const Complex* x, Complex* y) {
    const Eigen::Index n = A_.rows();
    Eigen::Map<Eigen::VectorXcd>(y, n) = lu_.solve(Eigen::Map<const Eigen::VectorXcd>(x, n));
  }

 private:
  const Eigen::SparseMatrix<double>& A_;
  ComplexSparse shifted_;
  Eigen::SparseLU<ComplexSparse, Eigen::COLAMDOrdering<int>> lu_;
  Complex sigma_{0.0, 0.0};
  bool factorised_ = false;
};

// A - sigma I factorised, nudged along Im where sigma is an eigenvalue
// (singular): returns the shift actually factorised.
Complex factorise_near(ShiftedSparseLU& lu, Complex sigma, double nudge) {
  for (int attempt = 0; !lu.factorise(sigma); ++attempt) {
    if (attempt >= 3)
      throw std::runtime_error("eigen_sparse_band: A - sigma I singular near sigma = " +
                               std::to_string(sigma.real()) + " + " +
                               std::to_string(sigma.imag()) + "i");
    sigma += Complex(0.0, nudge);
  }
  return sigma;
}

// Krylov-Schur restarted Arnoldi (Stewart, SIAM J. Matrix Anal. Appl. 23,
// 2002) for the eigenvalues theta of largest magnitude of a complex
// operator OP given as y = OP x. The Krylov relation
//   OP V_m = V_m S + v_{m+1} b^H       (V orthonormal, n x (m + 1))
// is kept in H = [S; b^H] ((m + 1) x m). Each cycle expands the basis to m
// by Arnoldi steps (classical Gram-Schmidt twice, Eigen's GEMV), takes the
// Schur form S = Q T Q^H (Eigen's ComplexSchur) reordered so that the p
// largest |T_ii| lead (unitary swaps of adjacent diagonal entries, as
// LAPACK's ztrexc), and keeps those p Schur vectors: V_p <- V_m Q_p, S <-
// T_pp, b^H <- b^H Q_p, v_{p+1} <- v_{m+1}. A Ritz pair (theta_i, V_m Q y_i),
// T y_i = theta_i y_i, has residual ||OP x - theta x|| = |b^H Q y_i| ||y_i||^-1
// (||x|| = ||y_i||); it has converged when that is <= tolerance |theta_i|
// (ARPACK's test). The wanted: the k largest |T_ii|, all converged; the
// next largest kept as well (p = (k + m) / 2).
// It replaces ARPACK's znaupd here: a restart that keeps the largest Ritz
// vectors (as ARPACK's exact shifts do) and the same convergence test, but
// the orthogonalisation runs in Eigen's vectorised GEMV instead of the
// reference BLAS zgemv that ARPACK calls (16-car train, 1248 states: one band
// solve 1.4 s CPU instead of 2.4 s; no Fortran SAVE state, so no lock).
// The convergence tolerance of a Ritz value theta of OP = (A - sigma I)^-1,
// relative to |theta|: `inside` where its eigenvalue lambda = sigma + 1 /
// theta lies in the box the caller reports (or near it: 1e-4 |lambda -
// sigma| around it), `outside` elsewhere. Eigenvalues outside the box only
// bound a disc's radius (to the rim margin, 1e-6 relative) and are drawn in
// the root locus; the train's out-of-box modes come in clusters of nearly
// equal modes (one per car, relative spread 1e-10..1e-7) that take many
// restarts to separate to 1e-12.
struct RitzTolerance {
  double inside = 1e-12, outside = 1e-12;  // outside <= inside: `inside` everywhere
  Complex sigma{0.0, 0.0};
  double min_real = 0.0, max_real = 0.0, max_imag = 0.0;

  double of(Complex theta) const {
    if (outside <= inside) return inside;
    const Complex offset = 1.0 / theta;
    const Complex lambda = sigma + offset;
    const double near = 1e-4 * std::abs(offset);
    const bool in_box = lambda.real() >= min_real - near && lambda.real() <= max_real + near &&
                        std::abs(lambda.imag()) <= max_imag + near;
    return in_box ? inside : outside;
  }
};

struct KrylovSchurResult {
  std::vector<Complex> values;  // theta, largest magnitude first
  Eigen::MatrixXcd vectors;     // their Ritz vectors (columns, unit norm)
  int restarts = 0;
  int operator_applications = 0;
  bool converged = false;
  // Stopped early on a converged prefix (PrefixStop): `values` are the
  // leading Ritz values, all converged, ending at a gap.
  bool prefix = false;
};

// An earlier stop with fewer than the k wanted. Sorted by |theta|
// descending, the leading Ritz pairs that have all converged (a prefix)
// rest on the same Krylov assumption as the full k (no unconverged Ritz
// value ahead of them, none of OP's larger eigenvalues unseen), so they
// are the nearest eigenvalues as well. After `after_restarts` restarts the
// solve returns the longest such prefix whose smallest |theta| is at most
// `max_theta_magnitude` (a disc wide enough for the caller) and that ends at
// a gap, |theta_j| > (1 + min_gap) |theta_{j+1}|: the disc's rim then does not
// cut a cluster of nearly equal modes whose unconverged members lie just
// outside it (the rim margin, 1e-6, is far inside the gap).
struct PrefixStop {
  int after_restarts = -1;  // < 0: never (all k or nothing)
  double max_theta_magnitude = 0.0;
  double min_gap = 1e-3;
};

// Swaps the adjacent diagonal entries i, i + 1 of the upper triangular T by
// a unitary 2 x 2 Z (T <- Z^H T Z on rows and columns i, i + 1; Q <- Q Z):
// Z's first column is T's eigenvector for T(i+1, i+1) in that 2 x 2 block,
// x = [T(i, i+1); T(i+1, i+1) - T(i, i)].
void swap_schur_diagonal(Eigen::MatrixXcd& T, Eigen::MatrixXcd& Q, Eigen::Index i) {
  const Complex t11 = T(i, i), t22 = T(i + 1, i + 1);
  Eigen::Vector2cd x(T(i, i + 1), t22 - t11);
  const double norm_x = x.norm();
  if (!(norm_x > 0.0)) return;  // equal and decoupled: already in order
  x /= norm_x;
  Eigen::Matrix2cd Z;
  Z << x(0), -std::conj(x(1)), x(1), std::conj(x(0));
  const Eigen::Index m = T.rows();
  T.block(0, i, i + 2, 2) = (T.block(0, i, i + 2, 2) * Z).eval();
  T.block(i, i, 2, m - i) = (Z.adjoint() * T.block(i, i, 2, m - i)).eval();
  Q.middleCols(i, 2) = (Q.middleCols(i, 2) * Z).eval();
  T(i + 1, i) = 0.0;
  T(i, i) = t22;
  T(i + 1, i + 1) = t11;
}

// The eigenvector of the upper triangular T for T(i, i) (support 0..i,
// component i = 1), by back substitution; a near-zero pivot (two nearly
// equal diagonal entries) is raised to eps |theta| as LAPACK's ztrevc.
Eigen::VectorXcd triangular_eigenvector(const Eigen::MatrixXcd& T, Eigen::Index i) {
  Eigen::VectorXcd y = Eigen::VectorXcd::Zero(i + 1);
  const Complex theta = T(i, i);
  const double small = std::numeric_limits<double>::epsilon() * std::max(std::abs(theta), 1e-300);
  y(i) = 1.0;
  for (Eigen::Index r = i - 1; r >= 0; --r) {
    Complex sum = 0.0;
    for (Eigen::Index q = r + 1; q <= i; ++q) sum += T(r, q) * y(q);
    Complex pivot = T(r, r) - theta;
    if (std::abs(pivot) < small) pivot = small;
    y(r) = -sum / pivot;
  }
  return y;
}

template <class Op>
KrylovSchurResult krylov_schur_largest(Op&& op, Eigen::Index n, int k, int m, const RitzTolerance& tolerance,
                                       int max_restarts, const PrefixStop& prefix_stop = {}) {
  KrylovSchurResult out;
  Eigen::MatrixXcd V(n, m + 1);
  Eigen::MatrixXcd H = Eigen::MatrixXcd::Zero(m + 1, m);
  Eigen::VectorXcd w(n), h(m + 1), c(m + 1);
  // Fixed start vector: results do not depend on earlier solves.
  std::mt19937_64 generator(20261130);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  const auto random_vector = [&](Eigen::VectorXcd& x) {
    for (Eigen::Index i = 0; i < n; ++i) x(i) = Complex(uniform(generator), uniform(generator));
  };
  random_vector(w);
  V.col(0) = w / w.norm();
  // w minus its components along V's first j columns, twice (CGS2);
  // the coefficients are added to h.
  const auto orthogonalise = [&](Eigen::Index j) {
    h.head(j).setZero();
    for (int pass = 0; pass < 2; ++pass) {
      c.head(j).noalias() = V.leftCols(j).adjoint() * w;
      w.noalias() -= V.leftCols(j) * c.head(j);
      h.head(j) += c.head(j);
    }
  };
  int p = 0;  // leading columns of V whose part of H is already known
  Eigen::MatrixXcd T, Q;
  for (int restart = 0;; ++restart) {
    for (int j = p; j < m; ++j) {
      op(V.col(j).data(), w.data());
      ++out.operator_applications;
      const double norm_w = w.norm();
      orthogonalise(j + 1);
      H.col(j).head(j + 1) = h.head(j + 1);
      double beta = w.norm();
      if (!(beta > 1e-10 * norm_w)) {
        // An invariant subspace: S is exact there; go on with any
        // direction orthogonal to it (no coupling: b's entry is 0).
        beta = 0.0;
        random_vector(w);
        orthogonalise(j + 1);
      }
      H(j + 1, j) = beta;
      // (With j + 1 = n there is no direction left: w is round-off, and b = 0
      // makes every Ritz pair exact, so the cycle ends converged.)
      const double norm_next = w.norm();
      if (norm_next > 0.0)
        V.col(j + 1) = w / norm_next;
      else
        V.col(j + 1).setZero();
    }
    const int wanted = std::min(k, m - 2);
    // The wanted and half of the rest (the next largest) are kept at a
    // restart.
    const int keep = std::min(m - 1, std::max(wanted + 1, (wanted + m) / 2));
    // Schur form of S with the `keep` largest |theta| in its leading block
    // (a stable partition by adjacent swaps: only kept past unkept), then
    // the wanted: the `wanted` largest of that block.
    const Eigen::ComplexSchur<Eigen::MatrixXcd> schur(H.topRows(m));
    T = schur.matrixT();
    Q = schur.matrixU();
    std::vector<Eigen::Index> by_magnitude(static_cast<size_t>(m));
    std::iota(by_magnitude.begin(), by_magnitude.end(), Eigen::Index{0});
    const auto larger = [&T](Eigen::Index a, Eigen::Index b) {
      return std::abs(T(a, a)) > std::abs(T(b, b));
    };
    std::nth_element(by_magnitude.begin(), by_magnitude.begin() + keep, by_magnitude.end(), larger);
    std::vector<char> kept(static_cast<size_t>(m), 0);
    for (int i = 0; i < keep; ++i) kept[static_cast<size_t>(by_magnitude[static_cast<size_t>(i)])] = 1;
    for (Eigen::Index j = 0, front = 0; j < m; ++j) {
      if (!kept[static_cast<size_t>(j)]) continue;
      for (Eigen::Index l = j; l > front; --l) {
        swap_schur_diagonal(T, Q, l - 1);
        std::swap(kept[static_cast<size_t>(l - 1)], kept[static_cast<size_t>(l)]);
      }
      ++front;
    }
    std::vector<Eigen::Index> order(static_cast<size_t>(keep));
    std::iota(order.begin(), order.end(), Eigen::Index{0});
    std::sort(order.begin(), order.end(), larger);
    order.resize(static_cast<size_t>(wanted));
    // b^H Q: H's last row is beta e_m^T.
    const Eigen::RowVectorXcd bQ = H(m, m - 1) * Q.row(m - 1);
    std::vector<Eigen::VectorXcd> Y;
    bool converged = true;
    for (Eigen::Index i : order) {
      Y.push_back(triangular_eigenvector(T, i));
      const Complex projected = bQ.head(i + 1) * Y.back();
      converged = std::abs(projected) / Y.back().norm() <= tolerance.of(T(i, i)) * std::abs(T(i, i));
      if (!converged) break;
    }
    // The converged prefix: Y holds its pairs and, when not all converged,
    // the first unconverged one last.
    int prefix = 0;
    if (!converged && prefix_stop.after_restarts >= 0 && restart >= prefix_stop.after_restarts) {
      for (int j = int(Y.size()) - 1; j >= 1; --j) {
        const double inner = std::abs(T(order[size_t(j - 1)], order[size_t(j - 1)]));
        const double outer = std::abs(T(order[size_t(j)], order[size_t(j)]));
        if (inner <= prefix_stop.max_theta_magnitude && inner > (1.0 + prefix_stop.min_gap) * outer) {
          prefix = j;
          break;
        }
      }
    }
    if (prefix > 0) {
      out.prefix = true;
      out.restarts = restart;
      out.values.resize(size_t(prefix));
      out.vectors.resize(n, prefix);
      for (int c = 0; c < prefix; ++c) {
        const Eigen::Index i = order[size_t(c)];
        out.values[size_t(c)] = T(i, i);
        out.vectors.col(c) = (V.leftCols(m) * (Q.leftCols(i + 1) * Y[size_t(c)])).normalized();
      }
      return out;
    }
    if (converged || restart >= max_restarts) {
      // All wanted pairs; out of restarts, those of them that converged
      // (as ARPACK: then nothing is proven about the rest).
      out.converged = converged;
      out.restarts = restart;
      std::vector<Eigen::VectorXcd> x;
      for (size_t c = 0; c < order.size(); ++c) {
        const Eigen::Index i = order[c];
        if (c >= Y.size()) Y.push_back(triangular_eigenvector(T, i));
        const Complex projected = bQ.head(i + 1) * Y[c];
        if (!(std::abs(projected) / Y[c].norm() <= tolerance.of(T(i, i)) * std::abs(T(i, i)))) continue;
        out.values.push_back(T(i, i));
        x.push_back((V.leftCols(m) * (Q.leftCols(i + 1) * Y[c])).normalized());
      }
      out.vectors.resize(n, Eigen::Index(x.size()));
      for (size_t c = 0; c < x.size(); ++c) out.vectors.col(Eigen::Index(c)) = x[c];
      return out;
    }
    p = keep;
    V.leftCols(p) = (V.leftCols(m) * Q.leftCols(p)).eval();
    V.col(p) = V.col(m);
    H.setZero();
    H.topLeftCorner(p, p) = T.topLeftCorner(p, p);
    H.row(p).head(p) = bQ.head(p);
  }
}

// The k eigenpairs of A nearest sigma (complex Arnoldi on (A - sigma I)^-1,
// largest magnitude), eigenvalues as Rayleigh quotients of the Ritz vectors.
// The disc's radius: the farthest of the k (less kRimMargin), 0 when the Arnoldi
// stopped before all k converged (then the pairs returned are not proven to
// be the nearest). Pairs nearest first.
NearestEigenpairs nearest_eigenpairs(const Eigen::SparseMatrix<double>& A, double norm_A,
                                     ShiftedSparseLU& lu, Complex sigma, int k,
                                     const RitzTolerance& tolerance, const PrefixStop& prefix_stop = {}) {
  NearestEigenpairs out;
  ShiftDisc& work = out.disc;
  work.shift = sigma;
  work.eigenvalues = k;
  const Eigen::Index n = A.rows();
  const int nev = int(std::min<Eigen::Index>(k, n - 2));
  // Basis 3k + 1: the cars' nearly equal modes come in tight clusters, which
  // a wider basis separates in fewer restarts.
  const int ncv = int(std::min<Eigen::Index>(n, std::max(3 * nev + 1, 20)));
  KrylovSchurResult ks = krylov_schur_largest(
      [&lu](const Complex* x, Complex* y) { lu.solve(x, y); }, n, nev, ncv, tolerance, 3000, prefix_stop);
  work.restarts = ks.restarts;
  work.operator_applications = ks.operator_applications;
  work.prefix = ks.prefix;
  work.eigenvalues = int(ks.values.size());
  const int converged = int(ks.values.size());  // all returned have converged
  const bool all_converged = ks.converged || ks.prefix;  // a prefix is proven as all k
  std::vector<EigenPair>& pairs = out.pairs;
  for (int j = 0; j < converged; ++j) {
    const Eigen::VectorXcd z = ks.vectors.col(j);
    const Eigen::VectorXd z_re = z.real(), z_im = z.imag();
    const Eigen::VectorXcd Az = (A * z_re).cast<Complex>() + Complex(0.0, 1.0) * (A * z_im).cast<Complex>();
    const double zz = z.squaredNorm();
    if (!(zz > 0.0)) continue;
    const Complex lambda = z.dot(Az) / zz;  // Rayleigh quotient z^H A z / z^H z
    EigenPair p{lambda, with_canonical_phase(z), 0.0};
    p.residual = (Az - lambda * z).norm() / (norm_A * std::sqrt(zz));
    pairs.push_back(std::move(p));
  }
  std::sort(pairs.begin(), pairs.end(), [sigma](const EigenPair& a, const EigenPair& b) {
    return std::abs(a.value - sigma) < std::abs(b.value - sigma);
  });
  // A hair inside the farthest: one on the rim (as another shift computes
  // it, differing at round-off) is never taken as inside.
  work.radius = all_converged && !pairs.empty()
                    ? std::abs(pairs.back().value - sigma) * (1.0 - kRimMargin)
                    : 0.0;
  return out;
}

// A disc of an earlier solve as a guess for this one: where its shift was,
// how far along the band it reached (half-height h in the box) and with
// how many eigenvalues.
struct PlannedShift {
  double imag = 0.0, half_height = 0.0;
  int k = 0;
  bool used = false;
};

// The plan's discs that spanned the box's width (a disc too narrow there
// was asked again at the same shift with a larger k: only that one counts).
std::vector<PlannedShift> planned_shifts(const std::vector<ShiftDisc>& plan, double half_width) {
  std::vector<PlannedShift> out;
  for (const ShiftDisc& d : plan) {
    if (!(d.radius > half_width) || d.eigenvalues < 1 || !std::isfinite(d.shift.imag())) continue;
    const double h = std::sqrt(d.radius * d.radius - half_width * half_width);
    if (h >= 0.1 * half_width) out.push_back({d.shift.imag(), h, d.eigenvalues, false});
  }
  return out;
}

// The next planned shift for a band covered up to `covered_to`: of the
// unused ones that reach past it, the one reaching farthest among those
// whose planned disc still joins the covered part; failing that the lowest.
// Either is lowered where needed so that its planned disc overlaps the
// covered part by 10 % of its half-height (a disc shrinks a little from one
// speed to the next; one that just touched would leave a gap). Each is used
// once (a guess that left a gap is not repeated). nullptr: none left.
PlannedShift* next_planned(std::vector<PlannedShift>& plan, double covered_to, double& imag) {
  PlannedShift* joining = nullptr;
  PlannedShift* lowest = nullptr;
  for (PlannedShift& s : plan) {
    if (s.used || !(s.imag + s.half_height > covered_to)) continue;
    if (s.imag - s.half_height <= covered_to) {
      if (!joining || s.imag + s.half_height > joining->imag + joining->half_height) joining = &s;
    } else if (!lowest || s.imag < lowest->imag) {
      lowest = &s;
    }
  }
  PlannedShift* chosen = joining ? joining : lowest;
  if (!chosen) return nullptr;
  chosen->used = true;
  imag = std::min(chosen->imag, covered_to + 0.9 * chosen->half_height);
  return chosen;
}

// The band of one matrix (all of A, or one diagonal block of it) covered
// by discs, starting from `plan`.
BandEigenResult cover_band(const Eigen::SparseMatrix<double>& A, const BandCoverOptions& o,
                           const std::vector<ShiftDisc>& plan) {
  const double centre = 0.5 * (o.min_real_part_per_s + o.max_real_part_per_s);
  const double half_width = 0.5 * (o.max_real_part_per_s - o.min_real_part_per_s);
  const double top = 2.0 * std::numbers::pi * o.max_frequency_hz;
  const int n = int(A.rows());
  const double norm_A = std::max(A.norm(), std::numeric_limits<double>::min());
  ShiftedSparseLU lu(A);
  BandEigenResult result;
  std::vector<PlannedShift> planned = planned_shifts(plan, half_width);
  double covered_to = 0.0;            // [0, covered_to] of the band's height is covered
  double expected_half = half_width;  // guess of the next disc's h
  int k = o.eigenvalues_per_shift;
  Complex requested{centre, 0.0};
  bool again = false;  // the last disc was too narrow: the same shift, a larger k
  // Spans [lower, upper] of discs that reached the box's width but left a
  // gap below them (their eigenvalues are kept), ordered by lower end: once
  // the gap is filled, the band is covered to their top without solving
  // there again.
  std::vector<std::pair<double, double>> islands;
  while (covered_to < top && int(result.discs.size()) < o.max_shifts) {
    if (!again && !islands.empty()) {
      // Fill the gap below the lowest island: a shift at its middle, whose
      // disc joins both sides if it reaches half the gap's height.
      const double half_gap = 0.5 * (std::min(islands.front().first, top) - covered_to);
      requested = Complex(centre, covered_to + std::min(expected_half, half_gap));
    } else if (!again) {
      requested = Complex(centre, std::min(covered_to + expected_half, top));
      double imag = 0.0;
      if (const PlannedShift* s = next_planned(planned, covered_to, imag)) {
        requested = Complex(centre, std::min(imag, top));
        k = std::min(n - 2, s->k);
        expected_half = s->half_height;
      }
    }
    again = false;
    const Complex sigma = factorise_near(lu, requested, 1e-7 * top);
    // A converged prefix may end the solve early when its disc already
    // spans the box's width with a usable height (PrefixStop).
    PrefixStop prefix_stop;
    if (o.prefix_stop_after_restarts >= 0) {
      const double wanted_half = std::max(0.1 * half_width, o.prefix_stop_height_fraction * expected_half);
      const double wanted_radius = std::hypot(half_width, wanted_half) / (1.0 - kRimMargin);
      prefix_stop.after_restarts = o.prefix_stop_after_restarts;
      prefix_stop.max_theta_magnitude = 1.0 / wanted_radius;
      prefix_stop.min_gap = o.prefix_stop_min_gap;
    }
    RitzTolerance tolerance;
    tolerance.inside = o.tolerance;
    tolerance.outside = o.outside_box_tolerance;
    tolerance.sigma = sigma;
    tolerance.min_real = o.min_real_part_per_s;
    tolerance.max_real = o.max_real_part_per_s;
    tolerance.max_imag = top;
    NearestEigenpairs found = nearest_eigenpairs(A, norm_A, lu, sigma, k, tolerance, prefix_stop);
    const double radius = found.disc.radius;
    // Keep what lies in this disc and in no earlier one.
    for (EigenPair& p : found.pairs) {
      if (!(std::abs(p.value - sigma) < radius)) continue;
      bool seen = false;
      for (const ShiftDisc& d : result.discs)
        if (std::abs(p.value - d.shift) < d.radius) seen = true;
      if (!seen) result.pairs.push_back(std::move(p));
    }
    result.discs.push_back(found.disc);
    const double h = radius > half_width ? std::sqrt(radius * radius - half_width * half_width) : 0.0;
    if (h < 0.1 * half_width) {
      // Too few eigenvalues to span the box's width here: ask for more.
      if (k >= n - 2) break;  // all there are: nothing more to find
      k = std::min(n - 2, 2 * k);
      again = true;
      continue;
    }
    // Back towards the base request: the density of eigenvalues changes
    // along the band (clusters near the hunting and body modes).
    k = std::max(o.eigenvalues_per_shift, k / 2);
    if (sigma.imag() - h <= covered_to) {
      covered_to = std::max(covered_to, sigma.imag() + h);
      expected_half = h;
      // Islands the covered part now reaches join it (lowest first).
      while (!islands.empty() && islands.front().first <= covered_to) {
        covered_to = std::max(covered_to, islands.front().second);
        islands.erase(islands.begin());
      }
    } else {
      const std::pair<double, double> span{sigma.imag() - h, sigma.imag() + h};
      islands.insert(std::upper_bound(islands.begin(), islands.end(), span), span);
      expected_half = 0.5 * h;  // a gap below: the next shift nearer the covered part
    }
  }
  result.covered = covered_to >= top;
  std::sort(result.pairs.begin(), result.pairs.end(), [](const EigenPair& a, const EigenPair& b) {
    if (a.value.real() != b.value.real()) return a.value.real() > b.value.real();
    return a.value.imag() > b.value.imag();
  });
  return result;
}

// The diagonal blocks the band is covered on: A's decoupled blocks, those
// under kMinBlockStates merged (a Krylov solve needs k + 2 states and a
// tiny block is cheaper inside a larger one), the merged rest joined to the
// first block if it is still small.
constexpr size_t kMinBlockStates = 64;

std::vector<std::vector<int>> band_blocks(const Eigen::SparseMatrix<double>& A) {
  std::vector<std::vector<int>> blocks, small;
  std::vector<int> rest;
  for (std::vector<int>& b : decoupled_blocks(A))
    (b.size() < kMinBlockStates ? small : blocks).push_back(std::move(b));
  for (const std::vector<int>& b : small) rest.insert(rest.end(), b.begin(), b.end());
  if (!rest.empty()) {
    if (rest.size() < kMinBlockStates && !blocks.empty()) {
      blocks.front().insert(blocks.front().end(), rest.begin(), rest.end());
    } else {
      blocks.push_back(std::move(rest));
    }
  }
  for (std::vector<int>& b : blocks) std::sort(b.begin(), b.end());
  std::sort(blocks.begin(), blocks.end());  // by smallest index: the same order at every speed
  return blocks;
}

// A(block, block) as a sparse matrix of the block's size.
Eigen::SparseMatrix<double> diagonal_block(const Eigen::SparseMatrix<double>& A,
                                           const std::vector<int>& block) {
  std::vector<int> local(size_t(A.rows()), -1);
  for (size_t k = 0; k < block.size(); ++k) local[size_t(block[k])] = int(k);
  std::vector<Eigen::Triplet<double>> entries;
  for (int j : block)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it)
      if (local[size_t(it.row())] >= 0) entries.emplace_back(local[size_t(it.row())], local[size_t(j)], it.value());
  Eigen::SparseMatrix<double> B(Eigen::Index(block.size()), Eigen::Index(block.size()));
  B.setFromTriplets(entries.begin(), entries.end());
  return B;
}

}  // namespace

BandEigenResult eigen_sparse_band(const Eigen::SparseMatrix<double>& A,
                                  const BandCoverOptions& o, const std::vector<ShiftDisc>& plan) {
  validate(A, o);
  const std::vector<std::vector<int>> blocks = band_blocks(A);
  // Each block starts from the plan's discs of the same block (a disc of a
  // block that no longer exists is dropped: guesses only).
  auto plan_of = [&plan](int b) {
    std::vector<ShiftDisc> block_plan;
    for (const ShiftDisc& d : plan)
      if (d.block == b) block_plan.push_back(d);
    return block_plan;
  };
  if (blocks.size() == 1) return cover_band(A, o, plan_of(0));
  const double norm_A = std::max(A.norm(), std::numeric_limits<double>::min());
  BandEigenResult result;
  result.covered = true;
  result.blocks = int(blocks.size());
  for (size_t b = 0; b < blocks.size(); ++b) {
    // max_shifts bounds the whole solve: each block gets what is left.
    BandCoverOptions block_options = o;
    block_options.max_shifts = o.max_shifts - int(result.discs.size());
    if (block_options.max_shifts < 1) {
      result.covered = false;
      break;
    }
    BandEigenResult part = cover_band(diagonal_block(A, blocks[b]), block_options, plan_of(int(b)));
    result.covered = result.covered && part.covered;
    for (ShiftDisc& d : part.discs) {
      d.block = int(b);
      result.discs.push_back(d);
    }
    // The block's eigenvectors on all of A's states (zeros elsewhere), the
    // residual against the whole A (the entries between blocks are
    // round-off: decoupled_blocks).
    for (EigenPair& p : part.pairs) {
      Eigen::VectorXcd v = Eigen::VectorXcd::Zero(A.rows());
      for (size_t k = 0; k < blocks[b].size(); ++k) v(blocks[b][k]) = p.vector(Eigen::Index(k));
      const Eigen::VectorXd v_re = v.real(), v_im = v.imag();
      const Eigen::VectorXcd Av =
          (A * v_re).cast<Complex>() + Complex(0.0, 1.0) * (A * v_im).cast<Complex>();
      p.residual = (Av - p.value * v).norm() / (norm_A * v.norm());
      p.vector = std::move(v);
      result.pairs.push_back(std::move(p));
    }
  }
  std::sort(result.pairs.begin(), result.pairs.end(), [](const EigenPair& a, const EigenPair& b) {
    if (a.value.real() != b.value.real()) return a.value.real() > b.value.real();
    return a.value.imag() > b.value.imag();
  });
  return result;
}

NearestEigenpairs eigen_sparse_nearest(const Eigen::SparseMatrix<double>& A,
                                       std::complex<double> shift, int k, double tolerance) {
  validate_matrix(A);
  if (k < 1 || k > A.rows() - 2 || !std::isfinite(shift.real()) || !std::isfinite(shift.imag()))
    throw std::invalid_argument("eigen_sparse_nearest: expected 1 <= k <= n - 2 = " +
                                std::to_string(A.rows() - 2) + " and a finite shift, got k = " +
                                std::to_string(k));
  const double norm_A = std::max(A.norm(), std::numeric_limits<double>::min());
  ShiftedSparseLU lu(A);
  const Complex sigma = factorise_near(lu, shift, 1e-7 * std::max(1.0, std::abs(shift)));
  RitzTolerance uniform;
  uniform.inside = uniform.outside = tolerance;
  return nearest_eigenpairs(A, norm_A, lu, sigma, k, uniform);
}

}  // namespace railstab
