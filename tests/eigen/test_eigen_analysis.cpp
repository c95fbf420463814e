// Eigen analysis: dense against closed forms, ARPACK shift-invert against
// dense, modal quantities, and mode tracking through a frequency crossing.
#include <railstab/eigen/eigen_analysis.hpp>
#include "eigen/synthetic_systems.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

using namespace railstab;
using namespace railstab::test;
using Complex = std::complex<double>;

namespace {


std::vector<Complex> values_nearest(const std::vector<EigenPair>& pairs, Complex sigma,
                                    std::size_t count) {
  std::vector<Complex> values;
  for (const EigenPair& p : pairs) values.push_back(p.value);
  std::sort(values.begin(), values.end(), [sigma](Complex a, Complex b) {
    return std::abs(a - sigma) < std::abs(b - sigma);
  });
  values.resize(std::min(count, values.size()));
  return values;
}

// Same multiset of eigenvalues, each to rel_tol of its magnitude (a one-to-one
// pairing: every expected value consumes the nearest unused actual value).
void expect_same_eigenvalues(const std::vector<EigenPair>& actual,
                             const std::vector<Complex>& expected, double rel_tol) {
  ASSERT_EQ(actual.size(), expected.size());
  std::vector<bool> used(actual.size(), false);
  for (Complex e : expected) {
    std::size_t best = actual.size();
    for (std::size_t i = 0; i < actual.size(); ++i)
      if (!used[i] && (best == actual.size() ||
                       std::abs(actual[i].value - e) < std::abs(actual[best].value - e)))
        best = i;
    ASSERT_LT(best, actual.size());
    used[best] = true;
    EXPECT_LE(std::abs(actual[best].value - e), rel_tol * std::abs(e))
        << "expected " << e << ", got " << actual[best].value;
  }
}

Complex damped_oscillator_root(double omega, double zeta) {
  return {-zeta * omega, omega * std::sqrt(1.0 - zeta * zeta)};
}

}  // namespace

// ---------------------------------------------------------------------------
// Dense solver
// ---------------------------------------------------------------------------

// Eigenvalues of order 5 computed by a backward-stable QR algorithm are good
// to ~1e-15 * ||A||; 1e-12 absolute leaves margin for the 4x4 and 2x2 cases.
TEST(EigenDense, SingleDofMatchesClosedForm) {
  const double m = 2.0, k = 50.0, c = 0.4;  // omega = 5, zeta = 0.02
  const Eigen::MatrixXd A = first_order_form(Eigen::MatrixXd::Constant(1, 1, m),
                                             Eigen::MatrixXd::Constant(1, 1, k),
                                             Eigen::MatrixXd::Constant(1, 1, c));
  const Complex root = damped_oscillator_root(5.0, 0.02);
  const std::vector<EigenPair> pairs = eigen_dense(A);
  ASSERT_EQ(pairs.size(), 2u);
  // Sorted by real part, then imaginary part descending: +i first.
  EXPECT_LE(std::abs(pairs[0].value - root), 1e-12);
  EXPECT_LE(std::abs(pairs[1].value - std::conj(root)), 1e-12);
  for (const EigenPair& p : pairs) EXPECT_LT(p.residual, 1e-12);
}

TEST(EigenDense, TwoDofProportionalDampingMatchesClosedForm) {
  // Two equal masses, three equal springs: omega^2 = k/m and 3k/m. C = alpha K
  // keeps the modes real-valued, with zeta_i = alpha omega_i / 2.
  const double m = 1.5, k = 60.0, alpha = 0.004;
  const Eigen::MatrixXd M = m * Eigen::MatrixXd::Identity(2, 2);
  Eigen::MatrixXd K(2, 2);
  K << 2 * k, -k, -k, 2 * k;
  const Eigen::MatrixXd A = first_order_form(M, K, alpha * K);
  std::vector<Complex> expected;
  for (double omega : {std::sqrt(k / m), std::sqrt(3 * k / m)}) {
    const Complex root = damped_oscillator_root(omega, alpha * omega / 2);
    expected.push_back(root);
    expected.push_back(std::conj(root));
  }
  const std::vector<EigenPair> pairs = eigen_dense(A);
  ASSERT_EQ(pairs.size(), 4u);
  for (Complex e : expected) {
    const auto nearest = std::min_element(pairs.begin(), pairs.end(), [e](auto& a, auto& b) {
      return std::abs(a.value - e) < std::abs(b.value - e);
    });
    EXPECT_LE(std::abs(nearest->value - e), 1e-12) << e;
  }
  for (const EigenPair& p : pairs) EXPECT_LT(p.residual, 1e-12);
}

// The phase convention is exact up to rounding: 1e-14.
TEST(EigenDense, VectorsAreUnitWithRealPositivePeak) {
  const Eigen::MatrixXd A = damped_mechanical_system(20, 3);
  for (const EigenPair& p : eigen_dense(A)) {
    EXPECT_NEAR(p.vector.norm(), 1.0, 1e-14);
    Eigen::Index peak = 0;
    p.vector.cwiseAbs().maxCoeff(&peak);
    EXPECT_NEAR(p.vector(peak).imag(), 0.0, 1e-14);
    EXPECT_GT(p.vector(peak).real(), 0.0);
  }
}

// ---------------------------------------------------------------------------
// ARPACK shift-invert against dense
// ---------------------------------------------------------------------------

// Both solvers are backward stable to ~1e-14 here (well-conditioned modes);
// 1e-9 relative is the brief's acceptance level and still far below any
// physically meaningful difference.
TEST(EigenArpack, ComplexShiftMatchesDenseNearestTen) {
  const Eigen::MatrixXd A = damped_mechanical_system(100, 11);
  ArpackOptions opt;
  opt.shift = {0.5, 5.0};
  opt.n_eigenvalues = 10;
  const std::vector<EigenPair> arpack = eigen_arpack_shift_invert(A, opt);
  const std::vector<Complex> dense = values_nearest(eigen_dense(A), opt.shift, 10);
  expect_same_eigenvalues(arpack, dense, 1e-9);
  for (const EigenPair& p : arpack) EXPECT_LT(p.residual, 1e-9) << p.value;
  // Returned nearest first.
  for (std::size_t i = 1; i < arpack.size(); ++i)
    EXPECT_LE(std::abs(arpack[i - 1].value - opt.shift), std::abs(arpack[i].value - opt.shift));
}

TEST(EigenArpack, RealShiftMatchesDense) {
  const Eigen::MatrixXd A = damped_mechanical_system(100, 12);
  ArpackOptions opt;
  opt.shift = {0.3, 0.0};
  opt.n_eigenvalues = 6;  // three conjugate pairs
  const std::vector<EigenPair> arpack = eigen_arpack_shift_invert(A, opt);
  expect_same_eigenvalues(arpack, values_nearest(eigen_dense(A), opt.shift, 6), 1e-9);
  for (const EigenPair& p : arpack) EXPECT_LT(p.residual, 1e-9) << p.value;
}

// With a real shift a conjugate pair is equidistant; asking for an odd count
// must not split the last pair.
TEST(EigenArpack, RealShiftKeepsConjugatePairsTogether) {
  const Eigen::MatrixXd A = damped_mechanical_system(100, 12);
  ArpackOptions opt;
  opt.shift = {0.3, 0.0};
  opt.n_eigenvalues = 5;
  const std::vector<EigenPair> arpack = eigen_arpack_shift_invert(A, opt);
  ASSERT_EQ(arpack.size(), 6u);
  expect_same_eigenvalues(arpack, values_nearest(eigen_dense(A), opt.shift, 6), 1e-9);
}

// Real eigenvalues (overdamped modes) near a real shift.
TEST(EigenArpack, RealShiftFindsRealEigenvalues) {
  std::mt19937 rng(5);
  const Eigen::Index n = 60;
  Eigen::VectorXd d = Eigen::VectorXd::LinSpaced(n, -30.0, -0.5);
  const Eigen::MatrixXd T = random_orthogonal(n, rng) + 0.3 * Eigen::MatrixXd::Identity(n, n);
  const Eigen::MatrixXd A = T * d.asDiagonal() * T.inverse();
  ArpackOptions opt;
  opt.shift = {-10.2, 0.0};
  opt.n_eigenvalues = 4;
  const std::vector<EigenPair> arpack = eigen_arpack_shift_invert(A, opt);
  expect_same_eigenvalues(arpack, values_nearest(eigen_dense(A), opt.shift, 4), 1e-9);
  for (const EigenPair& p : arpack) {
    EXPECT_EQ(p.value.imag(), 0.0);
    EXPECT_LT(p.residual, 1e-9);
  }
}

// The hard case of the complex-shift mode: an eigenvalue on the circle
// |lambda - Re sigma| = Im sigma gives OP = Re((A - sigma I)^-1) the same
// eigenvalue for lambda and conj(lambda). Individual Ritz vectors of OP are
// then arbitrary mixtures of two eigenvectors of A; the projection onto the
// invariant subspace must still return both eigenvalues exactly (1e-9).
TEST(EigenArpack, ComplexShiftEigenvalueOnDegenerateCircle) {
  const Complex sigma(0.5, 5.0);
  const double angle = 100.0 * std::numbers::pi / 180.0;
  const Complex on_circle = sigma.real() + sigma.imag() * std::polar(1.0, angle);
  std::vector<Complex> spectrum = {on_circle, {-0.2, 5.6}, {-0.05, 4.1}, {-0.3, 6.5},
                                   {-0.1, 3.0}, {-0.4, 8.0}, {-0.02, 1.0}, {-1.0, 12.0}};
  // Real block-diagonal form, then a fixed random similarity.
  const Eigen::Index n = 2 * Eigen::Index(spectrum.size()) + 4;
  Eigen::MatrixXd D = Eigen::MatrixXd::Zero(n, n);
  for (std::size_t b = 0; b < spectrum.size(); ++b) {
    const Eigen::Index i = 2 * Eigen::Index(b);
    D(i, i) = D(i + 1, i + 1) = spectrum[b].real();
    D(i, i + 1) = spectrum[b].imag();
    D(i + 1, i) = -spectrum[b].imag();
  }
  for (Eigen::Index i = n - 4; i < n; ++i) D(i, i) = -2.0 * double(i - n + 5);
  std::mt19937 rng(8);
  const Eigen::MatrixXd T = random_orthogonal(n, rng) + 0.5 * Eigen::MatrixXd::Identity(n, n);
  const Eigen::MatrixXd A = T * D * T.inverse();
  ArpackOptions opt;
  opt.shift = sigma;
  opt.n_eigenvalues = 4;
  const std::vector<EigenPair> arpack = eigen_arpack_shift_invert(A, opt);
  expect_same_eigenvalues(arpack, values_nearest(eigen_dense(A), sigma, 4), 1e-9);
  const bool found = std::any_of(arpack.begin(), arpack.end(), [&](const EigenPair& p) {
    return std::abs(p.value - on_circle) < 1e-9 * std::abs(on_circle);
  });
  EXPECT_TRUE(found);
  for (const EigenPair& p : arpack) EXPECT_LT(p.residual, 1e-9) << p.value;
}

// Shifts scattered over the spectrum, some with the wanted disc wide against
// Im(sigma): there OP's magnitude order is far from the distance order and a
// fixed Ritz count misses true nearest eigenvalues; the solver must notice
// and ask for more. Same 1e-9 relative acceptance as above.
TEST(EigenArpack, ScatteredComplexShiftsAllMatchDense) {
  const Eigen::MatrixXd A = damped_mechanical_system(100, 1);
  const std::vector<EigenPair> dense = eigen_dense(A);
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    ArpackOptions opt;
    opt.shift = {-0.5 + 1.5 * uniform(rng), 0.3 + 15.0 * uniform(rng)};
    opt.n_eigenvalues = 6 + int(10 * uniform(rng));
    SCOPED_TRACE(::testing::Message() << "shift " << opt.shift << ", " << opt.n_eigenvalues);
    const std::vector<EigenPair> arpack = eigen_arpack_shift_invert(A, opt);
    expect_same_eigenvalues(arpack, values_nearest(dense, opt.shift, arpack.size()), 1e-9);
  }
}

// OP = Re((A - sigma I)^-1) maps an eigenvalue at exactly Re(sigma) to 0: the
// real-part mode cannot see it at all, yet here it is the nearest one.
TEST(EigenArpack, ComplexShiftFindsRealEigenvalueAtRealPartOfShift) {
  const Complex sigma(-1.0, 0.5);
  const std::vector<double> real_values = {-1.0, -3.0, -0.2, -6.0};
  const std::vector<Complex> pairs = {{-0.1, 2.0}, {-0.3, 4.0}, {-0.05, 1.2}, {-0.5, 7.0}};
  const Eigen::Index n = Eigen::Index(real_values.size() + 2 * pairs.size());
  Eigen::MatrixXd D = Eigen::MatrixXd::Zero(n, n);
  for (std::size_t b = 0; b < pairs.size(); ++b) {
    const Eigen::Index i = 2 * Eigen::Index(b);
    D(i, i) = D(i + 1, i + 1) = pairs[b].real();
    D(i, i + 1) = pairs[b].imag();
    D(i + 1, i) = -pairs[b].imag();
  }
  for (std::size_t r = 0; r < real_values.size(); ++r)
    D(n - 1 - Eigen::Index(r), n - 1 - Eigen::Index(r)) = real_values[r];
  std::mt19937 rng(23);
  const Eigen::MatrixXd T = random_orthogonal(n, rng) + 0.5 * Eigen::MatrixXd::Identity(n, n);
  const Eigen::MatrixXd A = T * D * T.inverse();
  ArpackOptions opt;
  opt.shift = sigma;
  opt.n_eigenvalues = 3;
  const std::vector<EigenPair> arpack = eigen_arpack_shift_invert(A, opt);
  expect_same_eigenvalues(arpack, values_nearest(eigen_dense(A), sigma, 3), 1e-9);
  EXPECT_LE(std::abs(arpack.front().value - Complex(-1.0, 0.0)), 1e-9);
}

TEST(EigenArpack, IterationLimitReportsArpackInfo) {
  const Eigen::MatrixXd A = damped_mechanical_system(200, 21);
  ArpackOptions opt;
  opt.shift = {0.0, 9.0};
  opt.n_eigenvalues = 12;
  opt.tolerance = 1e-15;
  opt.max_iterations = 1;
  try {
    eigen_arpack_shift_invert(A, opt);
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("info = 1"), std::string::npos) << e.what();
  }
}

// ---------------------------------------------------------------------------
// Bad input
// ---------------------------------------------------------------------------

TEST(EigenInput, NonSquareMatrixThrows) {
  const Eigen::MatrixXd A = Eigen::MatrixXd::Ones(4, 5);
  EXPECT_THROW(eigen_dense(A), std::invalid_argument);
  ArpackOptions opt;
  opt.n_eigenvalues = 1;
  EXPECT_THROW(eigen_arpack_shift_invert(A, opt), std::invalid_argument);
}

TEST(EigenInput, BadArpackRequestsThrow) {
  const Eigen::MatrixXd A = damped_mechanical_system(20, 4);
  ArpackOptions opt;
  opt.shift = {0.1, 3.0};
  opt.n_eigenvalues = 19;  // needs n_eigenvalues <= n - 2 = 18
  EXPECT_THROW(eigen_arpack_shift_invert(A, opt), std::invalid_argument);
  opt.n_eigenvalues = 0;
  EXPECT_THROW(eigen_arpack_shift_invert(A, opt), std::invalid_argument);
  opt.n_eigenvalues = 4;
  opt.max_iterations = 0;
  EXPECT_THROW(eigen_arpack_shift_invert(A, opt), std::invalid_argument);
  opt.max_iterations = 100;
  opt.tolerance = -1.0;
  EXPECT_THROW(eigen_arpack_shift_invert(A, opt), std::invalid_argument);
  opt.tolerance = 1e-12;
  opt.n_eigenvalues = 18;  // the largest allowed count works
  EXPECT_NO_THROW(eigen_arpack_shift_invert(A, opt));
}

TEST(EigenInput, ShiftOnAnEigenvalueThrows) {
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(6, 6);
  A.diagonal() << -1, -2, -3, -4, -5, -6;
  ArpackOptions opt;
  opt.shift = {-3.0, 0.0};
  opt.n_eigenvalues = 2;
  EXPECT_THROW(eigen_arpack_shift_invert(A, opt), std::invalid_argument);
}

TEST(EigenInput, NonFiniteMatrixThrows) {
  Eigen::MatrixXd A = Eigen::MatrixXd::Identity(3, 3);
  A(1, 2) = std::nan("");
  EXPECT_THROW(eigen_dense(A), std::invalid_argument);
}

// ---------------------------------------------------------------------------
// Modal quantities
// ---------------------------------------------------------------------------

// Plain arithmetic on exact inputs: 1e-14.
TEST(ModeInfo, KnownEigenvalues) {
  const double two_pi = 2 * std::numbers::pi;
  const ModeInfo hunting = mode_info({-0.3, two_pi * 2.5});
  EXPECT_NEAR(hunting.frequency_hz, 2.5, 1e-14);
  EXPECT_NEAR(hunting.damping_ratio, 0.3 / std::hypot(0.3, two_pi * 2.5), 1e-14);
  EXPECT_TRUE(hunting.oscillatory);

  const ModeInfo unstable = mode_info({1.0, -1.0});  // conjugate half, growing
  EXPECT_NEAR(unstable.frequency_hz, 1.0 / two_pi, 1e-14);
  EXPECT_NEAR(unstable.damping_ratio, -1.0 / std::sqrt(2.0), 1e-14);

  const ModeInfo undamped = mode_info({0.0, 4.0});
  EXPECT_EQ(undamped.damping_ratio, 0.0);

  const ModeInfo decaying = mode_info({-2.0, 0.0});
  EXPECT_EQ(decaying.damping_ratio, 1.0);
  EXPECT_EQ(decaying.frequency_hz, 0.0);
  EXPECT_FALSE(decaying.oscillatory);

  EXPECT_EQ(mode_info({3.0, 0.0}).damping_ratio, -1.0);
  const ModeInfo rigid = mode_info({0.0, 0.0});
  EXPECT_EQ(rigid.damping_ratio, 0.0);
  EXPECT_EQ(rigid.frequency_hz, 0.0);
  EXPECT_FALSE(rigid.oscillatory);
}

// MAC is a ratio of O(1) sums: 1e-14.
TEST(ModalAssurance, ScaledCopyIsOneOrthogonalIsZero) {
  std::mt19937 rng(1);
  std::normal_distribution<double> normal;
  const Eigen::VectorXcd v =
      Eigen::VectorXcd::NullaryExpr(12, [&] { return Complex(normal(rng), normal(rng)); });
  EXPECT_NEAR(modal_assurance(v, Complex(-2.5, 0.7) * v), 1.0, 1e-14);
  EXPECT_NEAR(modal_assurance(Complex(0.0, 3.0) * v, v), 1.0, 1e-14);

  Eigen::VectorXcd a(2), b(2);
  a << 1.0, Complex(0.0, 1.0);
  b << 1.0, Complex(0.0, -1.0);  // a^H b = 1 + (-i)(-i) = 0
  EXPECT_NEAR(modal_assurance(a, b), 0.0, 1e-14);
  EXPECT_EQ(modal_assurance(Eigen::VectorXcd::Unit(3, 0), Eigen::VectorXcd::Unit(3, 2)), 0.0);
  EXPECT_EQ(modal_assurance(Eigen::VectorXcd::Zero(3), v.head(3)), 0.0);
}

// ---------------------------------------------------------------------------
// Mode tracking
// ---------------------------------------------------------------------------

namespace {

// Three uncoupled damped oscillators plus an overdamped one, mixed by a fixed
// similarity so eigenvectors are generic. Oscillator 0 rises from 2 to 4
// rad/s and oscillator 1 falls from 4 to 2 as p goes 0 -> 1: they cross at
// p = 0.5, but each keeps its own degree of freedom, hence its eigenvector.
struct CrossingFamily {
  Eigen::MatrixXd mixing;
  CrossingFamily() {
    std::mt19937 rng(17);
    mixing = random_orthogonal(8, rng);
  }
  static double omega(int oscillator, double p) {
    switch (oscillator) {
      case 0: return 2.0 + 2.0 * p;
      case 1: return 4.0 - 2.0 * p;
      default: return 6.0;
    }
  }
  static constexpr double zeta[3] = {0.02, 0.05, 0.03};
  Eigen::MatrixXd matrix(double p) const {
    Eigen::MatrixXd M = Eigen::MatrixXd::Identity(4, 4);
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(4, 4), C = K;
    for (int i = 0; i < 3; ++i) {
      K(i, i) = omega(i, p) * omega(i, p);
      C(i, i) = 2 * zeta[i] * omega(i, p);
    }
    K(3, 3) = 1.0;
    C(3, 3) = 5.0;  // overdamped: two real eigenvalues
    return mixing * first_order_form(M, K, C) * mixing.transpose();
  }
};

int index_of_nearest(const std::vector<EigenPair>& pairs, Complex value) {
  int best = 0;
  for (std::size_t i = 0; i < pairs.size(); ++i)
    if (std::abs(pairs[i].value - value) < std::abs(pairs[std::size_t(best)].value - value))
      best = int(i);
  return best;
}

// Rank of mode `index` among the Im > 0 modes ordered by frequency.
int frequency_rank(const std::vector<EigenPair>& pairs, int index) {
  int rank = 0;
  for (const EigenPair& p : pairs)
    if (p.value.imag() > 0 && p.value.imag() < pairs[std::size_t(index)].value.imag()) ++rank;
  return rank;
}

}  // namespace

// The tracked eigenvalue must be the closed-form root of the same oscillator
// at every step, to 1e-10 (dense eigenvalues are good to ~1e-14 here).
TEST(MatchModes, FollowsModesThroughFrequencyCrossing) {
  const CrossingFamily family;
  std::vector<EigenPair> previous = eigen_dense(family.matrix(0.0));
  int tracked = index_of_nearest(previous, damped_oscillator_root(2.0, CrossingFamily::zeta[0]));
  const int rank_at_start = frequency_rank(previous, tracked);
  for (int step = 1; step <= 10; ++step) {
    const double p = 0.1 * step;
    const std::vector<EigenPair> current = eigen_dense(family.matrix(p));
    const std::vector<int> match = match_modes(previous, current);
    ASSERT_EQ(match.size(), previous.size());
    tracked = match[std::size_t(tracked)];
    ASSERT_GE(tracked, 0) << "lost the mode at p = " << p;
    const Complex expected =
        damped_oscillator_root(CrossingFamily::omega(0, p), CrossingFamily::zeta[0]);
    EXPECT_LE(std::abs(current[std::size_t(tracked)].value - expected), 1e-10) << "p = " << p;
    previous = current;
  }
  // Sorting by frequency would have swapped the two modes.
  EXPECT_EQ(rank_at_start, 0);
  EXPECT_EQ(frequency_rank(previous, tracked), 1);
}

TEST(MatchModes, ConjugatesFollowAndRealModesAreUnmatched) {
  const CrossingFamily family;
  const std::vector<EigenPair> previous = eigen_dense(family.matrix(0.3));
  const std::vector<EigenPair> current = eigen_dense(family.matrix(0.35));
  const std::vector<int> match = match_modes(previous, current);
  ASSERT_EQ(match.size(), previous.size());
  for (std::size_t i = 0; i < previous.size(); ++i) {
    if (!mode_info(previous[i].value).oscillatory) {
      EXPECT_EQ(match[i], -1);
      continue;
    }
    ASSERT_GE(match[i], 0);
    const Complex now = current[std::size_t(match[i])].value;
    // Same half-plane, and close: the step in p is small (|dlambda| < 0.2).
    EXPECT_GT(now.imag() * previous[i].value.imag(), 0.0);
    EXPECT_LT(std::abs(now - previous[i].value), 0.2);
  }
  // Each current mode is used at most once.
  std::vector<int> used;
  for (int m : match)
    if (m >= 0) used.push_back(m);
  std::sort(used.begin(), used.end());
  EXPECT_EQ(std::adjacent_find(used.begin(), used.end()), used.end());
}

TEST(MatchModes, CountsMayDiffer) {
  const CrossingFamily family;
  const std::vector<EigenPair> all = eigen_dense(family.matrix(0.2));
  // The current set lacks the oscillator-2 pair (e.g. outside an ARPACK window).
  std::vector<EigenPair> partial;
  for (const EigenPair& p : all)
    if (std::abs(p.value.imag()) < 5.0) partial.push_back(p);
  const std::vector<int> match = match_modes(all, partial);
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (std::abs(all[i].value.imag()) >= 5.0) {
      EXPECT_EQ(match[i], -1);
    } else if (mode_info(all[i].value).oscillatory) {
      ASSERT_GE(match[i], 0);
      EXPECT_EQ(partial[std::size_t(match[i])].value, all[i].value);
    }
  }
}
