#pragma once
// Equivalent conicity by EN 15302 from the rolling-radius-difference
// function delta_r(y), by integrating the nonlinear kinematic (Klingel)
// motion of a free wheelset over distance s:
//   d2y/ds2 = -delta_r(y) / (2 e0 r0),   y(0) = amplitude, y'(0) = 0,
// (e0: half the distance between the nominal contact points, r0: nominal
// rolling radius). The wavelength lambda is the distance over which y
// returns to its start (one full cycle); the equivalent conicity is the
// conicity of the cone pair with that Klingel wavelength,
//   lambda = 2 pi sqrt(r0 e0 / tan(gamma_e))  =>  tan(gamma_e) = r0 e0 (2 pi / lambda)^2.
// A linear delta_r = 2 lambda0 y gives tan(gamma_e) = lambda0 at every amplitude.
//
// delta_r is interpolated LINEARLY between its samples: it jumps where the
// contact jumps (two-point contact), and a cubic through a jump would ring.
// Integration: classical Runge-Kutta with steps of lambda_est / 4000 and the
// turning points located by cubic Hermite interpolation of y'.
#include <vector>

namespace railstab {

struct DeltaRFunction {
  std::vector<double> y_m;        // strictly increasing
  std::vector<double> delta_r_m;
  double operator()(double y) const;  // linear interpolation; throws outside the range
};

struct ConicityPoint {
  double amplitude_m;
  double wavelength_m;
  double equivalent_conicity;   // tan(gamma_e)
};

// Throws std::invalid_argument (naming what is wrong) when delta_r does not
// restore (delta_r(y) y <= 0 at the amplitude) or the motion leaves the
// sampled range of delta_r.
ConicityPoint equivalent_conicity(const DeltaRFunction& delta_r, double amplitude_m,
                                  double half_contact_distance_m, double nominal_rolling_radius_m);

}  // namespace railstab
