#pragma once
// Least-squares fit of a damped sinusoid to a sampled signal:
//   y(t) = exp(sigma t) (a cos(omega t) + b sin(omega t)) + c
// by Gauss-Newton with the exact Jacobian, started from a guess of sigma and
// omega (the eigenvalue being verified); a, b, c start from the linear
// least-squares solution at that guess.
#include <Eigen/Dense>

#include <vector>

namespace railstab {

struct DampedSinusoid {
  double sigma_per_s = 0.0;    // growth (> 0) or decay (< 0) rate
  double omega_rad_s = 0.0;    // angular frequency
  double a = 0.0, b = 0.0, c = 0.0;  // a, b at the window start (time t - t_first)
  double rms_residual = 0.0;   // of the fit
  double rms_signal = 0.0;     // of the signal minus c (for a relative measure)
  int iterations = 0;
};

// Throws std::runtime_error if the fit does not converge.
DampedSinusoid fit_damped_sinusoid(const std::vector<double>& t, const std::vector<double>& y,
                                   double sigma_guess, double omega_guess);

}  // namespace railstab
