#pragma once
// Every eigenvalue of a large sparse state matrix A inside a box of the
// complex plane that holds the hunting band, by shift-invert Arnoldi at
// several shifts (eigen/eigen_analysis.hpp, sparse LU), with a proof of
// coverage instead of a guess at how many modes to ask for.
//
// The box: min_real_part <= Re(lambda) <= max_real_part and
// 0 <= Im(lambda) <= 2 pi max_frequency (the lower half is its mirror image:
// A is real). Shifts sigma_j = c + i y_j sit on the box's centre line
// c = (min + max) / 2. At each shift a complex Krylov-Schur restarted
// Arnoldi (band_eigen.cpp; it replaced ARPACK's znaupd/zneupd: the same
// convergence test, 1.7x faster on the 16-car train) iterates
// with OP = (A - sigma I)^-1, factorised once by a sparse LU
// (Eigen's SparseLU: the pattern analysed once for all shifts, the complex
// values factorised per shift). OP's eigenvalues are 1 / (lambda - sigma),
// so its k largest in magnitude are exactly the k eigenvalues of A nearest
// sigma: every eigenvalue in the open disc |lambda - sigma_j| < r_j (r_j:
// distance of the farthest of the k) is found. (A real-arithmetic driver
// with a complex shift works on Re or Im of OP, whose magnitude order is
// not the distance order, and needs every conjugate twice: measured 10-30x
// slower here.) With w = (max - min) / 2 the disc covers the box's full
// width for |Im(lambda) - y_j| <= h_j = sqrt(r_j^2 - w^2), so the discs
// cover the box exactly when the intervals [y_j - h_j, y_j + h_j] cover
// [0, 2 pi max_frequency]. Shifts are placed upwards from Im = 0, each where
// the previous interval ends plus its own expected half-height; a disc
// narrower than the box (r_j <= w) is asked again with twice k, one that
// leaves a gap is followed by a shift closer to the covered part. Each
// eigenvalue is taken from the first disc that holds it, so none is counted
// twice. One caveat of every Krylov method: an eigenvalue of exact
// multiplicity (identical cars without couplers) shows once per disc; the
// stability decision, which reads values, is not affected.
//
// In a sweep over speed the shifts and k of the previous speed's solve are
// the first guess (`plan`), and Ritz values outside the box converge to a
// looser tolerance (BandCoverOptions::outside_box_tolerance): 16-car train
// at 100 m/s, planned from 95 m/s, 2381 -> 1295 operator applications,
// 1.18 -> 0.75 s CPU, the same 105 modes in the box.
//
// Where A decouples into diagonal blocks (eigen/decoupled_blocks.hpp: a
// train on tangent track, lateral apart from vertical and longitudinal),
// each block's box is covered on its own: its own sparse LU and discs, and
// the box's modes divided between the blocks (blocks under 64 states are
// merged, down to the whole matrix when all are small).
//
// What is not computed: eigenvalues outside the box (and outside the discs,
// which stick out of it). The stability decision looks at the box only: an
// eigenvalue in the band with Re > max_real_part, or a real one there, would
// be missed. A hunting mode crosses the imaginary axis continuously with
// speed, so on a speed grid it is in the box (|Re| small) near its crossing.
#include <railstab/eigen/eigen_analysis.hpp>

#include <Eigen/Sparse>

#include <complex>
#include <vector>

namespace railstab {

struct BandCoverOptions {
  double min_real_part_per_s = -2.0;
  double max_real_part_per_s = 2.0;
  double max_frequency_hz = 20.0;
  int eigenvalues_per_shift = 16;  // k of the first solve at each shift (doubled as needed)
  int max_shifts = 400;            // then give up: covered = false
  // Relative Ritz tolerance (||OP x - theta x|| <= tol |theta|). 1e-9 missed members of the train's
  // clusters of nearly equal modes (94 of the 105 in the box of the 16-car
  // train at 100 m/s; 1e-12: all 105, as the dense solver).
  double tolerance = 1e-12;
  // The same for Ritz values whose eigenvalue lies outside the box: they
  // only bound a disc (radius to 1e-6 relative) and are reported as the
  // modes nearby, accurate to about this. The 16-car train's out-of-box
  // modes come in clusters of 16 nearly equal ones (relative spread
  // 1e-10..1e-7) that take many restarts to separate to 1e-12; at 1e-8 a
  // band solve planned from the previous speed took 1834 -> 1295 operator
  // applications (bench_scaling --band 16), every one of the 105 modes in
  // the box still equal to the dense solver's to 1e-8, and so were all
  // the out-of-box ones (at 1e-6 they were not).
  double outside_box_tolerance = 1e-8;
  // A solve may stop before all k converged (band_eigen.cpp, PrefixStop):
  // after this many restarts (< 0: never), when the leading converged Ritz
  // values (nearest first) end at a relative gap in |1 / (lambda - sigma)| of
  // prefix_stop_min_gap and give a disc whose half-height in the box is at
  // least prefix_stop_height_fraction of the expected one (and 0.1 of the
  // half-width). Those are then the disc. Where k cuts through a cluster of
  // nearly equal modes (one per car) the last members converge slowly; the
  // next shift finds them instead. 16-car train (bench_scaling --band 16):
  // 3035 -> 2381 OP applications, 78 -> 48 restarts, 1.45 -> 1.18 s CPU;
  // after 5 or 8 restarts or with a fraction of 0.5 less is saved, with a
  // gap of 1e-4 the same.
  int prefix_stop_after_restarts = 3;
  double prefix_stop_height_fraction = 0.0;
  double prefix_stop_min_gap = 1e-3;
};

struct ShiftDisc {
  std::complex<double> shift;
  double radius = 0.0;  // every eigenvalue with |lambda - shift| < radius was found
  int eigenvalues = 0;  // k of the solve
  // The Arnoldi's work (diagnostics): restarts and applications of OP.
  int restarts = 0;
  int operator_applications = 0;
  // The solve stopped on a converged prefix of fewer than k
  // (BandCoverOptions::prefix_stop_after_restarts): `eigenvalues` of them.
  bool prefix = false;
  // Which diagonal block of A the disc belongs to, where A decouples
  // (eigen_sparse_band below); 0 when it does not.
  int block = 0;
};

struct BandEigenResult {
  // Every eigenvalue in the union of the discs, once, least stable first.
  std::vector<EigenPair> pairs;
  std::vector<ShiftDisc> discs;
  bool covered = false;  // the discs cover the box
  int blocks = 1;        // diagonal blocks covered separately (1: A did not decouple)
};

// Throws std::invalid_argument for a non-square or non-finite A, an empty
// box (min >= max, max_frequency_hz <= 0) or eigenvalues_per_shift < 1.
//
// `plan`: the discs of an earlier solve of a nearby matrix (the previous
// speed of a sweep). Its shifts and k are where the placement starts: the
// spectrum moves little between neighbouring speeds, so the shifts it
// needed there (and the k a cluster needed) are the first guess here,
// instead of k = eigenvalues_per_shift doubled at every crowded shift. Only
// the guesses change: every disc is still checked as without a plan (too
// narrow: k doubled; a gap: a shift nearer the covered part), so coverage
// is proven the same way and a wrong plan costs solves, not eigenvalues.
BandEigenResult eigen_sparse_band(const Eigen::SparseMatrix<double>& A,
                                  const BandCoverOptions& options,
                                  const std::vector<ShiftDisc>& plan = {});

// The k eigenpairs of A nearest `shift` by one shift-invert Arnoldi solve
// (as one disc of eigen_sparse_band): every eigenvalue with
// |lambda - shift| < disc.radius is in `pairs` (radius 0 when Arnoldi did not
// converge all k: then nothing is proven). For following a known mode from
// a nearby matrix (a bisection in speed) at the cost of a few modes.
struct NearestEigenpairs {
  std::vector<EigenPair> pairs;  // nearest first
  ShiftDisc disc;
};
// Throws as eigen_sparse_band for a bad A, and for k < 1 or k > n - 2.
NearestEigenpairs eigen_sparse_nearest(const Eigen::SparseMatrix<double>& A,
                                       std::complex<double> shift, int k,
                                       double tolerance = 1e-12);

}  // namespace railstab
