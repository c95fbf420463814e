#pragma once
// One-sided power spectral densities of track irregularities, S(Omega) in
// m^2/(rad/m) over the spatial angular frequency Omega = 2 pi / wavelength
// (rad/m), so that the variance is the integral of S over Omega > 0.
// Formulas and parameters: docs/irregular_track.md (sources cited there).
//
// ERRI B176 (ORE B176, low and high level; Omega_c 0.8246, Omega_r 0.0206,
// Omega_s 0.438 rad/m, b 0.75 m):
//   alignment  A_a Omega_c^2 / ((Omega^2 + Omega_r^2)(Omega^2 + Omega_c^2))
//   level      A_v Omega_c^2 / ((Omega^2 + Omega_r^2)(Omega^2 + Omega_c^2))
//   cross level (as z_left - z_right = 2 b phi)
//              4 A_v Omega_c^2 Omega^2 / ((..r)(..c)(Omega^2 + Omega_s^2))
//   gauge      A_g Omega_c^2 Omega^2 / ((..r)(..c)(Omega^2 + Omega_s^2))
// FRA classes (k = 0.25, Omega_c 0.8245 rad/m, A in m^2 rad/m):
//   alignment  k A_a Omega_c^2 / (Omega^2 (Omega^2 + Omega_c^2))
//   level      k A_v Omega_c^2 / (Omega^2 (Omega^2 + Omega_c^2))
//   cross level 4 k A_v Omega_c^2 / ((Omega^2 + Omega_c^2)(Omega^2 + Omega_s^2))
//   gauge      none published here: zero.
#include <railstab/irregularity/irregularity_spec.hpp>

namespace railstab {

double irregularity_psd_m2_per_rad_per_m(IrregularitySpectrum spectrum, IrregularityChannel channel,
                                         double omega_rad_per_m);

// The integral of the PSD from omega1 to omega2 (closed form, m^2).
double irregularity_band_variance_m2(IrregularitySpectrum spectrum, IrregularityChannel channel,
                                     double omega1_rad_per_m, double omega2_rad_per_m);

}  // namespace railstab
