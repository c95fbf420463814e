#pragma once
// Analytic wheel and rail profiles for closed-form checks of the contact
// geometry (profile frame of profiles/profile.hpp: y outward, z up, metres).
#include <railstab/profiles/profile_pair.hpp>
#include <railstab/profiles/profile_validation.hpp>

#include <cmath>
#include <functional>

namespace railstab::testing {

inline Profile sampled_profile(ProfileKind kind, const std::string& name, double y0, double y1,
                               double step, const std::function<double(double)>& z) {
  std::vector<RawProfilePoint> pts;
  const int n = int(std::lround((y1 - y0) / step));
  for (int i = 0; i <= n; ++i) {
    const double y = y0 + (y1 - y0) * i / n;
    pts.push_back({y, z(y), i + 1});
  }
  return make_profile(kind, name, std::move(pts));
}

// Cone of slope t = tan(gamma): z_w(u) = t u, the radius r0 - t u shrinks outward.
inline Profile cone_wheel(double t) {
  return sampled_profile(ProfileKind::wheel, "cone", -0.040, 0.060, 2e-4,
                         [t](double u) { return t * u; });
}

// Convex circular rail head of radius R, top at (0, 0): z = sqrt(R^2 - y^2) - R.
inline Profile circular_rail(double R, double half_width) {
  return sampled_profile(ProfileKind::rail, "circular rail", -half_width, half_width, 2e-4,
                         [R](double y) { return std::sqrt(R * R - y * y) - R; });
}

// Hollow (concave) circular wheel tread of radius Rw whose centre lies at
// lateral u_c below the tread: z = z0 + sqrt(Rw^2 - (u - u_c)^2) - Rw, z(0) = 0.
inline double hollow_wheel_z0(double Rw, double uc) { return Rw - std::sqrt(Rw * Rw - uc * uc); }
inline Profile hollow_wheel(double Rw, double uc) {
  const double z0 = hollow_wheel_z0(Rw, uc);
  return sampled_profile(ProfileKind::wheel, "hollow wheel", -0.040, 0.060, 2e-4,
                         [=](double u) { return z0 + std::sqrt(Rw * Rw - (u - uc) * (u - uc)) - Rw; });
}

}  // namespace railstab::testing
