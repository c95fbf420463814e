#pragma once
// Equivalent conicity by EN 15302 (its Klingel-integration method) from the
// rolling-radius-difference function delta_r(y), y the lateral displacement
// of the wheelset relative to the track (rigid_contact.hpp: the EN 15302
// reference). The nonlinear kinematic (Klingel) motion of a free wheelset
// over distance s is
//   d2y/ds2 = -delta_r(y) / (2 e0 r0)
// (e0: half the distance between the nominal contact points, r0: nominal
// rolling radius). Its first integral (energy) with the potential
//   P(y) = integral_{y_first}^{y} delta_r(v) dv
// is  (dy/ds)^2 = (L - P(y)) / (e0 r0),  L the level of the turning points.
//
// Equilibrium: the bottom of the potential well nearest y = 0, where
// delta_r changes sign from - to + (klingel_equilibrium). On an asymmetric
// wheelset it is not y = 0. Where |delta_r| <= kDeltaRZero_m over a stretch
// (a profile pair with no rolling-radius difference about the centre) the
// bottom is that whole stretch [low, high].
//
// Amplitude: half the peak-to-peak motion about the equilibrium,
//   A = (y_upper - y_lower) / 2,  P(y_lower) = P(y_upper) = L,
// with y_upper the first point above the well's bottom where P reaches L and
// y_lower the first below it; L is found by bisection (the half width grows
// monotonically with L). A <= (high - low) / 2: the motion stays on the
// zero stretch, no restoring at all: conicity 0 (wavelength infinite), as the
// standard states for delta_r = 0.
//
// Wavelength: the motion from y(0) = y_upper, y'(0) = 0 integrated by
// classical Runge-Kutta (steps of lambda_est / 4000, lambda_est from a
// 64-point midpoint quadrature of the energy integral below) until it returns
// to y_upper (turning points located by cubic Hermite interpolation of y');
//   lambda = 2 sqrt(e0 r0) integral_{y_lower}^{y_upper} dy / sqrt(L - P(y))
// is the same number (the tests integrate it independently).
// The equivalent conicity is the conicity of the cone pair with that
// Klingel wavelength,
//   lambda = 2 pi sqrt(r0 e0 / tan(gamma_e))  =>  tan(gamma_e) = r0 e0 (2 pi / lambda)^2.
// A linear delta_r = 2 lambda0 (y - y_eq) gives tan(gamma_e) = lambda0 at
// every amplitude.
//
// delta_r is interpolated LINEARLY between its samples (so P is piecewise
// quadratic, exactly): delta_r jumps where the contact jumps (two-point
// contact), and a cubic through a jump would ring.
#include <vector>

namespace railstab {

// |delta_r| at or below this counts as zero when finding the bottom of the
// well (rigid-contact delta_r of a pair with a flat stretch is zero to
// round-off, ~1e-15 m; the smallest real delta_r of interest, 0.01 at
// 0.1 mm, is 2e-6 m).
inline constexpr double kDeltaRZero_m = 1e-9;

struct DeltaRFunction {
  std::vector<double> y_m;        // strictly increasing
  std::vector<double> delta_r_m;
  double operator()(double y) const;  // linear interpolation; throws outside the range
};

// The bottom of the potential well nearest y = 0: [low_m, high_m] (equal
// where delta_r crosses zero at a point). Throws std::invalid_argument when
// delta_r does not change sign from - to + within its range (no restoring).
struct KlingelEquilibrium {
  double low_m = 0, high_m = 0;
  double centre_m() const { return 0.5 * (low_m + high_m); }
};
KlingelEquilibrium klingel_equilibrium(const DeltaRFunction& delta_r);

struct ConicityPoint {
  double amplitude_m = 0;
  double wavelength_m = 0;           // +infinity where the conicity is 0
  double equivalent_conicity = 0;    // tan(gamma_e)
  double lower_turning_point_m = 0, upper_turning_point_m = 0;
};

// Throws std::invalid_argument (naming what is wrong) when delta_r has no
// equilibrium, when the motion at this amplitude leaves the sampled range of
// delta_r, or when no cycle has this amplitude (the half width jumps over it
// where the potential has a second well beyond a ridge).
ConicityPoint equivalent_conicity(const DeltaRFunction& delta_r, double amplitude_m,
                                  double half_contact_distance_m, double nominal_rolling_radius_m);

}  // namespace railstab
