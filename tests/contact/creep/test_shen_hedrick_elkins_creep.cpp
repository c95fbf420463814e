// Shen-Hedrick-Elkins and linear Kalker creep laws: the linear limit (values
// and the AD Jacobian at zero creepage), saturation at mu N, the
// Johnson-Vermeulen cubic and its C2 junction at u = 3, monotonicity, AD
// against central differences, parameter sensitivities, bad input.
#include <railstab/contact/creep/linear_kalker_creep.hpp>
#include <railstab/contact/creep/shen_hedrick_elkins_creep.hpp>
#include "creep_test_contact.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

using namespace railstab;
using namespace railstab::creep_test;

namespace {

// Creepage directions (sx, sy, phi per unit creepage); phi in 1/m.
const std::vector<Eigen::Vector3d> kDirections = {
    {1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 100.0}, {0.6, -0.8, 0.0}, {-0.3, 0.5, 2.0}};

CreepInput<double> along(const Eigen::Vector3d& dir, double t) {
  return contact(t * dir.x(), t * dir.y(), t * dir.z());
}

double magnitude_xy(const CreepForces<double>& f) { return std::hypot(f.force_x_N, f.force_y_N); }

}  // namespace

TEST(LinearKalkerCreep, EqualsKalkerFormulasTimesReductionFactor) {
  LinearKalkerCreep<double> law{0.7};
  for (const auto& dir : kDirections) {
    const CreepInput<double> in = along(dir, 3e-3);
    const Eigen::Vector3d expected =
        kalker_jacobian(in, 0.7) * Eigen::Vector3d(in.creep_x, in.creep_y, in.creep_spin_per_m);
    EXPECT_LT((as_vector(law.forces(in)) - expected).norm(), 1e-12 * expected.norm());
    const Jacobian J = ad_jacobian(law, in);
    EXPECT_LT((J.leftCols<3>() - kalker_jacobian(in, 0.7)).norm(),
              1e-15 * kalker_jacobian(in, 0.7).norm());
    EXPECT_EQ(J.col(3).norm(), 0.0);  // no dependence on the normal force
  }
}

// At |creepage| = 1e-9 (spin 1e-7 1/m) the saturation factor is
// e = 1 - u_r/3 + ... with u ~ 3e-7: forces within 1e-6 of Kalker's, and the
// deviation is the known first-order term u_r/3 (to 1 %), u_r = u^2/sqrt(u^2 + d^2).
TEST(ShenHedrickElkinsCreep, SmallCreepageIsLinearKalker) {
  const ShenHedrickElkinsCreep<double> law{0.4, 0.8};
  for (const auto& dir : kDirections) {
    const CreepInput<double> in = along(dir, 1e-9);
    const CreepForces<double> lin = LinearKalkerCreep<double>{0.8}.forces(in);
    const CreepForces<double> f = law.forces(in);
    const double u = magnitude_xy(lin) / (0.4 * kLoad_N);
    const double deviation = (as_vector(f) - as_vector(lin)).norm() / as_vector(lin).norm();
    EXPECT_LT(deviation, 1e-6);
    const double d = ShenHedrickElkinsCreep<double>::kResultantRegularisation;
    const double u_r = u * u / std::sqrt(u * u + d * d);
    EXPECT_NEAR(deviation, u_r / 3.0, 0.01 * u_r / 3.0) << "direction " << dir.transpose();
  }
}

// The linearisation sees exactly r times Kalker's coefficients at zero.
TEST(ShenHedrickElkinsCreep, JacobianAtZeroCreepageIsKalkerTimesReduction) {
  const ShenHedrickElkinsCreep<double> law{0.4, 0.8};
  const CreepInput<double> in = contact(0.0, 0.0, 0.0);
  const Jacobian J = ad_jacobian(law, in);
  ASSERT_TRUE(J.allFinite());
  const Eigen::Matrix3d K = kalker_jacobian(in, 0.8);
  EXPECT_LT((J.leftCols<3>() - K).norm(), 1e-9 * K.norm());
  EXPECT_EQ(J.col(3).norm(), 0.0);
}

// Beyond u = 3 the resultant is mu N (to round-off), at |creepage| = 0.1 in
// every direction (spin 10 1/m on the pure-spin ray; u = 7..30 here) and just
// past u = 3.
TEST(ShenHedrickElkinsCreep, SaturatesAtMuN) {
  const double mu = 0.35;
  const ShenHedrickElkinsCreep<double> law{mu, 1.0};
  for (const auto& dir : kDirections) {
    const CreepInput<double> in = along(dir, 0.1);
    EXPECT_GT(magnitude_xy(LinearKalkerCreep<double>{}.forces(in)), 3.0 * mu * kLoad_N);
    EXPECT_NEAR(magnitude_xy(law.forces(in)) / (mu * kLoad_N), 1.0, 1e-14);
  }
  // Just past u = 3 on the x axis: t3 = 3 mu N / f11.
  const double t3 = 3.0 * mu * kLoad_N / contact(0, 0, 0).f11_N;
  EXPECT_NEAR(magnitude_xy(law.forces(contact(1.001 * t3, 0, 0))) / (mu * kLoad_N), 1.0, 1e-14);
}

// Below u = 3: |F| / (mu N) = 1 - (1 - u/3)^3 (Johnson-Vermeulen), with u
// from the linear force. The deficit at u = 3 - du is (du/3)^3: value, slope
// and curvature of |F| are continuous at u = 3 (C2), as SHE intended.
TEST(ShenHedrickElkinsCreep, JohnsonVermeulenCubicWithC2Junction) {
  const double mu = 0.4;
  const ShenHedrickElkinsCreep<double> law{mu, 1.0};
  const double f11 = contact(0, 0, 0).f11_N;
  for (double u : {0.01, 0.5, 1.0, 2.0, 2.9, 2.97, 2.997}) {
    const double t = u * mu * kLoad_N / f11;  // pure longitudinal creepage
    const double ratio = magnitude_xy(law.forces(contact(t, 0, 0))) / (mu * kLoad_N);
    EXPECT_NEAR(ratio, 1.0 - std::pow(1.0 - u / 3.0, 3), 2e-9) << "u = " << u;
    EXPECT_NEAR(1.0 - ratio, std::pow((3.0 - u) / 3.0, 3), 2e-9) << "u = " << u;
  }
  // AD slope d|F|/du: 3 (1 - u/3)^2 / 3 * mu N... i.e. mu N (1 - u/3)^2 below,
  // 0 above; continuous at u = 3.
  for (double u : {1.5, 2.999, 3.001}) {
    const double t = u * mu * kLoad_N / f11;
    const CreepForces<AdScalar> f = law.forces(seeded(contact(t, 0, 0)));
    const double dF_du = -f.force_x_N.derivatives()(0) * mu * kLoad_N / f11;
    const double expected = u < 3.0 ? mu * kLoad_N * std::pow(1.0 - u / 3.0, 2) : 0.0;
    EXPECT_NEAR(dF_du, expected, 1e-9 * mu * kLoad_N) << "u = " << u;
  }
}

// |F| grows monotonically with the creepage along every ray (constant mu).
TEST(ShenHedrickElkinsCreep, ForceCreepCurveIsMonotonic) {
  const ShenHedrickElkinsCreep<double> law{0.4, 1.0};
  for (const auto& dir : kDirections) {
    double previous = -1.0;
    for (int k = 0; k <= 300; ++k) {
      const double t = 1e-7 * std::pow(10.0, 7.0 * k / 300.0);  // 1e-7 .. 1
      const double F = magnitude_xy(law.forces(along(dir, t)));
      EXPECT_GE(F, previous * (1.0 - 1e-12)) << "t = " << t;
      previous = F;
    }
  }
}

// AD Jacobian (creepages and normal force) against central differences, at
// small, mid, near-saturation (u = 2.9 and 3.1) and saturated points.
TEST(ShenHedrickElkinsCreep, AdJacobianMatchesCentralDifferences) {
  const double mu = 0.4;
  const ShenHedrickElkinsCreep<double> law{mu, 0.9};
  const double f11 = contact(0, 0, 0).f11_N;
  std::vector<CreepInput<double>> points = {contact(2e-4, -1e-4, 0.05), contact(1e-3, 2e-3, -0.3),
                                            contact(0.02, -0.01, 0.4)};
  for (double u : {2.9, 3.1}) {
    const double t = u * mu * kLoad_N / (0.9 * f11);
    points.push_back(contact(t * 0.8, t * 0.6 * f11 / contact(0, 0, 0).f22_N, 0.0));
  }
  for (const auto& in : points) {
    const Jacobian ad = ad_jacobian(law, in), cd = central_difference_jacobian(law, in);
    EXPECT_LT(jacobian_mismatch(ad, cd), 1e-6) << "AD\n" << ad << "\nCD\n" << cd;
  }
}

// S = AdScalar: the derivative with respect to the friction coefficient.
TEST(ShenHedrickElkinsCreep, FrictionSensitivityMatchesCentralDifference) {
  const CreepInput<double> in = contact(4e-3, 1e-3, 0.2);
  ShenHedrickElkinsCreep<AdScalar> law{AdScalar(0.4, AdDerivatives::Unit(5)), constant<AdScalar>(1.0)};
  const CreepForces<AdScalar> f = law.forces(seeded(in));
  const double h = 6e-6 * 0.4;
  const auto at = [&](double mu) {
    return as_vector(ShenHedrickElkinsCreep<double>{mu, 1.0}.forces(in));
  };
  const Eigen::Vector3d cd = (at(0.4 + h) - at(0.4 - h)) / (2 * h);
  const Eigen::Vector3d ad(f.force_x_N.derivatives()(5), f.force_y_N.derivatives()(5),
                           f.spin_moment_N_m.derivatives()(5));
  EXPECT_GT(cd.norm(), 1e3);  // saturating here: mu matters
  EXPECT_LT((ad - cd).norm(), 1e-7 * cd.norm());
  // cast<double>() of the AD parameters gives the same values.
  EXPECT_EQ(law.cast<double>().friction_coefficient, 0.4);
}

TEST(ShenHedrickElkinsCreep, ZeroNormalForceGivesZeroForces) {
  CreepInput<double> in = contact(1e-3, 1e-3, 0.1);
  in.normal_force_N = 0.0;
  EXPECT_EQ(as_vector(ShenHedrickElkinsCreep<double>{}.forces(in)).norm(), 0.0);
}

TEST(ShenHedrickElkinsCreep, BadInputNamesTheField) {
  const auto message = [](auto&& f) { return error_message(f); };
  EXPECT_NE(message([] { ShenHedrickElkinsCreep<double>{-0.1, 1.0}.forces(contact(0, 0, 0)); })
                .find("friction_coefficient"),
            std::string::npos);
  EXPECT_NE(message([] { ShenHedrickElkinsCreep<double>{0.4, 1.5}.forces(contact(0, 0, 0)); })
                .find("kalker_reduction_factor"),
            std::string::npos);
  EXPECT_NE(message([] { ShenHedrickElkinsCreep<double>{}.forces(contact(NAN, 0, 0)); })
                .find("creep_x"),
            std::string::npos);
  CreepInput<double> in = contact(0, 0, 0);
  in.normal_force_N = -1.0;
  EXPECT_NE(message([&] { ShenHedrickElkinsCreep<double>{}.forces(in); }).find("normal_force_N"),
            std::string::npos);
  EXPECT_THROW(LinearKalkerCreep<double>{0.0}.forces(contact(0, 0, 0)), std::invalid_argument);
}
