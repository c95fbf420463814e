// Rigid-contact characteristic functions against closed forms: a cone on a
// circular rail head (tangency of a line and a circle), a hollow circular
// wheel on a circular rail (internal tangency of two circles), symmetry of a
// symmetric pair, and the S1002/UIC60 1:40 flange contact of the Manchester
// benchmark.
#include <railstab/contact_geometry/characteristic_functions.hpp>
#include <railstab/contact_geometry/wheelset_pose.hpp>
#include "contact_geometry/synthetic_profiles.hpp"
#include <railstab/profiles/profile_readers.hpp>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>
#include "support/benchmark_profiles.hpp"

using namespace railstab;
using namespace railstab::testing;

namespace {

// Rail placement for an analytic rail whose gauge point (2 mm below the
// top) sits at y_g: the gauge that centres the wheel profile origin over the
// rail profile origin (nominal wheel lateral 0).
ProfilePairParameters centred_parameters(double y_g) {
  ProfilePairParameters p;
  p.gauge_measuring_height_m = 0.002;
  p.track_gauge_m = 2.0 * (0.5 * p.flange_back_distance_m + p.tape_circle_from_flange_back_m + y_g);
  return p;
}

// Independent oracle: solve the two contact conditions F(z, phi) = 0 (one per
// side, given as a function of that side's wheel pose) by Newton's method
// with a central-difference Jacobian.
template <class Condition>
Eigen::Vector2d solve_two_sides(const ProfilePair& pair, double y, Condition condition) {
  auto F = [&](const Eigen::Vector2d& x) {
    Eigen::Vector2d f;
    for (int k = 0; k < 2; ++k) {
      const int side = k == 0 ? +1 : -1;
      f(k) = condition(wheel_pose_in_rail_frame<double>(pair, side, y, x(0), x(1)));
    }
    return f;
  };
  Eigen::Vector2d x(pair.parameters.nominal_rolling_radius_m, 0.0);
  for (int it = 0; it < 50; ++it) {
    const Eigen::Vector2d f = F(x);
    Eigen::Matrix2d J;
    for (int c = 0; c < 2; ++c) {
      Eigen::Vector2d h = Eigen::Vector2d::Zero();
      h(c) = 1e-7;
      J.col(c) = (F(x + h) - F(x - h)) / 2e-7;
    }
    const Eigen::Vector2d dx = J.partialPivLu().solve(-f);
    x += dx;
    if (dx.norm() < 1e-15) break;
  }
  return x;
}

}  // namespace

// Cone (slope t) on a circular rail head of radius R, centre c = (0, -R):
// the wheel line through o with direction R(theta)(1, t) is tangent to the
// circle when (o - c) . n = R, n = R(theta)(-t, 1) / sqrt(1 + t^2); the
// contact is the circle point c + R n, at wheel coordinate
// u = [R(-theta)(P - o)]_y, radius r0 - t u.
TEST(CharacteristicFunctions, ConeOnCircularRailMatchesTangencyClosedForm) {
  const double t = 0.05, R = 0.3;
  const Profile rail = circular_rail(R, 0.040);
  const double y_g = -std::sqrt(R * R - (R - 0.002) * (R - 0.002));
  const ProfilePair pair = make_profile_pair(cone_wheel(t), rail, centred_parameters(y_g));
  const double r0 = pair.parameters.nominal_rolling_radius_m;
  auto normal = [&](double th) -> Eigen::Vector2d {
    return Eigen::Vector2d(-t * std::cos(th) - std::sin(th), -t * std::sin(th) + std::cos(th)) /
           std::sqrt(1 + t * t);
  };
  const Eigen::Vector2d c(0.0, -R);
  auto condition = [&](const WheelPoseOf<double>& p) {
    return (Eigen::Vector2d(p.lateral_m, p.vertical_m) - c).dot(normal(p.roll_rad)) - R;
  };
  auto radius = [&](const WheelPoseOf<double>& p) {
    const Eigen::Vector2d P = c + R * normal(p.roll_rad);
    const Eigen::Vector2d d = P - Eigen::Vector2d(p.lateral_m, p.vertical_m);
    const double u = std::cos(p.roll_rad) * d.x() + std::sin(p.roll_rad) * d.y();
    return r0 - t * u;
  };
  for (double y : {-0.008, -0.003, -0.0005, 0.001, 0.004, 0.009}) {
    SCOPED_TRACE(y);
    const Eigen::Vector2d zr = solve_two_sides(pair, y, condition);
    const double dr_exact = radius(wheel_pose_in_rail_frame<double>(pair, +1, y, zr(0), zr(1))) -
                            radius(wheel_pose_in_rail_frame<double>(pair, -1, y, zr(0), zr(1)));
    const RigidContactSolution s = solve_rigid_contact(pair, y);
    EXPECT_NEAR(s.roll_rad, zr(1), 1e-10);
    EXPECT_NEAR(s.vertical_m, zr(0), 1e-9);
    const double dr = s.left.front().rolling_radius_m - s.right.front().rolling_radius_m;
    EXPECT_NEAR(dr, dr_exact, 1e-9);
    // The contact angle of a cone is its slope plus the wheelset roll.
    EXPECT_NEAR(s.left.front().contact_angle_rad, std::atan(t) + s.roll_rad, 1e-7);
    EXPECT_NEAR(s.right.front().contact_angle_rad, std::atan(t) - s.roll_rad, 1e-7);
  }
}

// With the roll held at zero, a cone gives delta_r = 2 tan(gamma) y exactly,
// whatever the rail shape (both contact points shift by y on the wheels).
TEST(CharacteristicFunctions, ConeWithoutRollGivesTwiceTanGammaY) {
  const double t = 0.05, R = 0.3;
  const double y_g = -std::sqrt(R * R - (R - 0.002) * (R - 0.002));
  const ProfilePair pair =
      make_profile_pair(cone_wheel(t), circular_rail(R, 0.040), centred_parameters(y_g));
  for (double y : {-0.01, -0.004, 0.002, 0.007, 0.01}) {
    double r[2];
    for (int k = 0; k < 2; ++k) {
      const WheelPoseOf<double> p = wheel_pose_in_rail_frame<double>(pair, k ? -1 : 1, y, 0.0, 0.0);
      const auto c = find_contact_points(pair, WheelPose{p.lateral_m, p.vertical_m, p.roll_rad});
      ASSERT_EQ(c.size(), 1u);
      r[k] = c.front().rolling_radius_m;
    }
    EXPECT_NEAR(r[0] - r[1], 2 * t * y, 1e-10) << "y = " << y;
  }
}

// Hollow circular wheel tread (radius Rw, centre O_w below it) on a circular
// rail head (Rr < Rw, centre O_r): internal tangency |O_w - O_r| = Rw - Rr;
// the contact lies on the line of centres, e = (O_r - O_w)/(Rw - Rr) =
// (-sin gamma, cos gamma), at P = O_r + Rr e.
TEST(CharacteristicFunctions, HollowWheelOnCircularRailMatchesTwoCircleClosedForm) {
  const double Rw = 0.5, Rr = 0.3, uc = 0.015;
  const double z0 = hollow_wheel_z0(Rw, uc);
  const double y_g = -std::sqrt(Rr * Rr - (Rr - 0.002) * (Rr - 0.002));
  const ProfilePair pair =
      make_profile_pair(hollow_wheel(Rw, uc), circular_rail(Rr, 0.040), centred_parameters(y_g));
  const double r0 = pair.parameters.nominal_rolling_radius_m;
  const Eigen::Vector2d Or(0.0, -Rr);
  auto wheel_centre = [&](const WheelPoseOf<double>& p) {
    const double c = std::cos(p.roll_rad), s = std::sin(p.roll_rad);
    const Eigen::Vector2d local(uc, z0 - Rw);
    return Eigen::Vector2d(p.lateral_m + c * local.x() - s * local.y(),
                           p.vertical_m + s * local.x() + c * local.y());
  };
  auto condition = [&](const WheelPoseOf<double>& p) { return (wheel_centre(p) - Or).norm() - (Rw - Rr); };
  struct Exact { double gamma, radius; };
  auto exact = [&](const WheelPoseOf<double>& p) {
    const Eigen::Vector2d e = (Or - wheel_centre(p)) / (Rw - Rr);
    const Eigen::Vector2d P = Or + Rr * e;
    const Eigen::Vector2d d = P - Eigen::Vector2d(p.lateral_m, p.vertical_m);
    const double c = std::cos(p.roll_rad), s = std::sin(p.roll_rad);
    const double zw = -s * d.x() + c * d.y();  // wheel-frame height of P
    return Exact{std::atan2(-e.x(), e.y()), r0 - zw};
  };
  for (double y : {-0.006, -0.002, 0.0015, 0.005}) {
    SCOPED_TRACE(y);
    const Eigen::Vector2d zr = solve_two_sides(pair, y, condition);
    const Exact L = exact(wheel_pose_in_rail_frame<double>(pair, +1, y, zr(0), zr(1)));
    const Exact Rt = exact(wheel_pose_in_rail_frame<double>(pair, -1, y, zr(0), zr(1)));
    const RigidContactSolution s = solve_rigid_contact(pair, y);
    EXPECT_NEAR(s.roll_rad, zr(1), 1e-9);
    EXPECT_NEAR(s.left.front().contact_angle_rad, L.gamma, 1e-7);
    EXPECT_NEAR(s.right.front().contact_angle_rad, Rt.gamma, 1e-7);
    EXPECT_NEAR(s.left.front().rolling_radius_m - s.right.front().rolling_radius_m,
                L.radius - Rt.radius, 1e-9);
    // Relative lateral curvature of the two circles: B = (1/Rr - 1/Rw) / 2.
    EXPECT_NEAR(s.left.front().B_per_m, 0.5 * (1 / Rr - 1 / Rw), 2e-3);
  }
}

namespace {
using railstab::test::benchmark_profile_pair;
}  // namespace

TEST(CharacteristicFunctions, SymmetricPairGivesOddDeltaRAndRoll) {
  const ProfilePair pair = benchmark_profile_pair();
  for (double y : {0.0013, 0.0031, 0.0047, 0.0058, 0.0071, 0.0094}) {
    const RigidContactSolution a = solve_rigid_contact(pair, y), b = solve_rigid_contact(pair, -y);
    const double dra = a.left.front().rolling_radius_m - a.right.front().rolling_radius_m;
    const double drb = b.left.front().rolling_radius_m - b.right.front().rolling_radius_m;
    EXPECT_NEAR(dra, -drb, 1e-10) << "y = " << y;
    EXPECT_NEAR(a.roll_rad, -b.roll_rad, 1e-11) << "y = " << y;
    EXPECT_NEAR(a.vertical_m, b.vertical_m, 1e-10) << "y = " << y;
    EXPECT_GT(dra, 0.0);
  }
}

// Manchester Contact Benchmark (Shackleton and Iwnicki 2008), case A: the
// S1002/UIC60 1:40 pair reaches flange contact between 6.0 and 6.5 mm.
TEST(CharacteristicFunctions, BenchmarkPairReachesFlangeContactBetween6And6Point5mm) {
  const FlangeContact fc = find_flange_contact(benchmark_profile_pair());
  ASSERT_TRUE(fc.found);
  EXPECT_GT(fc.lateral_shift_m, 0.0060);
  EXPECT_LT(fc.lateral_shift_m, 0.0065);
  EXPECT_GT(fc.flange_contact_angle_rad, 1.0);  // on the flange face (~70 degrees)
}
