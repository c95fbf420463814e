#include "eigen/band_eigen.hpp"
#include "eigen/eigenvector_phase.hpp"

#include <arpack/arpack.hpp>

#include <Eigen/SparseLU>

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <numbers>
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

// ARPACK keeps its iteration state in Fortran SAVE variables.
std::mutex& znaupd_mutex() {
  static std::mutex m;
  return m;
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

// The k eigenpairs of A nearest sigma (complex Arnoldi on (A - sigma I)^-1,
// largest magnitude), eigenvalues as Rayleigh quotients of the Ritz vectors.
// The disc's radius: the farthest of the k (less kRimMargin), 0 when ARPACK
// stopped before all k converged (then the pairs returned are not proven to
// be the nearest). Pairs nearest first.
NearestEigenpairs nearest_eigenpairs(const Eigen::SparseMatrix<double>& A, double norm_A,
                                     ShiftedSparseLU& lu, Complex sigma, int k,
                                     double tolerance) {
  NearestEigenpairs out;
  ShiftDisc& work = out.disc;
  work.shift = sigma;
  work.eigenvalues = k;
  const a_int n = a_int(A.rows());
  const a_int nev = std::min<a_int>(k, n - 2);
  // Basis 3k + 1: the cars' nearly equal modes come in tight clusters, which
  // a wider basis separates in fewer restarts (16-car train: 0.8x the time
  // of 2k + 1).
  const a_int ncv = std::min<a_int>(n, std::max<a_int>(3 * nev + 1, 20));
  const size_t un = static_cast<size_t>(n), uncv = static_cast<size_t>(ncv);
  std::vector<Complex> resid(un), v(un * uncv), workd(3 * un), workl(3 * uncv * uncv + 5 * uncv);
  std::vector<double> rwork(uncv);
  // Fixed start vector: results do not depend on earlier solves.
  std::mt19937_64 generator(20261130);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (Complex& r : resid) r = Complex(uniform(generator), uniform(generator));
  a_int iparam[11] = {}, ipntr[14] = {};
  iparam[0] = 1;     // exact shifts
  iparam[2] = 3000;  // restarts
  iparam[6] = 1;     // OP given by the caller: (A - sigma I)^-1
  a_int ido = 0, info = 1;
  const size_t unev = static_cast<size_t>(nev);
  std::vector<Complex> values(unev + 1), vectors(un * (unev + 1)), workev(2 * uncv);
  std::vector<a_int> select(uncv);
  {
    std::lock_guard<std::mutex> lock(znaupd_mutex());
    while (true) {
      arpack::naupd(ido, arpack::bmat::identity, n, arpack::which::largest_magnitude, nev,
                    tolerance, resid.data(), ncv, v.data(), n, iparam, ipntr, workd.data(),
                    workl.data(), a_int(workl.size()), rwork.data(), info);
      if (ido == 99) break;
      if (ido != -1 && ido != 1)
        throw std::runtime_error("eigen_sparse_band: unexpected ARPACK request ido = " +
                                 std::to_string(ido));
      lu.solve(workd.data() + ipntr[0] - 1, workd.data() + ipntr[1] - 1);
    }
    if (info != 0 && info != 1)
      throw std::runtime_error("eigen_sparse_band: ARPACK znaupd failed, info = " +
                               std::to_string(info));
    a_int info_e = 0;
    arpack::neupd(1, arpack::howmny::ritz_vectors, select.data(), values.data(), vectors.data(), n,
                  Complex(0.0, 0.0), workev.data(), arpack::bmat::identity, n,
                  arpack::which::largest_magnitude, nev, tolerance, resid.data(), ncv, v.data(),
                  n, iparam, ipntr, workd.data(), workl.data(), a_int(workl.size()), rwork.data(),
                  info_e);
    if (info_e != 0)
      throw std::runtime_error("eigen_sparse_band: ARPACK zneupd failed, info = " +
                               std::to_string(info_e));
  }
  work.restarts = int(iparam[2]);
  work.operator_applications = int(iparam[8]);
  const int converged = int(std::min<a_int>(iparam[4], nev));
  const bool all_converged = converged >= nev;
  std::vector<EigenPair>& pairs = out.pairs;
  for (int j = 0; j < converged; ++j) {
    const Eigen::Map<const Eigen::VectorXcd> z(vectors.data() + static_cast<size_t>(j) * un, n);
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

}  // namespace

BandEigenResult eigen_sparse_band(const Eigen::SparseMatrix<double>& A,
                                  const BandCoverOptions& o) {
  validate(A, o);
  const double centre = 0.5 * (o.min_real_part_per_s + o.max_real_part_per_s);
  const double half_width = 0.5 * (o.max_real_part_per_s - o.min_real_part_per_s);
  const double top = 2.0 * std::numbers::pi * o.max_frequency_hz;
  const int n = int(A.rows());
  const double norm_A = std::max(A.norm(), std::numeric_limits<double>::min());
  ShiftedSparseLU lu(A);
  BandEigenResult result;
  double covered_to = 0.0;            // [0, covered_to] of the band's height is covered
  double expected_half = half_width;  // guess of the next disc's h
  int k = o.eigenvalues_per_shift;
  while (covered_to < top && int(result.discs.size()) < o.max_shifts) {
    const Complex sigma = factorise_near(
        lu, Complex(centre, std::min(covered_to + expected_half, top)), 1e-7 * top);
    NearestEigenpairs found = nearest_eigenpairs(A, norm_A, lu, sigma, k, o.tolerance);
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
      continue;
    }
    // Back towards the base request: the density of eigenvalues changes
    // along the band (clusters near the hunting and body modes).
    k = std::max(o.eigenvalues_per_shift, k / 2);
    if (sigma.imag() - h <= covered_to) {
      covered_to = std::max(covered_to, sigma.imag() + h);
      expected_half = h;
    } else {
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
  return nearest_eigenpairs(A, norm_A, lu, sigma, k, tolerance);
}

}  // namespace railstab
