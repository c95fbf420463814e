#pragma once
// A realistic wheel-rail contact for the creep-law tests: 80 kN wheel load,
// ellipse a = 6 mm, b = 4 mm, steel (G = 8.4e10 Pa, nu = 0.25), Kalker
// coefficients from contact/kalker.hpp. Helpers seed AD directions on the
// creepages and compare Jacobians.
#include <railstab/contact/creep/creep_input.hpp>
#include <railstab/contact/kalker.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace railstab::creep_test {

inline constexpr double kLoad_N = 8.0e4;
inline constexpr double kSemiA_m = 6.0e-3, kSemiB_m = 4.0e-3;
inline constexpr double kShear_Pa = 8.4e10, kPoisson = 0.25;
inline constexpr double kSpeed_m_per_s = 30.0;

inline CreepInput<double> contact(double sx, double sy, double phi_per_m) {
  const CreepCoefficients<double> f = kalker_coefficients(kSemiA_m, kSemiB_m, kShear_Pa, kPoisson);
  CreepInput<double> in;
  in.creep_x = sx;
  in.creep_y = sy;
  in.creep_spin_per_m = phi_per_m;
  in.normal_force_N = kLoad_N;
  in.semi_axis_a_m = kSemiA_m;
  in.semi_axis_b_m = kSemiB_m;
  in.f11_N = f.f11_N;
  in.f22_N = f.f22_N;
  in.f23_N_m = f.f23_N_m;
  in.f33_N_m2 = f.f33_N_m2;
  in.speed_m_per_s = kSpeed_m_per_s;
  return in;
}

// AD copy of a double input: directions 0, 1, 2, 3 on creep_x, creep_y,
// creep_spin_per_m, normal_force_N.
inline CreepInput<AdScalar> seeded(const CreepInput<double>& in) {
  const auto c = [](double x) { return constant<AdScalar>(x); };
  const auto d = [](double x, int i) { return AdScalar(x, AdDerivatives::Unit(i)); };
  CreepInput<AdScalar> out;
  out.creep_x = d(in.creep_x, 0);
  out.creep_y = d(in.creep_y, 1);
  out.creep_spin_per_m = d(in.creep_spin_per_m, 2);
  out.normal_force_N = d(in.normal_force_N, 3);
  out.semi_axis_a_m = c(in.semi_axis_a_m);
  out.semi_axis_b_m = c(in.semi_axis_b_m);
  out.f11_N = c(in.f11_N);
  out.f22_N = c(in.f22_N);
  out.f23_N_m = c(in.f23_N_m);
  out.f33_N_m2 = c(in.f33_N_m2);
  out.speed_m_per_s = c(in.speed_m_per_s);
  return out;
}

using Jacobian = Eigen::Matrix<double, 3, 4>;  // rows Fx, Fy, Mz; columns sx, sy, phi, N

inline Eigen::Vector3d as_vector(const CreepForces<double>& f) {
  return {f.force_x_N, f.force_y_N, f.spin_moment_N_m};
}

template <class Law> Jacobian ad_jacobian(const Law& law, const CreepInput<double>& in) {
  const CreepForces<AdScalar> f = law.forces(seeded(in));
  Jacobian J;
  J.row(0) = f.force_x_N.derivatives().head<4>().transpose();
  J.row(1) = f.force_y_N.derivatives().head<4>().transpose();
  J.row(2) = f.spin_moment_N_m.derivatives().head<4>().transpose();
  return J;
}

// Central differences with step h_j = 6e-6 (~cbrt(eps)) times a scale per column.
template <class Law> Jacobian central_difference_jacobian(const Law& law, const CreepInput<double>& in) {
  const std::array<double, 4> scale = {1e-3, 1e-3, 1e-1, kLoad_N};
  Jacobian J;
  for (int j = 0; j < 4; ++j) {
    const double h = 6e-6 * scale[j];
    CreepInput<double> plus = in, minus = in;
    double* p[4] = {&plus.creep_x, &plus.creep_y, &plus.creep_spin_per_m, &plus.normal_force_N};
    double* m[4] = {&minus.creep_x, &minus.creep_y, &minus.creep_spin_per_m,
                    &minus.normal_force_N};
    *p[j] += h;
    *m[j] -= h;
    J.col(j) = (as_vector(law.forces(plus)) - as_vector(law.forces(minus))) / (2.0 * h);
  }
  return J;
}

// Largest row-wise relative mismatch of two Jacobians, columns scaled by the
// typical size of their variable (creepage 1e-3, spin 0.1 1/m, load kLoad_N).
inline double jacobian_mismatch(const Jacobian& ad, const Jacobian& cd) {
  const Eigen::Vector4d scale(1e-3, 1e-3, 1e-1, kLoad_N);
  const Jacobian a = ad * scale.asDiagonal(), c = cd * scale.asDiagonal();
  double worst = 0.0;
  for (int i = 0; i < 3; ++i)
    worst = std::max(worst, (a.row(i) - c.row(i)).norm() / std::max(a.row(i).norm(), 1e-9));
  return worst;
}

// Linear Kalker Jacobian with respect to (sx, sy, phi), scaled by r.
inline Eigen::Matrix3d kalker_jacobian(const CreepInput<double>& in, double r) {
  Eigen::Matrix3d K;
  K << -in.f11_N, 0.0, 0.0,  //
      0.0, -in.f22_N, -in.f23_N_m,  //
      0.0, in.f23_N_m, -in.f33_N_m2;
  return r * K;
}

// The message of what f() throws, or "no throw".
template <class F> std::string error_message(F&& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return std::string(e.what());
  }
  return std::string("no throw");
}

}  // namespace railstab::creep_test
