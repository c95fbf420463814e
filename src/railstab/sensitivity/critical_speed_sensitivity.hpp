#pragma once
// d(critical speed)/dp for scene parameters, exactly in p.
//
// At the critical speed Vc the hunting eigenvalue lambda(V, p) has
// Re lambda(Vc(p), p) = 0. The implicit function theorem gives
//
//   dVc/dp = - (d Re lambda / dp) / (d Re lambda / dV)      at (Vc, p),
//
// with d lambda/dp = w^H (dA/dp) v / (w^H v) (eigenvalue_derivative; right
// and left eigenvectors v, w of the state matrix A, dA/dp exact by AD along
// p, the equilibrium's and the preloads' dependence on p included:
// parameter_derivative.hpp). d Re lambda / dV is exact the same way, with V
// as the parameter (kSpeedParameter: the track frames' rates, the spin, the
// creepages, the steady state and the preloads' twin differentiated in V);
// before it was a central difference at Vc +- 0.05 m/s (error ~1e-7
// relative). It is one number for all parameters, so it scales every dVc/dp
// alike and cannot change the ranking.
//
// The ranking is by the elasticity (p / Vc) dVc/dp: the relative change of
// the critical speed per relative change of p (dimensionless, so a
// stiffness and a mass compare).
#include <railstab/scene/scene_spec.hpp>

#include <complex>
#include <string>
#include <vector>

namespace railstab {

struct ParameterSensitivity {
  std::string key;                    // parameter_keys naming
  double value = 0.0;                 // p
  std::complex<double> eigenvalue_derivative;  // d lambda / dp
  double critical_speed_derivative = 0.0;      // dVc/dp, m/s per unit of p
  double elasticity = 0.0;                     // (p / Vc) dVc/dp
};

struct CriticalSpeedSensitivityOptions {
  double max_frequency_hz = 20.0;    // the hunting band (picks lambda)
};

struct CriticalSpeedSensitivities {
  double critical_speed_m_per_s = 0.0;
  std::complex<double> eigenvalue;         // lambda at Vc (Im > 0)
  double real_part_speed_derivative = 0.0; // d Re lambda / dV, 1/s per m/s
  std::vector<ParameterSensitivity> parameters;  // ranked by |elasticity|, largest first
};

// `hunting_frequency_hz`: the frequency of the critical mode at Vc (from the
// critical-speed search); lambda is the eigenvalue of A(Vc) nearest to
// i 2 pi f. `keys` empty: every parameter_keys(scene). Throws
// std::runtime_error when d Re lambda / dV is zero (no crossing at Vc).
CriticalSpeedSensitivities critical_speed_sensitivities(const SceneSpec& scene,
                                                        double critical_speed_m_per_s,
                                                        double hunting_frequency_hz,
                                                        std::vector<std::string> keys = {},
                                                        const CriticalSpeedSensitivityOptions& options = {});

}  // namespace railstab
