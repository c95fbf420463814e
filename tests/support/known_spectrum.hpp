#pragma once
// A sparse test matrix whose eigenvalues are known exactly: 2 x 2 blocks
// [a w; -w a] (eigenvalues a +- i w) with a uniform in [-20, 10] 1/s and w in
// [0.5, 200] rad/s, then `real_eigenvalues` 1 x 1 blocks [a], all from one
// seeded generator (so a test sees the same matrix on every run).
#include <Eigen/Sparse>

#include <complex>
#include <random>
#include <vector>

namespace railstab::test {

struct KnownSpectrum {
  Eigen::SparseMatrix<double> matrix;
  std::vector<std::complex<double>> eigenvalues;  // both members of each pair
};

inline KnownSpectrum block_diagonal_known_spectrum(unsigned seed, int complex_pairs,
                                                   int real_eigenvalues = 0) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> re(-20.0, 10.0), im(0.5, 200.0);
  std::vector<Eigen::Triplet<double>> t;
  KnownSpectrum out;
  int row = 0;
  for (int b = 0; b < complex_pairs; ++b, row += 2) {
    const double a = re(rng), w = im(rng);
    t.emplace_back(row, row, a);
    t.emplace_back(row, row + 1, w);
    t.emplace_back(row + 1, row, -w);
    t.emplace_back(row + 1, row + 1, a);
    out.eigenvalues.push_back({a, w});
    out.eigenvalues.push_back({a, -w});
  }
  for (int r = 0; r < real_eigenvalues; ++r, ++row) {
    const double a = re(rng);
    t.emplace_back(row, row, a);
    out.eigenvalues.push_back({a, 0.0});
  }
  out.matrix.resize(row, row);
  out.matrix.setFromTriplets(t.begin(), t.end());
  return out;
}

}  // namespace railstab::test
