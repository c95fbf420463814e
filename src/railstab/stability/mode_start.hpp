#pragma once
// A time-domain start on a mode: the steady state at the run's speed plus
// the real part of the mode's eigenvector, rotated and scaled so that the
// leading wheelset's lateral shift starts at a crest of the chosen size:
//   x0 = x_eq + Re(c v),   c = M conj(v_L) / |v_L|^2
// v: the eigenvector on the linear model's kept states (positions, rates and
// element states; a wheelset's spin angle, which nothing depends on, stays
// at the steady state), v_L its entry for the leading wheelset's y, M the
// amplitude in m. So x0(y_L) - x_eq(y_L) = M exactly and every other entry
// is Re(v_k conj(v_L)) M / |v_L|^2: the mode shape as the eigen report gives
// it, at t = 0 of the linear motion x_eq + Re(c v e^(lambda t)).
//
// The leading wheelset: model/leading_wheelset.hpp.
#include <railstab/model/model.hpp>

#include <Eigen/Dense>

#include <complex>
#include <string>

namespace railstab {

// The mode "hunting": the least stable oscillatory lateral mode in the
// hunting band (as critical-speed and verify choose it).
inline constexpr const char* kHuntingModeSelector = "hunting";
// The band the modes are looked for in (Hz), the analyses' default.
inline constexpr double kModeStartBandHz = 20.0;

struct ModeStart {
  Eigen::VectorXd state;         // x0
  std::string mode_name;         // as the eigen report names it
  std::complex<double> eigenvalue;
  std::string leading_wheelset;  // whose lateral shift is M
  double amplitude_m = 0.0;      // M
};

// `selector`: kHuntingModeSelector or a mode name of the eigen analysis at
// speed V (exactly as `railstab eigen` prints it). Throws
// std::invalid_argument naming --mode with the known names when none
// matches, and when the mode does not move the leading wheelset laterally.
ModeStart mode_start_state(const Model& model, double speed_m_per_s,
                           const Eigen::VectorXd& equilibrium_guess, const std::string& selector,
                           double amplitude_m);

// How a run started on it, as the reports say: "mode 'hunting', wheelset1
// lateral 0.005 m".
std::string mode_start_description(const ModeStart& start);

}  // namespace railstab
