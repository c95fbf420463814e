// Polach creep law: the (reduced) Kalker limit in values and in the AD
// Jacobian at zero creepage, the published formulas as an oracle (c11 = c22,
// where the Kalker-directed form of this code coincides with Polach's),
// saturation at mu N and at A mu0 N, monotonicity without friction decrease
// and the adhesion optimum with it, AD against central differences, parameter
// sensitivities, bad input.
#include <railstab/contact/creep/polach_creep.hpp>
#include "creep_test_contact.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

using namespace railstab;
using namespace railstab::creep_test;

namespace {

constexpr double kPi = std::numbers::pi;

PolachCreep<double> polach(double mu0, double A, double B, double kA, double kS, double r) {
  return PolachCreep<double>{mu0, A, B, kA, kS, r};
}

double magnitude_xy(const CreepForces<double>& f) { return std::hypot(f.force_x_N, f.force_y_N); }

// Polach's formulas as published (1999 with spin, 2005 with k_A, k_S and
// falling friction), in his notation, hard switch for s_yC, forces along the
// creepage; Kalker's c11 = c22 taken from f11. Returns (Fx, Fy) on the wheel.
Eigen::Vector2d published_polach(const CreepInput<double>& in, const PolachCreep<double>& p) {
  const double Q = in.normal_force_N, a = in.semi_axis_a_m, b = in.semi_axis_b_m;
  const double sx = in.creep_x, sy = in.creep_y, psi = in.creep_spin_per_m;
  const double syC = std::abs(sy + psi * a) > std::abs(sy) ? sy + psi * a : sy;
  const double sC = std::hypot(sx, syC);
  const double w = in.speed_m_per_s * sC;
  const double f = p.friction_coefficient * ((1.0 - p.limit_friction_ratio) *
                                                 std::exp(-p.friction_decrease_rate_s_per_m * w) +
                                             p.limit_friction_ratio);
  const double r = p.kalker_reduction_factor;
  const double C = 3.0 / 8.0 * r * in.f11_N / (a * a * b);  // (3/8) G c11 / a, G a b c11 = f11
  const double eps = 2.0 / 3.0 * C * kPi * a * a * b * sC / (Q * f);
  const double kA = p.adhesion_reduction_factor, kS = p.slip_reduction_factor;
  const double F = 2.0 * Q * f / kPi * (kA * eps / (1.0 + kA * kA * eps * eps) + std::atan(kS * eps));
  const double KS = 1.0 + 6.3 * (1.0 - std::exp(-a / b));
  const double epsM = 8.0 / 3.0 * (r * in.f23_N_m / a) * sC / (Q * f * KS);  // G b sqrt(ab) c23 = f23/a
  const double d = (epsM * epsM - 1.0) / (epsM * epsM + 1.0);
  const double KM = std::abs(epsM) * (d * d * d / 3.0 - d * d / 2.0 + 1.0 / 6.0) -
                    std::sqrt(std::pow(1.0 - d * d, 3)) / 3.0;
  const double FyS = -9.0 / 16.0 * a * Q * f * KM * KS * psi / sC;  // Polach's orientation
  return {-F * sx / sC, -(F * sy / sC + FyS)};
}

}  // namespace

TEST(PolachCreep, PublishedFormulasAreReproducedWhenC11EqualsC22) {
  const std::vector<Eigen::Vector3d> points = {
      {1e-3, 0.0, 0.0},   {2e-3, -1e-3, 0.1}, {5e-3, 2e-3, -0.5}, {0.02, 0.01, 1.0},
      {0.0, 0.0, 0.5},    {1e-4, 3e-3, -2.0}, {-0.3, 0.1, 3.0},   {4e-4, -2e-4, 0.02}};
  for (const PolachCreep<double>& law :
       {polach(0.55, 1.0, 0.6, 1.0, 1.0, 1.0), polach(0.55, 0.4, 0.6, 1.0, 0.4, 1.0),
        polach(0.3, 0.4, 0.2, 0.3, 0.1, 0.8)}) {
    for (const auto& p : points) {
      CreepInput<double> in = contact(p.x(), p.y(), p.z());
      in.f22_N = in.f11_N;
      const CreepForces<double> f = law.forces(in);
      const Eigen::Vector2d expected = published_polach(in, law);
      // Falling friction: the regularised slip velocity is low by
      // w0^2/(2w) <= 1e-10 m/s here (w >= 6 mm/s), so mu is high by < 1e-10.
      const double tol = law.limit_friction_ratio < 1.0 ? 1e-9 : 1e-12;
      EXPECT_NEAR(f.force_x_N, expected.x(), tol * expected.norm()) << p.transpose();
      EXPECT_NEAR(f.force_y_N, expected.y(), tol * expected.norm()) << p.transpose();
    }
  }
}

// At |creepage| = 1e-7 (eps ~ 2e-5): Fx, Fy(xi_y) are (k_A + k_S)/2 r Kalker,
// the spin terms r Kalker, to 1e-6 relative.
TEST(PolachCreep, SmallCreepageIsReducedKalker) {
  const PolachCreep<double> law = polach(0.55, 0.4, 0.6, 1.0, 0.4, 0.9);
  const double R0 = 0.7;
  for (const Eigen::Vector3d& dir : {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0),
                                    Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0.6, -0.8, 3.0)}) {
    const CreepInput<double> in = contact(1e-7 * dir.x(), 1e-7 * dir.y(), 1e-7 * dir.z());
    const double r = 0.9;
    const Eigen::Vector3d expected(-r * R0 * in.f11_N * in.creep_x,
                                   -r * R0 * in.f22_N * in.creep_y - r * in.f23_N_m * in.creep_spin_per_m,
                                   r * (in.f23_N_m * in.creep_y - in.f33_N_m2 * in.creep_spin_per_m));
    EXPECT_LT((as_vector(law.forces(in)) - expected).norm(), 1e-6 * expected.norm())
        << dir.transpose();
  }
}

TEST(PolachCreep, JacobianAtZeroCreepageIsReducedKalker) {
  for (const PolachCreep<double>& law :
       {polach(0.55, 0.4, 0.6, 1.0, 0.4, 0.9), polach(0.55, 1.0, 0.0, 1.0, 1.0, 1.0)}) {
    const CreepInput<double> in = contact(0.0, 0.0, 0.0);
    const Jacobian J = ad_jacobian(law, in);
    ASSERT_TRUE(J.allFinite());
    const double r = law.kalker_reduction_factor;
    const double R0 = 0.5 * (law.adhesion_reduction_factor + law.slip_reduction_factor);
    Eigen::Matrix3d K = kalker_jacobian(in, r);
    K(0, 0) *= R0;
    K(1, 1) *= R0;
    EXPECT_LT((J.leftCols<3>() - K).norm(), 1e-9 * K.norm()) << J;
    EXPECT_EQ(J.col(3).norm(), 0.0);
  }
}

// Without friction decrease |F| -> mu N: bounded by
// 1 - 2/(pi k_S eps) <= |F|/(mu N) <= 1 (atan z >= pi/2 - 1/z); with
// k_A = k_S = 1 the deficit is (2/pi)(2/3)/eps^3 + O(eps^-5).
TEST(PolachCreep, TendsToMuNWithoutFrictionDecrease) {
  const double mu = 0.55;
  for (const Eigen::Vector2d& dir : {Eigen::Vector2d(1, 0), Eigen::Vector2d(0, 1),
                                    Eigen::Vector2d(0.6, -0.8)}) {
    for (double t : {0.1, 1.0}) {
      const CreepInput<double> in = contact(t * dir.x(), t * dir.y(), 0.0);
      const double eps = kPi / 4.0 * std::hypot(in.f11_N * in.creep_x, in.f22_N * in.creep_y) /
                         (mu * kLoad_N);
      const double dry = magnitude_xy(polach(mu, 1.0, 0.6, 1.0, 0.4, 1.0).forces(in)) / (mu * kLoad_N);
      EXPECT_LE(dry, 1.0);
      EXPECT_GE(dry, 1.0 - 2.0 / (kPi * 0.4 * eps));
      const double full = magnitude_xy(polach(mu, 1.0, 0.6, 1.0, 1.0, 1.0).forces(in)) / (mu * kLoad_N);
      EXPECT_NEAR(1.0 - full, 4.0 / (3.0 * kPi * eps * eps * eps), 0.01 * 4.0 / (3.0 * kPi * eps * eps * eps) + 1e-15)
          << "t = " << t;
    }
  }
}

// With A < 1, at slip velocity 30 m/s (creepage 1 at 30 m/s) mu = A mu0
// (exp(-18) ~ 1.5e-8 left): |F| -> A mu0 N.
TEST(PolachCreep, TendsToLimitFrictionAtHighSlipVelocity) {
  const PolachCreep<double> law = polach(0.55, 0.4, 0.6, 1.0, 1.0, 1.0);
  for (const Eigen::Vector2d& dir : {Eigen::Vector2d(1, 0), Eigen::Vector2d(0, 1)}) {
    const CreepInput<double> in = contact(dir.x(), dir.y(), 0.0);
    EXPECT_NEAR(magnitude_xy(law.forces(in)) / (0.4 * 0.55 * kLoad_N), 1.0, 1e-6);
  }
}

// Constant friction: |F| increases along every creepage ray (dry and wet
// 2005 sets, k_S < k_A). With friction decrease (dry set, 30 m/s) the curve
// has an interior maximum, the adhesion optimum, and falls towards A mu0 N.
TEST(PolachCreep, MonotonicWithoutFrictionDecreaseAndAdhesionOptimumWithIt) {
  for (const PolachCreep<double>& law :
       {polach(0.55, 1.0, 0.6, 1.0, 0.4, 1.0), polach(0.30, 1.0, 0.2, 0.3, 0.1, 1.0)}) {
    for (const Eigen::Vector2d& dir : {Eigen::Vector2d(1, 0), Eigen::Vector2d(0, 1),
                                      Eigen::Vector2d(0.6, -0.8)}) {
      double previous = -1.0;
      for (int k = 0; k <= 300; ++k) {
        const double t = 1e-7 * std::pow(10.0, 7.0 * k / 300.0);
        const double F = magnitude_xy(law.forces(contact(t * dir.x(), t * dir.y(), 0.0)));
        EXPECT_GT(F, previous) << "t = " << t;
        previous = F;
      }
    }
  }
  const PolachCreep<double> falling = polach(0.55, 0.4, 0.6, 1.0, 0.4, 1.0);
  double best = 0.0, best_t = 0.0, last = 0.0;
  for (int k = 0; k <= 300; ++k) {
    const double t = 1e-5 * std::pow(10.0, 5.0 * k / 300.0);  // 1e-5 .. 1
    last = magnitude_xy(falling.forces(contact(t, 0.0, 0.0)));
    if (last > best) best = last, best_t = t;
  }
  EXPECT_GT(best_t, 1e-3);
  EXPECT_LT(best_t, 0.1);
  EXPECT_GT(best / (0.55 * kLoad_N), 0.6);                    // optimum near mu0 N
  EXPECT_NEAR(last / (0.55 * kLoad_N), 0.4, 0.01);           // falls to A mu0 N at 30 m/s
}

TEST(PolachCreep, AdJacobianMatchesCentralDifferences) {
  const std::vector<CreepInput<double>> points = {
      contact(2e-4, -1e-4, 0.05), contact(1e-3, 2e-3, -0.3), contact(5e-3, 1e-3, 0.4),
      contact(0.02, -0.01, 0.8),  contact(-0.1, 0.05, 2.0),  contact(1e-3, 0.0, 0.5)};
  for (const PolachCreep<double>& law :
       {polach(0.55, 0.4, 0.6, 1.0, 0.4, 0.9), polach(0.55, 1.0, 0.6, 1.0, 1.0, 1.0)})
    for (const auto& in : points) {
      const Jacobian ad = ad_jacobian(law, in), cd = central_difference_jacobian(law, in);
      EXPECT_LT(jacobian_mismatch(ad, cd), 1e-6) << "AD\n" << ad << "\nCD\n" << cd;
    }
}

// S = AdScalar: sensitivities to mu0, A, B, k_A, k_S against central differences.
TEST(PolachCreep, ParameterSensitivitiesMatchCentralDifferences) {
  const CreepInput<double> in = contact(6e-3, 2e-3, 0.3);
  const std::array<double, 5> p0 = {0.55, 0.4, 0.6, 0.9, 0.4};
  PolachCreep<AdScalar> law;
  AdScalar* fields[5] = {&law.friction_coefficient, &law.limit_friction_ratio,
                         &law.friction_decrease_rate_s_per_m, &law.adhesion_reduction_factor,
                         &law.slip_reduction_factor};
  for (int i = 0; i < 5; ++i) *fields[i] = AdScalar(p0[i], AdDerivatives::Unit(5 + i));
  law.kalker_reduction_factor = constant<AdScalar>(1.0);
  const CreepForces<AdScalar> f = law.forces(seeded(in));
  for (int i = 0; i < 5; ++i) {
    const double h = 6e-6 * p0[i];
    std::array<double, 5> plus = p0, minus = p0;
    plus[i] += h;
    minus[i] -= h;
    const auto at = [&](const std::array<double, 5>& p) {
      return as_vector(polach(p[0], p[1], p[2], p[3], p[4], 1.0).forces(in));
    };
    const Eigen::Vector3d cd = (at(plus) - at(minus)) / (2.0 * h);
    const Eigen::Vector3d ad(f.force_x_N.derivatives()(5 + i), f.force_y_N.derivatives()(5 + i),
                             f.spin_moment_N_m.derivatives()(5 + i));
    EXPECT_GT(cd.norm(), 1.0) << "parameter " << i;
    EXPECT_LT((ad - cd).norm(), 1e-6 * cd.norm()) << "parameter " << i << "\nAD " << ad.transpose()
                                                  << "\nCD " << cd.transpose();
  }
  const PolachCreep<double> back = law.cast<double>();
  EXPECT_EQ(back.slip_reduction_factor, 0.4);
}

TEST(PolachCreep, ZeroNormalForceGivesZeroForces) {
  CreepInput<double> in = contact(1e-3, 1e-3, 0.1);
  in.normal_force_N = 0.0;
  EXPECT_EQ(as_vector(PolachCreep<double>{}.forces(in)).norm(), 0.0);
}

TEST(PolachCreep, BadInputNamesTheField) {
  const auto message = [](auto&& f) { return error_message(f); };
  const CreepInput<double> in = contact(1e-3, 0, 0);
  EXPECT_NE(message([&] { polach(0.55, 0.4, 0.6, 0.3, 0.4, 1.0).forces(in); })
                .find("slip_reduction_factor"),
            std::string::npos);
  EXPECT_NE(message([&] { polach(0.55, 1.2, 0.6, 1.0, 0.4, 1.0).forces(in); })
                .find("limit_friction_ratio"),
            std::string::npos);
  EXPECT_NE(message([&] { polach(0.55, 0.4, -1.0, 1.0, 0.4, 1.0).forces(in); })
                .find("friction_decrease_rate_s_per_m"),
            std::string::npos);
  CreepInput<double> flat = in;
  flat.semi_axis_a_m = 0.0;
  EXPECT_NE(message([&] { PolachCreep<double>{}.forces(flat); }).find("semi_axis_a_m"),
            std::string::npos);
  CreepInput<double> inf_speed = in;
  inf_speed.speed_m_per_s = INFINITY;
  EXPECT_NE(message([&] { PolachCreep<double>{}.forces(inf_speed); }).find("speed_m_per_s"),
            std::string::npos);
}
