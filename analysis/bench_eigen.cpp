// Timing of the two eigen solvers on synthetic damped mechanical systems in
// first-order form, A = [[0, I], [-M^-1 K, -M^-1 C]], of 100 and 200 states:
// all eigenpairs by eigen_dense against the 12 nearest sigma = 0.5 + 5i by
// eigen_arpack_shift_invert. Prints the time per call and dense / ARPACK.
#include "cpu_timing.hpp"
#include <railstab/eigen/eigen_analysis.hpp>
#include "eigen/synthetic_systems.hpp"  // tests/

#include <algorithm>
#include <cstdio>
#include <functional>
#include <limits>
#include <random>
#include <vector>

namespace {

using railstab::ArpackOptions;
using railstab::EigenPair;
using Complex = std::complex<double>;
using railstab::test::damped_mechanical_system;

// CPU seconds per call (analysis/cpu_timing.hpp): a warm-up call
// (first-touch allocations, caches), then five batches of at least 0.2 s,
// the median of the batch means.
double seconds_per_call(const std::function<void()>& call) {
  call();
  return railstab::bench::median_of_batches(call);
}

// Largest relative difference between ARPACK's eigenvalues and the nearest
// dense ones: the timing means nothing if the answers differ.
double largest_relative_difference(const std::vector<EigenPair>& arpack,
                                   const std::vector<EigenPair>& dense) {
  double worst = 0.0;
  for (const EigenPair& a : arpack) {
    double nearest = std::numeric_limits<double>::infinity();
    for (const EigenPair& d : dense) nearest = std::min(nearest, std::abs(a.value - d.value));
    worst = std::max(worst, nearest / std::abs(a.value));
  }
  return worst;
}

void bench_system(Eigen::Index states) {
  const Eigen::MatrixXd A = damped_mechanical_system(states, 11);
  ArpackOptions opt;
  opt.shift = Complex(0.5, 5.0);
  opt.n_eigenvalues = 12;

  const double dense_s = seconds_per_call([&] { (void)railstab::eigen_dense(A); });
  const double arpack_s =
      seconds_per_call([&] { (void)railstab::eigen_arpack_shift_invert(A, opt); });
  const double difference = largest_relative_difference(
      railstab::eigen_arpack_shift_invert(A, opt), railstab::eigen_dense(A));
  std::printf("%4ld states: dense %9.3f ms   ARPACK (12 near %.1f%+.1fi) %9.3f ms   "
              "dense/ARPACK %6.2f   max rel. difference %.1e\n",
              long(states), 1e3 * dense_s, opt.shift.real(), opt.shift.imag(), 1e3 * arpack_s,
              dense_s / arpack_s, difference);
}

}  // namespace

int main() {
  for (Eigen::Index states : {100, 200}) bench_system(states);
  return 0;
}
