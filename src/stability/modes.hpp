#pragma once
// Modes of a linearised model: frequency, damping ratio, a name from the
// kinetic-energy participation of (body, coordinate), and the neutral /
// rigid-body classification that keeps them out of the stability decision.
#include "eigen/eigen_analysis.hpp"
#include "linear/linearization.hpp"
#include "model/model.hpp"

#include <complex>
#include <string>
#include <vector>

namespace railstab {

struct Participation {
  std::string body;
  int coordinate;  // 0..5
  double share;    // of the mode's kinetic energy, 0..1
};

struct ModeReport {
  std::complex<double> eigenvalue;
  double frequency_hz = 0.0;
  double damping_ratio = 0.0;
  double residual = 0.0;  // eigenpair residual (scale free)
  bool neutral = false;   // |lambda| at round-off level: rigid-body / cyclic
  std::string name;       // e.g. "wheelset1 lateral/yaw"
  std::vector<Participation> participation;  // largest first (at most 6)
  // Share of the kinetic energy in the lateral plane (lateral, roll and yaw
  // of every body): near 1 for hunting and sway, near 0 for bounce, pitch
  // and longitudinal modes.
  double lateral_share = 0.0;
  Eigen::VectorXcd vector;  // eigenvector on the linear model's kept states
};

// Kinetic-energy participation: share_k ~ M_k |v_rate_k|^2 with M_k the mass
// (translations) or the principal inertia (rotations) of that coordinate.
std::vector<ModeReport> describe_modes(const Model& model, const LinearModel& lin,
                                       const std::vector<EigenPair>& pairs);

// Threshold below which |lambda| counts as zero: round-off of the
// eigen-solver relative to the matrix norm.
double neutral_threshold(const Eigen::MatrixXd& A);

// Index of the least stable non-neutral mode at or below max_frequency_hz
// (largest real part; among equal real parts the oscillatory one), or -1.
int least_stable_mode(const std::vector<ModeReport>& modes, double max_frequency_hz);

// As least_stable_mode, among the oscillatory modes with lateral_share of at
// least min_lateral_share (the candidates for hunting), or -1.
int least_stable_lateral_mode(const std::vector<ModeReport>& modes, double max_frequency_hz,
                              double min_lateral_share = 0.5);

std::string coordinate_word(int coordinate);

}  // namespace railstab
