#include <railstab/eigen/eigen_analysis.hpp>
#include <railstab/eigen/balance.hpp>
#include <railstab/eigen/decoupled_blocks.hpp>
#include <railstab/eigen/eigenvector_phase.hpp>
#include <railstab/linalg/dense_decompositions.hpp>

#include <arpack/arpack.hpp>

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

// ---------------------------------------------------------------------------
// Eigenpair bookkeeping shared by both solvers
// ---------------------------------------------------------------------------

}  // namespace

// The first index of the largest |v_i|, the one v.cwiseAbs().maxCoeff()
// finds, without a modulus (hypot, ~20 ns) per entry: the squared moduli
// re^2 + im^2 are within 3 ulps of |v_i|^2, so an entry whose squared modulus
// is below (1 - 1e-12) times the largest has a smaller modulus for certain;
// only the others are compared by std::abs. Outside the range where the
// squares neither underflow nor overflow, all are compared by std::abs.
// (Not std::norm: libstdc++ computes it as std::abs squared.)
namespace {
Eigen::Index first_largest_modulus(const Eigen::VectorXcd& v) {
  const double largest_square = v.cwiseAbs2().maxCoeff();
  Eigen::Index peak = 0;
  if (!(largest_square > 1e-280 && largest_square < 1e280)) {
    v.cwiseAbs().maxCoeff(&peak);
    return peak;
  }
  const double threshold = (1.0 - 1e-12) * largest_square;
  double peak_modulus = -1.0;
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    const double square = v(i).real() * v(i).real() + v(i).imag() * v(i).imag();
    if (!(square >= threshold)) continue;
    const double modulus = std::abs(v(i));
    if (modulus > peak_modulus) {
      peak_modulus = modulus;
      peak = i;
    }
  }
  return peak;
}
}  // namespace

// Unit 2-norm, and the phase that makes the largest-magnitude component real
// positive: eigenvectors are only defined up to a complex scalar, and a fixed
// convention lets callers compare or plot them without further work.
Eigen::VectorXcd with_canonical_phase(Eigen::VectorXcd v) {
  const double norm = v.norm();
  if (norm == 0.0) return v;
  const Eigen::Index peak = first_largest_modulus(v);
  const Complex unit_phase = v(peak) / std::abs(v(peak));
  return v * (std::conj(unit_phase) / norm);
}

namespace {

double relative_residual(const Eigen::MatrixXd& A, double norm_A, Complex lambda,
                         const Eigen::VectorXcd& v) {
  const double scale = norm_A * v.norm();
  if (scale == 0.0) return 0.0;
  // A v for real A without forming a complex copy of A.
  const Eigen::VectorXd Av_re = A * v.real(), Av_im = A * v.imag();
  const Eigen::VectorXcd Av = Av_re.cast<Complex>() + Complex(0.0, 1.0) * Av_im.cast<Complex>();
  return (Av - lambda * v).norm() / scale;
}

EigenPair make_eigenpair(const Eigen::MatrixXd& A, double norm_A, Complex lambda,
                         const Eigen::VectorXcd& raw_vector) {
  EigenPair pair{lambda, with_canonical_phase(raw_vector), 0.0};
  pair.residual = relative_residual(A, norm_A, lambda, pair.vector);
  return pair;
}

// Least stable first: that is the order a stability report reads in.
void sort_by_descending_real_part(std::vector<EigenPair>& pairs) {
  std::sort(pairs.begin(), pairs.end(), [](const EigenPair& a, const EigenPair& b) {
    if (a.value.real() != b.value.real()) return a.value.real() > b.value.real();
    return a.value.imag() > b.value.imag();
  });
}

void require_square_and_finite(const Eigen::MatrixXd& A, const char* who) {
  if (A.rows() != A.cols())
    throw std::invalid_argument(std::string(who) + ": matrix must be square, got " +
                                std::to_string(A.rows()) + " x " + std::to_string(A.cols()));
  if (A.size() == 0) throw std::invalid_argument(std::string(who) + ": matrix is empty");
  if (!A.allFinite())
    throw std::invalid_argument(std::string(who) + ": matrix has NaN or infinite entries");
}

// ---------------------------------------------------------------------------
// Shift-invert operator
// ---------------------------------------------------------------------------

// Which part of (A - sigma I)^-1 ARPACK iterates with, as dnaupd's mode
// number. For a real shift both modes are the plain inverse. For a complex
// shift sigma = a + ib both are real operators with the eigenvectors of A:
//  - real part (mode 3): (1/2)[(A - sigma I)^-1 + (A - conj(sigma) I)^-1],
//    eigenvalue (lambda - a) / ((lambda - sigma)(lambda - conj(sigma)));
//  - imaginary part (mode 4): b (A - sigma I)^-1 (A - conj(sigma) I)^-1,
//    eigenvalue b / ((lambda - sigma)(lambda - conj(sigma))).
// The real part vanishes at lambda = a: it is blind to eigenvalues of A near
// Re(sigma) on the real axis, the imaginary part has no such spot.
enum class OperatorPart { real = 3, imaginary = 4 };

// Magnitude of the eigenvalue of OP that an eigenvalue lambda of A becomes:
// ARPACK finds the largest ones, so this is the order it sees A's spectrum in.
double op_magnitude(Complex lambda, Complex sigma, OperatorPart part) {
  const double denominator = std::abs(lambda - sigma) * std::abs(lambda - std::conj(sigma));
  const double numerator =
      part == OperatorPart::real ? std::abs(lambda - sigma.real()) : std::abs(sigma.imag());
  return numerator / denominator;
}

// The real part's blind spot, Re(sigma) on the real axis, lies in the disc
// |lambda - sigma| <= radius.
bool disc_contains_blind_spot(Complex sigma, double radius) {
  return sigma.imag() != 0.0 && std::abs(sigma.imag()) <= radius;
}

// Smallest op_magnitude over the closed disc |lambda - sigma| <= radius.
// Inside the disc OP's eigenvalue function has its pole at sigma and no zero
// unless the disc reaches a = Re(sigma) (real part only), so by the minimum
// modulus principle the minimum lies on the circle; 4096 samples find it to
// well under the 1e-3 slack used by the caller.
double min_op_magnitude_in_disc(Complex sigma, double radius, OperatorPart part) {
  if (part == OperatorPart::real && disc_contains_blind_spot(sigma, radius)) return 0.0;
  constexpr int samples = 4096;
  double smallest = std::numeric_limits<double>::infinity();
  for (int j = 0; j < samples; ++j) {
    const Complex lambda = sigma + std::polar(radius, 2.0 * std::numbers::pi * j / samples);
    smallest = std::min(smallest, op_magnitude(lambda, sigma, part));
  }
  return smallest;
}

// OP x = Re or Im of (A - sigma I)^-1 x, the operator of dnaupd modes 3 / 4.
// This class is the only place that knows how (A - sigma I) is factorised:
// a sparse LU (e.g. Eigen::SparseLU<SparseMatrix<complex>>) can replace the
// dense one without touching the Arnoldi driver.
class ShiftInvertOperator {
 public:
  ShiftInvertOperator(const Eigen::MatrixXd& A, Complex sigma)
      : lu_(shifted(A, sigma)), rhs_(A.rows()) {
    // A (near-)singular A - sigma I means sigma sits on an eigenvalue: the
    // operator is meaningless and the solves would return garbage silently.
    if (numerically_singular())
      throw std::invalid_argument(
          "eigen_arpack_shift_invert: A - shift*I is numerically singular (the shift is an "
          "eigenvalue of A); move the shift slightly");
  }

  int size() const { return int(rhs_.size()); }

  void apply(OperatorPart part, const double* x, double* y) {
    rhs_ = Eigen::Map<const Eigen::VectorXd>(x, size()).cast<Complex>();
    const Eigen::VectorXcd solution = lu_.solve(rhs_);
    Eigen::Map<Eigen::VectorXd> out(y, size());
    if (part == OperatorPart::real)
      out = solution.real();
    else
      out = solution.imag();
  }

 private:
  // Both tests: Eigen's rcond() estimate misses an exactly zero pivot (it
  // reports a healthy value), and a tiny pivot ratio alone misses some
  // ill-conditioned but well-pivoted factors.
  bool numerically_singular() const {
    const double tiny = 64 * std::numeric_limits<double>::epsilon();
    const Eigen::VectorXd pivots = lu_.matrixLU().diagonal().cwiseAbs();
    return !(pivots.minCoeff() > tiny * pivots.maxCoeff()) || !(lu_.rcond() > tiny);
  }

  static Eigen::MatrixXcd shifted(const Eigen::MatrixXd& A, Complex sigma) {
    Eigen::MatrixXcd S = A.cast<Complex>();
    S.diagonal().array() -= sigma;
    return S;
  }

  Eigen::PartialPivLU<Eigen::MatrixXcd> lu_;
  Eigen::VectorXcd rhs_;
};

// ---------------------------------------------------------------------------
// ARPACK (dnaupd / dneupd) driver
// ---------------------------------------------------------------------------

std::string naupd_info_meaning(int info) {
  switch (info) {
    case 1: return "maximum number of iterations taken before all wanted Ritz values converged";
    case 3: return "no shifts could be applied during an implicit restart; increase NCV";
    case -1: return "N must be positive";
    case -2: return "NEV must be positive";
    case -3: return "NCV must satisfy NEV + 2 <= NCV <= N";
    case -4: return "the maximum number of Arnoldi update iterations must be positive";
    case -5: return "WHICH must be one of LM, SM, LR, SR, LI, SI";
    case -6: return "BMAT must be I or G";
    case -7: return "length of private work array WORKL is not sufficient";
    case -8: return "error return from LAPACK eigenvalue calculation";
    case -9: return "starting vector is zero";
    case -10: return "IPARAM(7) must be 1, 2, 3 or 4";
    case -11: return "IPARAM(7) = 1 and BMAT = G are incompatible";
    case -12: return "IPARAM(1) must be 0 or 1";
    case -9999: return "could not build an Arnoldi factorisation (invariant subspace too small)";
    default: return "unknown ARPACK dnaupd info code";
  }
}

std::string neupd_info_meaning(int info) {
  switch (info) {
    case 1: return "the Schur form could not be reordered by LAPACK dtrsen";
    case -1: return "N must be positive";
    case -2: return "NEV must be positive";
    case -3: return "NCV must satisfy NEV + 2 <= NCV <= N";
    case -5: return "WHICH must be one of LM, SM, LR, SR, LI, SI";
    case -6: return "BMAT must be I or G";
    case -7: return "length of private work array WORKL is not sufficient";
    case -8: return "error return from LAPACK dlahqr (real Schur form)";
    case -9: return "error return from LAPACK dtrevc (eigenvectors)";
    case -10: return "IPARAM(7) must be 1, 2, 3 or 4";
    case -11: return "IPARAM(7) = 1 and BMAT = G are incompatible";
    case -12: return "HOWMNY = S is not implemented";
    case -13: return "HOWMNY must be A or P when RVEC is true";
    case -14: return "dnaupd did not find any eigenvalues to sufficient accuracy";
    case -15: return "dneupd and dnaupd disagree on the number of converged Ritz values";
    default: return "unknown ARPACK dneupd info code";
  }
}

[[noreturn]] void throw_arpack_error(const char* routine, int info, const std::string& meaning,
                                     const std::string& detail = {}) {
  throw std::runtime_error(std::string("eigen_arpack_shift_invert: ARPACK ") + routine +
                           " failed, info = " + std::to_string(info) + " (" + meaning + ")" +
                           detail);
}

void validate_arpack_request(const Eigen::MatrixXd& A, const ArpackOptions& opt) {
  require_square_and_finite(A, "eigen_arpack_shift_invert");
  const int n = int(A.rows());
  // ARPACK needs NEV + 2 <= NCV <= N, hence at most n - 2 wanted values.
  if (opt.n_eigenvalues < 1 || opt.n_eigenvalues > n - 2)
    throw std::invalid_argument(
        "eigen_arpack_shift_invert: n_eigenvalues must be in [1, n - 2] = [1, " +
        std::to_string(n - 2) + "] for n = " + std::to_string(n) + ", got " +
        std::to_string(opt.n_eigenvalues) + " (use eigen_dense for all eigenvalues)");
  if (opt.max_iterations < 1)
    throw std::invalid_argument("eigen_arpack_shift_invert: max_iterations must be positive");
  if (!(opt.tolerance >= 0.0))
    throw std::invalid_argument(
        "eigen_arpack_shift_invert: tolerance must be >= 0 (0 = machine precision)");
  if (!std::isfinite(opt.shift.real()) || !std::isfinite(opt.shift.imag()))
    throw std::invalid_argument("eigen_arpack_shift_invert: shift must be finite");
}

struct ArnoldiSizes {
  int nev;  // Ritz values of OP asked from ARPACK
  int ncv;  // Arnoldi basis size
};

// How many eigenvalues of OP to ask for first. With a complex shift every
// eigenvalue of A near sigma comes with its conjugate (near conj(sigma)) as a
// conjugate pair of OP, so twice as many; plus a margin because OP's
// magnitude order is only roughly the distance order to sigma. Too few is
// detected afterwards (see nearest_are_certain) and the request grown.
int initial_ritz_count(int n, int wanted, Complex sigma) {
  const bool complex_shift = sigma.imag() != 0.0;
  const int margin = 4 + wanted / 2;
  return std::min(n - 2, (complex_shift ? 2 * wanted : wanted) + margin);
}

// ARPACK wants NEV + 2 <= NCV <= N; about twice NEV converges fast.
ArnoldiSizes arnoldi_sizes(int n, int nev) {
  return {nev, std::min(n, std::max(2 * nev + 1, 20))};
}

// The arrays dnaupd and dneupd share; they must not change between the calls.
struct ArnoldiWorkspace {
  ArnoldiWorkspace(int n, ArnoldiSizes s)
      : n(n),
        sizes(s),
        resid(n),
        basis(std::size_t(n) * s.ncv),
        workd(3 * std::size_t(n)),
        workl(3 * std::size_t(s.ncv) * s.ncv + 6 * std::size_t(s.ncv)) {}

  int n;
  ArnoldiSizes sizes;
  std::vector<double> resid;
  std::vector<double> basis;  // V, n x ncv, column major
  std::vector<double> workd;
  std::vector<double> workl;
  a_int iparam[11] = {};
  a_int ipntr[14] = {};
};

// A fixed pseudo-random start vector instead of ARPACK's own: ARPACK's seed
// is Fortran SAVE state that advances from call to call, which would make a
// speed sweep depend on how many solves ran before.
void set_reproducible_start_vector(std::vector<double>& resid) {
  std::mt19937_64 generator(20240611);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (double& r : resid) r = uniform(generator);
}

constexpr arpack::which kLargestMagnitude = arpack::which::largest_magnitude;

// Implicitly restarted Arnoldi on OP until the wanted Ritz values converge.
void run_arnoldi(ShiftInvertOperator& op, OperatorPart part, ArnoldiWorkspace& ws,
                 const ArpackOptions& opt) {
  set_reproducible_start_vector(ws.resid);
  ws.iparam[0] = 1;                   // exact shifts
  ws.iparam[2] = opt.max_iterations;  // restart limit
  ws.iparam[6] = int(part);           // shift-invert mode 3 or 4
  a_int ido = 0;
  a_int info = 1;  // 1: use the start vector in resid
  while (true) {
    arpack::naupd(ido, arpack::bmat::identity, ws.n, kLargestMagnitude, ws.sizes.nev,
                  opt.tolerance, ws.resid.data(), ws.sizes.ncv, ws.basis.data(), ws.n,
                  ws.iparam, ws.ipntr, ws.workd.data(), ws.workl.data(), a_int(ws.workl.size()),
                  info);
    if (ido == 99) break;
    const double* x = ws.workd.data() + ws.ipntr[0] - 1;
    double* y = ws.workd.data() + ws.ipntr[1] - 1;
    if (ido == -1 || ido == 1) {
      op.apply(part, x, y);
    } else if (ido == 2) {
      std::copy(x, x + ws.n, y);  // B = I
    } else {
      throw std::runtime_error("eigen_arpack_shift_invert: unexpected ARPACK request ido = " +
                               std::to_string(ido));
    }
  }
  if (info != 0)
    throw_arpack_error("dnaupd", info, naupd_info_meaning(info),
                       "; converged " + std::to_string(ws.iparam[4]) + " of " +
                       std::to_string(ws.sizes.nev) + " Ritz values after " +
                       std::to_string(ws.iparam[2]) + " restarts");
}

// Orthonormal basis (n x nconv) of the converged invariant subspace of OP,
// i.e. ARPACK's Schur vectors (dneupd with HOWMNY = 'P').
Eigen::MatrixXd converged_schur_basis(ArnoldiWorkspace& ws, const ArpackOptions& opt) {
  const int nev = ws.sizes.nev;
  const int ncv = ws.sizes.ncv;
  std::vector<a_int> select(ncv);
  std::vector<double> ritz_re(nev + 1), ritz_im(nev + 1), workev(3 * std::size_t(ncv));
  std::vector<double> schur(std::size_t(ws.n) * (nev + 1));
  a_int info = 0;
  arpack::neupd(1, arpack::howmny::schur_vectors, select.data(), ritz_re.data(), ritz_im.data(),
                schur.data(), ws.n, opt.shift.real(), opt.shift.imag(), workev.data(),
                arpack::bmat::identity, ws.n, kLargestMagnitude, nev, opt.tolerance,
                ws.resid.data(), ncv, ws.basis.data(), ws.n, ws.iparam, ws.ipntr,
                ws.workd.data(), ws.workl.data(), a_int(ws.workl.size()), info);
  if (info != 0) throw_arpack_error("dneupd", info, neupd_info_meaning(info));
  const int converged = std::min<int>(ws.iparam[4], nev + 1);
  return Eigen::Map<Eigen::MatrixXd>(schur.data(), ws.n, converged);
}

// Eigenpairs of A from an invariant subspace of OP. OP is a rational function
// of A, so the converged invariant subspace of OP is invariant under A too,
// and the projected matrix Q^T A Q has exactly the corresponding eigenvalues
// of A (Rayleigh-Ritz: the block form of the Rayleigh quotient v^H A v / v^H v
// that ARPACK's remark 3 asks for when sigma is complex). Working on the
// subspace rather than on ARPACK's individual Ritz vectors matters: an
// eigenvalue lambda of A on the circle |lambda - Re sigma| = |Im sigma|
// (which passes through sigma) gives OP eigenvalues for lambda and
// conj(lambda) that coincide, so the individual Ritz vectors of OP may be
// arbitrary mixtures of the two eigenvectors, while the subspace is exact.
std::vector<EigenPair> rayleigh_ritz_pairs(const Eigen::MatrixXd& A, double norm_A,
                                           const Eigen::MatrixXd& Q) {
  const Eigen::MatrixXd AQ = A * Q;
  const Eigen::MatrixXd projected = Q.transpose() * AQ;
  Eigen::EigenSolver<Eigen::MatrixXd> small(projected, true);
  if (small.info() != Eigen::Success)
    throw std::runtime_error(
        "eigen_arpack_shift_invert: eigen-decomposition of the projected matrix failed");
  const Eigen::MatrixXcd vectors = Q.cast<Complex>() * small.eigenvectors();
  std::vector<EigenPair> pairs;
  pairs.reserve(std::size_t(projected.rows()));
  for (Eigen::Index j = 0; j < projected.rows(); ++j)
    pairs.push_back(make_eigenpair(A, norm_A, small.eigenvalues()(j), vectors.col(j)));
  return pairs;
}

// The `wanted` pairs nearest sigma, nearest first. If the last one kept has
// its conjugate partner at the same distance (real shift), the partner is
// kept too: a conjugate pair is one physical mode.
std::vector<EigenPair> nearest_to_shift(std::vector<EigenPair> pairs, Complex sigma,
                                        int wanted) {
  std::sort(pairs.begin(), pairs.end(), [sigma](const EigenPair& a, const EigenPair& b) {
    const double da = std::abs(a.value - sigma), db = std::abs(b.value - sigma);
    if (da != db) return da < db;
    return a.value.imag() > b.value.imag();
  });
  if (int(pairs.size()) <= wanted) return pairs;
  const EigenPair& last = pairs[std::size_t(wanted) - 1];
  const EigenPair& next = pairs[std::size_t(wanted)];
  const double tie = 1e-10 * std::max(1.0, std::abs(last.value));
  const bool next_is_partner =
      std::abs(last.value - std::conj(last.value)) > tie &&
      std::abs(next.value - std::conj(last.value)) <= tie &&
      std::abs(std::abs(next.value - sigma) - std::abs(last.value - sigma)) <= tie;
  const bool partner_already_kept =
      wanted >= 2 &&
      std::abs(pairs[std::size_t(wanted) - 2].value - std::conj(last.value)) <= tie;
  pairs.resize(std::size_t(wanted) + (next_is_partner && !partner_already_kept ? 1 : 0));
  return pairs;
}

// ARPACK keeps its iteration state in Fortran SAVE variables: two solves on
// different threads would corrupt each other.
std::mutex& arpack_mutex() {
  static std::mutex m;
  return m;
}

// One ARPACK run asking for nev Ritz values of OP; returns the eigenpairs of A
// in the converged invariant subspace.
std::vector<EigenPair> shift_invert_eigenpairs(const Eigen::MatrixXd& A, double norm_A,
                                               ShiftInvertOperator& op, OperatorPart part,
                                               int nev, const ArpackOptions& opt) {
  ArnoldiWorkspace workspace(op.size(), arnoldi_sizes(op.size(), nev));
  Eigen::MatrixXd schur_basis;
  {
    std::lock_guard<std::mutex> lock(arpack_mutex());
    run_arnoldi(op, part, workspace, opt);
    schur_basis = converged_schur_basis(workspace, opt);
  }
  return rayleigh_ritz_pairs(A, norm_A, schur_basis);
}

// Proof that no unseen eigenvalue is nearer sigma than the farthest one kept.
// ARPACK returns the eigenvalues of A whose OP eigenvalues are largest, so an
// unseen one has op_magnitude at most that of the weakest one seen; if every
// point of the disc reaching the farthest kept eigenvalue has a larger
// op_magnitude, no unseen eigenvalue lies in it. Needed because with a
// complex shift the magnitude order and the distance order differ a lot once
// the disc is not small against Im(sigma), and no fixed margin covers that.
bool nearest_are_certain(const std::vector<EigenPair>& converged,
                         const std::vector<EigenPair>& nearest, Complex sigma,
                         OperatorPart part) {
  double weakest_seen = std::numeric_limits<double>::infinity();
  for (const EigenPair& p : converged)
    weakest_seen = std::min(weakest_seen, op_magnitude(p.value, sigma, part));
  const double radius = std::abs(nearest.back().value - sigma);
  return min_op_magnitude_in_disc(sigma, radius, part) * (1.0 - 1e-3) > weakest_seen;
}

// ---------------------------------------------------------------------------
// Mode tracking
// ---------------------------------------------------------------------------

bool is_upper_oscillatory(const EigenPair& p) {
  return mode_info(p.value).oscillatory && p.value.imag() > 0.0;
}

bool is_lower_oscillatory(const EigenPair& p) {
  return mode_info(p.value).oscillatory && p.value.imag() < 0.0;
}

std::vector<int> indices_where(const std::vector<EigenPair>& pairs,
                               bool (*predicate)(const EigenPair&)) {
  std::vector<int> idx;
  for (std::size_t i = 0; i < pairs.size(); ++i)
    if (predicate(pairs[i])) idx.push_back(int(i));
  return idx;
}

// Minimum-cost assignment of rows to columns (rows <= columns), Hungarian
// method with row/column potentials and shortest augmenting paths, O(r^2 c).
// Returns the column of every row.
std::vector<int> min_cost_assignment_rows_le_cols(const Eigen::MatrixXd& cost) {
  const int rows = int(cost.rows()), cols = int(cost.cols());
  const double inf = std::numeric_limits<double>::infinity();
  // Index 0 is a virtual column/row that starts each augmenting path.
  std::vector<double> row_potential(rows + 1, 0.0), col_potential(cols + 1, 0.0);
  std::vector<int> row_of_col(cols + 1, 0);  // 1-based row, 0 = free
  std::vector<int> previous_col(cols + 1, 0);
  for (int row = 1; row <= rows; ++row) {
    row_of_col[0] = row;
    int col = 0;
    std::vector<double> slack(cols + 1, inf);
    std::vector<bool> visited(cols + 1, false);
    // Grow the alternating tree until it reaches a free column.
    do {
      visited[col] = true;
      const int tree_row = row_of_col[col];
      double step = inf;
      int next_col = 0;
      for (int c = 1; c <= cols; ++c) {
        if (visited[c]) continue;
        const double reduced =
            cost(tree_row - 1, c - 1) - row_potential[tree_row] - col_potential[c];
        if (reduced < slack[c]) {
          slack[c] = reduced;
          previous_col[c] = col;
        }
        if (slack[c] < step) {
          step = slack[c];
          next_col = c;
        }
      }
      for (int c = 0; c <= cols; ++c) {
        if (visited[c]) {
          row_potential[row_of_col[c]] += step;
          col_potential[c] -= step;
        } else {
          slack[c] -= step;
        }
      }
      col = next_col;
    } while (row_of_col[col] != 0);
    // Flip the matched/unmatched edges along the path back to the root.
    do {
      const int back = previous_col[col];
      row_of_col[col] = row_of_col[back];
      col = back;
    } while (col != 0);
  }
  std::vector<int> col_of_row(rows, -1);
  for (int c = 1; c <= cols; ++c)
    if (row_of_col[c] != 0) col_of_row[row_of_col[c] - 1] = c - 1;
  return col_of_row;
}

// Row -> column maximising the summed weight; -1 for rows left over when
// there are more rows than columns.
std::vector<int> max_weight_assignment(const Eigen::MatrixXd& weight) {
  if (weight.rows() == 0 || weight.cols() == 0) return std::vector<int>(weight.rows(), -1);
  if (weight.rows() <= weight.cols()) return min_cost_assignment_rows_le_cols(-weight);
  const std::vector<int> row_of_col = min_cost_assignment_rows_le_cols(-weight.transpose());
  std::vector<int> col_of_row(weight.rows(), -1);
  for (std::size_t c = 0; c < row_of_col.size(); ++c) col_of_row[row_of_col[c]] = int(c);
  return col_of_row;
}

// Index in `candidates` of the pair whose eigenvalue is nearest `value`.
int nearest_value(const std::vector<EigenPair>& pairs, const std::vector<int>& candidates,
                  Complex value) {
  int best = -1;
  double best_distance = std::numeric_limits<double>::infinity();
  for (int i : candidates) {
    const double d = std::abs(pairs[std::size_t(i)].value - value);
    if (d < best_distance) {
      best_distance = d;
      best = i;
    }
  }
  return best;
}

}  // namespace

// ---------------------------------------------------------------------------
// Public functions
// ---------------------------------------------------------------------------

namespace {

// The eigenpairs of one diagonal block B(block, block) of the balanced
// matrix B = D^-1 A D (all of B when `block` holds every state), as
// eigenpairs of A: vectors D v with zeros outside the block, residuals
// against the whole A.
void append_block_eigenpairs(const Eigen::MatrixXd& A, double norm_A, const BalancedMatrix& balanced,
                             const std::vector<int>& block, std::vector<EigenPair>& pairs) {
  const bool whole = block.size() == size_t(A.rows());
  const Eigen::MatrixXd part = whole ? Eigen::MatrixXd() : Eigen::MatrixXd(balanced.matrix(block, block));
  Eigen::EigenSolver<Eigen::MatrixXd> solver(whole ? balanced.matrix : part, true);
  if (solver.info() != Eigen::Success)
    throw std::runtime_error("eigen_dense: Eigen::EigenSolver did not converge");
  // EigenSolver::eigenvectors() assembles and normalises the whole complex
  // matrix on every call: once here, not once per column (that made the
  // post-processing O(n^3) per column and most of the solve's cost).
  const Eigen::VectorXd scaling = whole ? balanced.scaling : Eigen::VectorXd(balanced.scaling(block));
  const Eigen::MatrixXcd block_vectors = scaling.cast<Complex>().asDiagonal() * solver.eigenvectors();
  const Eigen::VectorXcd& values = solver.eigenvalues();
  // The vectors on all of A's states (zeros outside the block).
  Eigen::MatrixXcd embedded;
  if (!whole) {
    embedded = Eigen::MatrixXcd::Zero(A.rows(), block_vectors.cols());
    embedded(block, Eigen::all) = block_vectors;
  }
  const Eigen::MatrixXcd& vectors = whole ? block_vectors : embedded;
  // A V for all columns at once (two real matrix products: a fraction of
  // the time of one matrix-vector product per column; for a block only A's
  // block columns, the vectors being zero elsewhere); each residual
  // ||A v - lambda v|| / (||A|| ||v||) is then formed from its column (on
  // the raw vector: the quotient does not depend on v's scale or phase).
  const Eigen::MatrixXd V_re = vectors.real(), V_im = vectors.imag();
  Eigen::MatrixXd AV_re, AV_im;
  if (whole) {
    AV_re = A * V_re;
    AV_im = A * V_im;
  } else {
    const Eigen::MatrixXd A_block_columns = A(Eigen::all, block);
    AV_re = A_block_columns * block_vectors.real();
    AV_im = A_block_columns * block_vectors.imag();
  }
  auto residual = [&](Eigen::Index j) {
    const double scale = norm_A * vectors.col(j).norm();
    if (scale == 0.0) return 0.0;
    const Complex lambda = values(j);
    // Re and Im of A v - lambda v, lambda v = (l_r v_r - l_i v_i) + i (l_r v_i + l_i v_r).
    const double squared =
        (AV_re.col(j) - lambda.real() * V_re.col(j) + lambda.imag() * V_im.col(j)).squaredNorm() +
        (AV_im.col(j) - lambda.real() * V_im.col(j) - lambda.imag() * V_re.col(j)).squaredNorm();
    return std::sqrt(squared) / scale;
  };
  const Eigen::Index m = values.size();
  for (Eigen::Index j = 0; j < m; ++j) {
    pairs.push_back(EigenPair{values(j), with_canonical_phase(vectors.col(j)), residual(j)});
    // EigenSolver stores a complex pair as columns j, j+1 with value and
    // vector of j+1 the exact conjugates of j's. For real A every step of
    // the phasing maps conjugate input to conjugate output exactly, the
    // residual is the same number
    // (moduli, norms and the peak are the same, products and sums are
    // negated in their imaginary part only; IEEE rounding is symmetric), so
    // the partner is the conjugate of j's pair, bit for bit, at half the
    // cost (tests/eigen/test_eigen_analysis.cpp checks it against the
    // column-by-column result).
    if (j + 1 < m && values(j).imag() != 0.0 && values(j + 1) == std::conj(values(j)) &&
        vectors.col(j + 1) == vectors.col(j).conjugate()) {
      const EigenPair& first = pairs.back();
      pairs.push_back(EigenPair{std::conj(first.value), first.vector.conjugate(), first.residual});
      ++j;
    }
  }
}

}  // namespace

std::vector<EigenPair> eigen_dense(const Eigen::MatrixXd& A) {
  require_square_and_finite(A, "eigen_dense");
  // QR on the balanced matrix D^-1 A D (eigen/balance.hpp: same
  // eigenvalues, backward error against a far smaller norm); A's
  // eigenvectors are D times B's. Where B decouples into diagonal blocks
  // (eigen/decoupled_blocks.hpp: a symmetric vehicle on tangent track,
  // lateral apart from vertical), QR on each block.
  const BalancedMatrix balanced = balance(A);
  const double norm_A = A.norm();
  std::vector<EigenPair> pairs;
  pairs.reserve(std::size_t(A.rows()));
  for (const std::vector<int>& block : decoupled_blocks(balanced.matrix))
    append_block_eigenpairs(A, norm_A, balanced, block, pairs);
  sort_by_descending_real_part(pairs);
  return pairs;
}

std::vector<EigenPair> eigen_arpack_shift_invert(const Eigen::MatrixXd& A,
                                                 const ArpackOptions& opt) {
  validate_arpack_request(A, opt);
  const int n = int(A.rows());
  ShiftInvertOperator op(A, opt.shift);
  const double norm_A = A.norm();
  // dnaupd mode 4 (imaginary part of the shifted inverse) first: measured
  // 1.3-2x faster than mode 3 with fewer reruns, and no blind spot at Re(shift)
  // on the real axis where the vehicle's slow real modes sit. Mode 3 remains
  // the fallback below. A real shift makes the operator real: mode 3 only.
  OperatorPart part = opt.shift.imag() != 0.0 ? OperatorPart::imaginary : OperatorPart::real;
  int nev = initial_ritz_count(n, opt.n_eigenvalues, opt.shift);
  while (true) {
    const std::vector<EigenPair> converged =
        shift_invert_eigenpairs(A, norm_A, op, part, nev, opt);
    std::vector<EigenPair> nearest = nearest_to_shift(converged, opt.shift, opt.n_eigenvalues);
    const bool enough = int(nearest.size()) >= opt.n_eigenvalues;
    if (enough && nearest_are_certain(converged, nearest, opt.shift, part)) return nearest;
    // The real part hides eigenvalues near Re(sigma) on the real axis: once
    // the wanted disc reaches that point no Ritz count can prove the answer,
    // but the imaginary part can.
    if (enough && part == OperatorPart::real &&
        disc_contains_blind_spot(opt.shift, std::abs(nearest.back().value - opt.shift))) {
      part = OperatorPart::imaginary;
      continue;
    }
    if (nev < n - 2) {
      nev = std::min(n - 2, 2 * nev);
      continue;
    }
    if (!enough)
      throw std::runtime_error("eigen_arpack_shift_invert: ARPACK converged only " +
                               std::to_string(nearest.size()) + " eigenvalues, " +
                               std::to_string(opt.n_eigenvalues) + " requested");
    // n - 2 Ritz values and still unproven: only the two eigenvalues OP
    // weights least are unseen. Best available answer.
    return nearest;
  }
}

ModeInfo mode_info(Complex lambda) {
  const double magnitude = std::abs(lambda);
  ModeInfo info;
  info.frequency_hz = std::abs(lambda.imag()) / (2.0 * std::numbers::pi);
  info.damping_ratio = magnitude > 0.0 ? -lambda.real() / magnitude : 0.0;
  info.oscillatory = lambda.imag() != 0.0;
  return info;
}

double modal_assurance(const Eigen::VectorXcd& a, const Eigen::VectorXcd& b) {
  if (a.size() != b.size())
    throw std::invalid_argument("modal_assurance: vectors differ in length (" +
                                std::to_string(a.size()) + " vs " + std::to_string(b.size()) +
                                ")");
  const double aa = a.squaredNorm(), bb = b.squaredNorm();
  if (aa == 0.0 || bb == 0.0) return 0.0;
  return std::norm(a.dot(b)) / (aa * bb);  // Eigen's dot conjugates a: a^H b
}

std::vector<int> match_modes(const std::vector<EigenPair>& previous,
                             const std::vector<EigenPair>& current) {
  const std::vector<int> prev_upper = indices_where(previous, is_upper_oscillatory);
  const std::vector<int> cur_upper = indices_where(current, is_upper_oscillatory);
  // modal_assurance for every pair: the vectors as columns of P and C, all
  // inner products a^H b at once as P^H C (one matrix product), each
  // vector's squared norm once.
  auto columns = [](const std::vector<EigenPair>& pairs, const std::vector<int>& which) {
    const Eigen::Index n = which.empty() ? 0 : pairs[std::size_t(which[0])].vector.size();
    Eigen::MatrixXcd M(n, Eigen::Index(which.size()));
    for (std::size_t k = 0; k < which.size(); ++k) {
      const Eigen::VectorXcd& v = pairs[std::size_t(which[k])].vector;
      if (v.size() != n) modal_assurance(pairs[std::size_t(which[0])].vector, v);  // throws
      M.col(Eigen::Index(k)) = v;
    }
    return M;
  };
  const Eigen::MatrixXcd P = columns(previous, prev_upper), C = columns(current, cur_upper);
  if (P.cols() > 0 && C.cols() > 0 && P.rows() != C.rows())
    modal_assurance(previous[std::size_t(prev_upper[0])].vector,
                    current[std::size_t(cur_upper[0])].vector);  // throws, naming the lengths
  const Eigen::VectorXd prev_n2 = P.colwise().squaredNorm().transpose();
  const Eigen::VectorXd cur_n2 = C.colwise().squaredNorm().transpose();
  Eigen::MatrixXd mac(P.cols(), C.cols());
  if (P.cols() > 0 && C.cols() > 0) {
    const Eigen::MatrixXcd inner = P.adjoint() * C;
    for (Eigen::Index i = 0; i < P.cols(); ++i)
      for (Eigen::Index j = 0; j < C.cols(); ++j)
        mac(i, j) = prev_n2(i) == 0.0 || cur_n2(j) == 0.0
                        ? 0.0
                        : std::norm(inner(i, j)) / (prev_n2(i) * cur_n2(j));
  }
  // Hungarian rather than greedy: near a frequency crossing two modes can
  // both resemble the same current mode, and greedy would let the first one
  // take it; the optimal assignment decides on the whole set.
  const std::vector<int> assigned = max_weight_assignment(mac);

  std::vector<int> match(previous.size(), -1);
  for (std::size_t i = 0; i < prev_upper.size(); ++i)
    if (assigned[i] >= 0) match[std::size_t(prev_upper[i])] = cur_upper[std::size_t(assigned[i])];

  // Conjugates follow: the Im < 0 half of a pair goes where its partner went.
  const std::vector<int> cur_lower = indices_where(current, is_lower_oscillatory);
  for (int i : indices_where(previous, is_lower_oscillatory)) {
    const int partner = nearest_value(previous, prev_upper, std::conj(previous[std::size_t(i)].value));
    if (partner < 0 || match[std::size_t(partner)] < 0) continue;
    const Complex target = std::conj(current[std::size_t(match[std::size_t(partner)])].value);
    match[std::size_t(i)] = nearest_value(current, cur_lower, target);
  }
  return match;
}

}  // namespace railstab
