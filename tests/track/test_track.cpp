// Track geometry and moving-frame kinematics (src/track), checked against
// closed forms, the ERRATA 1 series, brute-force quadrature and finite
// differences.
#include <railstab/track/track.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace railstab {
namespace {

using Kind = TrackSegmentKind;
constexpr double kEps = std::numeric_limits<double>::epsilon();

// ERRATA 5: straight 1000 m, clothoid 200 m to R = 1000 m with cant 0 -> 0.05 m,
// arc 3000 m; D = 1.5 m.
constexpr double kSeedRadius_m = 1000.0;
constexpr double kSeedClothoid_m = 200.0;
TrackSpec seed_track() {
  TrackSpec t;
  t.rail_contact_distance_m = 1.5;
  t.segments = {{Kind::tangent, 1000.0, 0.0, 0.0},
                {Kind::clothoid, kSeedClothoid_m, 1.0 / kSeedRadius_m, 0.05},
                {Kind::arc, 3000.0, 1.0 / kSeedRadius_m, 0.05}};
  return t;
}

// Every segment kind, both curve directions, clothoids starting curved and
// crossing zero curvature, cant ramps of both signs, an off-origin start.
TrackSpec winding_track() {
  TrackSpec t;
  t.start_x_m = 120.0;
  t.start_y_m = -40.0;
  t.start_z_m = 3.0;
  t.start_heading_rad = 0.3;
  t.rail_contact_distance_m = 1.5;
  t.segments = {{Kind::tangent, 150.0, 0.0, 0.0},
                {Kind::clothoid, 120.0, 1.0 / 600.0, 0.08},
                {Kind::arc, 200.0, 0.0, 0.08},
                {Kind::clothoid, 180.0, -1.0 / 450.0, -0.06},  // reverse curve through k = 0
                {Kind::arc, 90.0, 0.0, -0.06},
                {Kind::clothoid, 60.0, -1.0 / 300.0, -0.1},    // starts curved
                {Kind::clothoid, 140.0, 0.0, 0.0},
                {Kind::tangent, 100.0, 0.0, 0.0}};
  return t;
}

std::vector<double> joints_of(const TrackSpec& spec) {
  std::vector<double> joints;
  double s = 0.0;
  for (size_t i = 0; i + 1 < spec.segments.size(); ++i)
    joints.push_back(s += spec.segments[i].length_m);
  return joints;
}

// Interior sample points of every segment, kept away from the joints by more
// than the finite-difference steps used below.
std::vector<double> interior_points(const TrackSpec& spec) {
  std::vector<double> points;
  double start = 0.0;
  for (const TrackSegmentSpec& seg : spec.segments) {
    for (double f : {0.13, 0.5, 0.87}) points.push_back(start + f * seg.length_m);
    start += seg.length_m;
  }
  return points;
}

// |actual - expected| <= rel * max(|expected|, floor): relative, with a floor
// for quantities that are zero in some segments.
void expect_close(double actual, double expected, double rel, double floor,
                  const std::string& what) {
  EXPECT_LE(std::abs(actual - expected), rel * std::max(std::abs(expected), floor))
      << what << ": actual " << actual << ", expected " << expected;
}
void expect_close(const Eigen::Vector3d& actual, const Eigen::Vector3d& expected, double rel,
                  double floor, const std::string& what) {
  EXPECT_LE((actual - expected).norm(), rel * std::max(expected.norm(), floor))
      << what << ":\n actual   " << actual.transpose() << "\n expected " << expected.transpose();
}

// ERRATA 1 series for a clothoid from k = 0 to 1/R over L, heading t^2 / a
// with a = 2RL:  integral_0^u exp(i t^2 / a) dt = u sum_m (i q)^m / (m! (2m + 1)),
// q = u^2 / a. Its real part is x = u - u^5/(40 R^2 L^2) + u^9/(3456 R^4 L^4) - ...
// and its imaginary part y = u^3/(6RL) - u^7/(336 R^3 L^3) + ... Summed to convergence.
Eigen::Vector2d clothoid_series(double u, double radius, double length) {
  const double q = u * u / (2.0 * radius * length);
  std::complex<double> power(1.0, 0.0);  // (i q)^m / m!
  std::complex<double> sum(0.0, 0.0);
  for (int m = 0; m < 60; ++m) {
    const std::complex<double> term = power / double(2 * m + 1);
    sum += term;
    if (std::abs(term) < 1e-20 * std::abs(sum)) break;
    power *= std::complex<double>(0.0, q) / double(m + 1);
  }
  return {u * sum.real(), u * sum.imag()};
}

// Adaptive Simpson with Richardson correction: an independent brute-force
// quadrature for the general clothoid.
double adaptive_simpson(const std::function<double(double)>& f, double a, double b, double fa,
                        double fm, double fb, double whole, double tol, int depth) {
  const double m = 0.5 * (a + b);
  const double lm = 0.5 * (a + m), rm = 0.5 * (m + b);
  const double flm = f(lm), frm = f(rm);
  const double left = (m - a) / 6.0 * (fa + 4.0 * flm + fm);
  const double right = (b - m) / 6.0 * (fm + 4.0 * frm + fb);
  const double delta = left + right - whole;
  if (depth <= 0 || std::abs(delta) <= 15.0 * tol) return left + right + delta / 15.0;
  return adaptive_simpson(f, a, m, fa, flm, fm, left, 0.5 * tol, depth - 1) +
         adaptive_simpson(f, m, b, fm, frm, fb, right, 0.5 * tol, depth - 1);
}
double integrate(const std::function<double(double)>& f, double a, double b, double tol) {
  const double fa = f(a), fb = f(b), fm = f(0.5 * (a + b));
  return adaptive_simpson(f, a, b, fa, fm, fb, (b - a) / 6.0 * (fa + 4.0 * fm + fb), tol, 50);
}

// Pair of arc lengths s -/+ h and their exact spacing (the sum s + h rounds,
// the difference of the rounded values does not).
struct Stencil {
  double minus, plus, span;
};
Stencil stencil(double s, double h) {
  const double plus = s + h, minus = s - h;
  return {minus, plus, plus - minus};
}

// d2p/ds2 by central second differences at steps h and 2h, Richardson
// extrapolated: (4 D(h) - D(2h)) / 3 = p'' + O(h^4). s +/- h must be exact.
Eigen::Vector3d second_difference(const Track& track, double s, double h) {
  const auto difference = [&](double step) -> Eigen::Vector3d {
    return (track.geometry_at(s + step).p_WT_W - 2.0 * track.geometry_at(s).p_WT_W +
            track.geometry_at(s - step).p_WT_W) /
           (step * step);
  };
  return (4.0 * difference(h) - difference(2.0 * h)) / 3.0;
}

// Angular velocity from the rotation's derivative: A^T dA/dt = skew(w).
Eigen::Vector3d unskew(const Eigen::Matrix3d& w) {
  return 0.5 * Eigen::Vector3d(w(2, 1) - w(1, 2), w(0, 2) - w(2, 0), w(1, 0) - w(0, 1));
}

// ---------------------------------------------------------------------------
// Continuity at joints.

// Evaluates the previous segment's law at the last double below each joint
// and the next segment's at the joint itself (s = s_joint picks the later
// segment). The gap is one ulp of s, so any jump above rounding is a fault in
// the chaining.
void expect_continuous_at_joints(const TrackSpec& spec) {
  const Track track(spec);
  double max_curvature = 0.0;
  for (double s : interior_points(spec))
    max_curvature = std::max(max_curvature, std::abs(track.geometry_at(s).curvature_per_m));
  const double d = spec.rail_contact_distance_m;
  const double tol = 1e-12;
  int joint_index = 0;
  for (double joint : joints_of(spec)) {
    ++joint_index;
    const TrackGeometryPoint before = track.geometry_at(std::nextafter(joint, 0.0));
    const TrackGeometryPoint after = track.geometry_at(joint);
    const std::string where =
        "joint " + std::to_string(joint_index) + " at s = " + std::to_string(joint);
    ASSERT_EQ(before.segment, joint_index - 1) << where;
    ASSERT_EQ(after.segment, joint_index) << where;
    EXPECT_LE((after.p_WT_W - before.p_WT_W).norm(), tol * track.length_m()) << where;
    EXPECT_LE(std::abs(after.heading_rad - before.heading_rad),
              tol * std::max(1.0, std::abs(after.heading_rad)))
        << where;
    EXPECT_LE(std::abs(after.curvature_per_m - before.curvature_per_m), tol * max_curvature)
        << where;
    EXPECT_LE(std::abs(after.cant_m - before.cant_m), tol * d) << where;
    EXPECT_LE(std::abs(after.roll_rad - before.roll_rad), tol) << where;
  }
}

TEST(TrackGeometry, ContinuousAtEveryJointOfSeedTrack) {
  expect_continuous_at_joints(seed_track());
}
TEST(TrackGeometry, ContinuousAtEveryJointOfWindingTrack) {
  expect_continuous_at_joints(winding_track());
}

// The joint test above compares values one ulp apart; this one compares the
// left and right first-order extrapolations to the joint from 1 mm away, so a
// wrong derivative law on either side (or a jump) shows up too.
TEST(TrackGeometry, OneSidedExtrapolationsMeetAtJoints) {
  const TrackSpec spec = winding_track();
  const Track track(spec);
  const double h = 1e-3;
  for (double joint : joints_of(spec)) {
    const TrackGeometryPoint left = track.geometry_at(joint - h);
    const TrackGeometryPoint right = track.geometry_at(joint + h);
    // O(h^2 k') and O(h^2 k) remainders: < 1e-6 * 1e-5.
    EXPECT_NEAR(left.heading_rad + h * left.curvature_per_m,
                right.heading_rad - h * right.curvature_per_m, 1e-10);
    EXPECT_NEAR(left.curvature_per_m + h * left.curvature_rate_per_m2,
                right.curvature_per_m - h * right.curvature_rate_per_m2, 1e-15);
    EXPECT_NEAR(left.roll_rad + h * left.roll_rate_per_m,
                right.roll_rad - h * right.roll_rate_per_m, 1e-10);
    const Eigen::Vector3d t_left(std::cos(left.heading_rad), std::sin(left.heading_rad), 0.0);
    const Eigen::Vector3d t_right(std::cos(right.heading_rad), std::sin(right.heading_rad), 0.0);
    EXPECT_LE(((left.p_WT_W + h * t_left) - (right.p_WT_W - h * t_right)).norm(), 1e-9);
  }
}

TEST(TrackGeometry, SegmentIndexAtJointIsTheLaterSegment) {
  const Track track(seed_track());
  EXPECT_EQ(track.geometry_at(0.0).segment, 0);
  EXPECT_EQ(track.geometry_at(999.999).segment, 0);
  EXPECT_EQ(track.geometry_at(1000.0).segment, 1);
  EXPECT_EQ(track.geometry_at(1200.0).segment, 2);
  EXPECT_EQ(track.geometry_at(4200.0).segment, 2);
  EXPECT_DOUBLE_EQ(track.length_m(), 4200.0);
}

// ---------------------------------------------------------------------------
// Seed track (ERRATA 1-3, 5).

TEST(TrackGeometry, SeedClothoidEndHeadingIsLOver2R) {
  const Track track(seed_track());
  const TrackGeometryPoint end = track.geometry_at(1200.0);
  EXPECT_NEAR(end.heading_rad, kSeedClothoid_m / (2.0 * kSeedRadius_m), 1e-14);
  EXPECT_DOUBLE_EQ(end.curvature_per_m, 1.0 / kSeedRadius_m);
  EXPECT_DOUBLE_EQ(end.cant_m, 0.05);
}

TEST(TrackGeometry, SeedClothoidPositionMatchesErrataSeries) {
  const Track track(seed_track());
  for (double u : {0.0, 1.0, 10.0, 37.5, 50.0, 99.9, 100.0, 100.1, 150.0, 199.0, 200.0}) {
    const Eigen::Vector2d series = clothoid_series(u, kSeedRadius_m, kSeedClothoid_m);
    const TrackGeometryPoint g = track.geometry_at(1000.0 + u);
    EXPECT_NEAR(g.p_WT_W.x() - 1000.0, series.x(), 1e-12) << "u = " << u;
    EXPECT_NEAR(g.p_WT_W.y(), series.y(), 1e-12) << "u = " << u;
    EXPECT_EQ(g.p_WT_W.z(), 0.0);
  }
}

TEST(TrackGeometry, SeedArcPointsLieOnCircleOfRadiusR) {
  const Track track(seed_track());
  const TrackGeometryPoint start = track.geometry_at(1200.0);
  // Centre: R to the left of the arc start (curvature > 0 turns left).
  const Eigen::Vector2d centre =
      start.p_WT_W.head<2>() +
      kSeedRadius_m * Eigen::Vector2d(-std::sin(start.heading_rad), std::cos(start.heading_rad));
  for (double s = 1200.0; s <= 4200.0; s += 37.0) {
    const TrackGeometryPoint g = track.geometry_at(s);
    const Eigen::Vector2d radial = g.p_WT_W.head<2>() - centre;
    EXPECT_NEAR(radial.norm(), kSeedRadius_m, 1e-9 * kSeedRadius_m) << "s = " << s;
    // The tangent is perpendicular to the radius, and heading advances as s / R.
    EXPECT_NEAR(radial.dot(Eigen::Vector2d(std::cos(g.heading_rad), std::sin(g.heading_rad))), 0.0,
                1e-9 * kSeedRadius_m);
    EXPECT_NEAR(g.heading_rad, 0.1 + (s - 1200.0) / kSeedRadius_m, 1e-13);
  }
}

TEST(TrackGeometry, SeedCantRampAndRollSign) {
  const Track track(seed_track());
  const double d = 1.5;
  EXPECT_EQ(track.geometry_at(500.0).cant_m, 0.0);
  EXPECT_EQ(track.geometry_at(500.0).roll_rad, 0.0);
  const TrackGeometryPoint mid = track.geometry_at(1100.0);
  EXPECT_NEAR(mid.cant_m, 0.025, 1e-15);
  EXPECT_NEAR(mid.roll_rad, -std::asin(0.025 / d), 1e-15);
  // Cant > 0 raises the right rail: right contact point (y = -D/2) minus the
  // left one (y = +D/2), in W, differ in height by the cant.
  const TrackFrameKinematics k = track.frame_at(2000.0, 20.0);
  const double right_z = (k.R_WT * Eigen::Vector3d(0.0, -0.5 * d, 0.0)).z();
  const double left_z = (k.R_WT * Eigen::Vector3d(0.0, 0.5 * d, 0.0)).z();
  EXPECT_NEAR(right_z - left_z, 0.05, 1e-15);
  EXPECT_EQ(k.geometry.grade_rad, 0.0);
}

// The arc's end_curvature_per_m is not used (arc curvature = start), so scene
// builders may leave it 0.
// Uniform stretches end at the next clothoid or cant ramp; equal tangents
// and equal arcs merge; inside a clothoid the stretch is empty.
TEST(TrackGeometry, UniformStretchEnds) {
  const Track seed(seed_track());
  EXPECT_EQ(seed.uniform_stretch_end_m(100.0), 1000.0);
  EXPECT_EQ(seed.uniform_stretch_end_m(1100.0), 1100.0);
  EXPECT_EQ(seed.uniform_stretch_end_m(2000.0), 4200.0);
  TrackSpec spec;
  spec.segments = {{Kind::tangent, 100.0, 0.0, 0.0},
                   {Kind::tangent, 50.0, 0.0, 0.0},
                   {Kind::tangent, 30.0, 0.0, 0.02},  // cant ramp
                   {Kind::tangent, 40.0, 0.0, 0.02}};
  const Track t(spec);
  EXPECT_EQ(t.uniform_stretch_end_m(10.0), 150.0);
  EXPECT_EQ(t.uniform_stretch_end_m(160.0), 160.0);
  EXPECT_EQ(t.uniform_stretch_end_m(190.0), 220.0);
}

TEST(TrackGeometry, ArcIgnoresEndCurvatureField) {
  TrackSpec with_zero = seed_track();
  with_zero.segments[2].end_curvature_per_m = 0.0;
  const Track a(seed_track()), b(with_zero);
  for (double s : {1500.0, 3000.0, 4200.0}) {
    EXPECT_EQ(a.geometry_at(s).p_WT_W, b.geometry_at(s).p_WT_W);
    EXPECT_EQ(a.geometry_at(s).curvature_per_m, b.geometry_at(s).curvature_per_m);
  }
}

// ---------------------------------------------------------------------------
// General clothoid k0 -> k1 against brute-force quadrature.

void expect_clothoid_matches_quadrature(double k0, double k1, double length, double heading0) {
  TrackSpec spec;
  spec.start_x_m = 7.0;
  spec.start_y_m = -3.0;
  spec.start_heading_rad = heading0;
  spec.start_curvature_per_m = k0;
  spec.segments = {{Kind::clothoid, length, k1, 0.0}};
  const Track track(spec);
  const double dk = (k1 - k0) / length;
  const auto heading = [&](double t) { return heading0 + k0 * t + 0.5 * dk * t * t; };
  for (double f : {0.1, 0.333, 0.5, 0.77, 1.0}) {
    const double u = f * length;
    const double x = integrate([&](double t) { return std::cos(heading(t)); }, 0.0, u, 1e-13);
    const double y = integrate([&](double t) { return std::sin(heading(t)); }, 0.0, u, 1e-13);
    const TrackGeometryPoint g = track.geometry_at(u);
    EXPECT_NEAR(g.p_WT_W.x() - 7.0, x, 1e-10) << "k0 " << k0 << " k1 " << k1 << " u " << u;
    EXPECT_NEAR(g.p_WT_W.y() + 3.0, y, 1e-10) << "k0 " << k0 << " k1 " << k1 << " u " << u;
    EXPECT_NEAR(g.heading_rad, heading(u), 1e-13);
    EXPECT_NEAR(g.curvature_per_m, k0 + dk * u, 1e-16);
  }
}

TEST(TrackGeometry, GeneralClothoidMatchesBruteForceQuadrature) {
  expect_clothoid_matches_quadrature(1.0 / 150.0, -1.0 / 90.0, 400.0, 0.7);  // through k = 0
  expect_clothoid_matches_quadrature(-1.0 / 800.0, -1.0 / 250.0, 250.0, -2.0);
  // Sharp spiral (heading turns ~12 rad): many quadrature pieces.
  expect_clothoid_matches_quadrature(0.05, 0.2, 100.0, 0.0);
}

// ---------------------------------------------------------------------------
// Rotation.

TEST(TrackRotation, IsOrthonormalWithUnitDeterminant) {
  for (double heading : {-2.5, 0.0, 0.1, 1.3, 4.0})
    for (double grade : {-0.3, 0.0, 0.02})
      for (double roll : {-0.05, 0.0, 0.7}) {
        const Eigen::Matrix3d r = track_rotation(heading, grade, roll);
        EXPECT_LE((r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), 1e-14);
        EXPECT_NEAR(r.determinant(), 1.0, 1e-14);
      }
  const Track track(winding_track());
  for (double s : interior_points(winding_track())) {
    const Eigen::Matrix3d r = track.frame_at(s, 30.0).R_WT;
    EXPECT_LE((r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), 1e-14);
    EXPECT_NEAR(r.determinant(), 1.0, 1e-14);
  }
}

TEST(TrackRotation, ComposesRightHandedElementaryRotationsZYX) {
  const double a = 0.4, b = -0.2, c = 0.3;
  Eigen::Matrix3d rz, ry, rx;
  rz << std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1;
  ry << std::cos(b), 0, std::sin(b), 0, 1, 0, -std::sin(b), 0, std::cos(b);
  rx << 1, 0, 0, 0, std::cos(c), -std::sin(c), 0, std::sin(c), std::cos(c);
  EXPECT_LE((track_rotation(a, b, c) - rz * ry * rx).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_LE((track_rotation(a, 0, 0) - rz).cwiseAbs().maxCoeff(), 0.0);
}

// ---------------------------------------------------------------------------
// Derivatives against central differences, inside segments.

void expect_derivatives_match_differences(const TrackSpec& spec, double speed) {
  const Track track(spec);
  // Angles and curvature vary on the scale of ~1/k ~ 300..1000 m: first
  // differences use h ~ cbrt(eps) * 100 m. The second difference of the
  // position (size ~1e3 m, rounding noise eps |p| / h^2) needs a larger step,
  // with Richardson extrapolation removing its h^2 truncation error.
  const double h1 = std::cbrt(kEps) * 100.0;
  const double h2 = 0.5;
  const double rel = 1e-7;
  for (double s_raw : interior_points(spec)) {
    const double s = std::round(s_raw * 1024.0) / 1024.0;  // s +/- h2 exact
    const std::string at = "s = " + std::to_string(s);
    const TrackFrameKinematics k = track.frame_at(s, speed);
    const TrackGeometryPoint& g = k.geometry;
    const Stencil st = stencil(s, h1);
    const TrackFrameKinematics km = track.frame_at(st.minus, speed);
    const TrackFrameKinematics kp = track.frame_at(st.plus, speed);

    expect_close((kp.geometry.heading_rad - km.geometry.heading_rad) / st.span, g.curvature_per_m,
                 rel, 1e-6, "d heading/ds, " + at);
    expect_close((kp.geometry.curvature_per_m - km.geometry.curvature_per_m) / st.span,
                 g.curvature_rate_per_m2, rel, 1e-9, "d curvature/ds, " + at);
    expect_close((kp.geometry.roll_rad - km.geometry.roll_rad) / st.span, g.roll_rate_per_m, rel,
                 1e-6, "d roll/ds, " + at);
    expect_close((kp.geometry.roll_rate_per_m - km.geometry.roll_rate_per_m) / st.span,
                 g.roll_rate2_per_m2, 1e-6, 1e-9, "d2 roll/ds2, " + at);

    // w from A^T dA/dt = skew(w), dA/dt = V dA/ds.
    const Eigen::Matrix3d a_dot = (kp.R_WT - km.R_WT) / st.span * speed;
    expect_close(k.w_WT_T, unskew(k.R_WT.transpose() * a_dot), rel, 1e-6 * speed,
                 "w_WT_T, " + at);
    // The derivative of a rotation is A skew(w): its symmetric part vanishes.
    const Eigen::Matrix3d a_t_a_dot = k.R_WT.transpose() * a_dot;
    EXPECT_LE((a_t_a_dot + a_t_a_dot.transpose()).cwiseAbs().maxCoeff(), 1e-9 * speed) << at;

    expect_close(k.alpha_WT_T, (kp.w_WT_T - km.w_WT_T) / st.span * speed, rel,
                 1e-9 * speed * speed, "alpha_WT_T, " + at);

    // Origin velocity and acceleration, compared in W.
    expect_close(k.R_WT * k.v_WT_T, (kp.geometry.p_WT_W - km.geometry.p_WT_W) / st.span * speed,
                 rel, speed, "v_WT, " + at);
    EXPECT_NEAR(k.v_WT_T.x(), speed, 1e-12 * speed) << at;
    const Eigen::Vector3d second = second_difference(track, s, h2) * speed * speed;
    expect_close(k.R_WT * k.a_WT_T, second, rel, 1e-3 * speed * speed, "a_WT, " + at);
  }
}

TEST(TrackFrame, DerivativesMatchCentralDifferencesOnSeedTrack) {
  expect_derivatives_match_differences(seed_track(), 27.5);
}
TEST(TrackFrame, DerivativesMatchCentralDifferencesOnWindingTrack) {
  expect_derivatives_match_differences(winding_track(), 41.0);
}

// On a canted arc the frame turns at V/R about its own (rolled) z axis and the
// origin accelerates centripetally, V^2/R towards the centre in the horizontal.
TEST(TrackFrame, SteadyArcClosedForm) {
  const Track track(seed_track());
  const double v = 20.0, phi = -std::asin(0.05 / 1.5);
  const TrackFrameKinematics k = track.frame_at(2500.0, v);
  const Eigen::Vector3d w_expected(0.0, std::sin(phi) * v / kSeedRadius_m,
                                   std::cos(phi) * v / kSeedRadius_m);
  EXPECT_LE((k.w_WT_T - w_expected).norm(), 1e-17);
  EXPECT_LE(k.alpha_WT_T.norm(), 1e-17);
  const Eigen::Vector3d a_W = k.R_WT * k.a_WT_T;
  const double h = k.geometry.heading_rad;
  EXPECT_LE((a_W - v * v / kSeedRadius_m * Eigen::Vector3d(-std::sin(h), std::cos(h), 0.0)).norm(),
            1e-15);
}

// ---------------------------------------------------------------------------
// Frame independence: a different start pose moves the track rigidly.

TEST(TrackGeometry, StartPoseMovesTrackRigidly) {
  TrackSpec base = winding_track();
  base.start_x_m = base.start_y_m = base.start_z_m = base.start_heading_rad = 0.0;
  TrackSpec moved = base;
  moved.start_x_m = -350.0;
  moved.start_y_m = 2200.0;
  moved.start_z_m = 12.5;
  moved.start_heading_rad = 1.1;
  const Track a(base), b(moved);
  const Eigen::Matrix3d turn = track_rotation(1.1, 0.0, 0.0);
  const Eigen::Vector3d shift(-350.0, 2200.0, 12.5);
  for (double s = 0.0; s <= a.length_m(); s += 13.0) {
    const TrackFrameKinematics ka = a.frame_at(s, 30.0), kb = b.frame_at(s, 30.0);
    EXPECT_EQ(ka.geometry.curvature_per_m, kb.geometry.curvature_per_m);
    EXPECT_EQ(ka.geometry.cant_m, kb.geometry.cant_m);
    EXPECT_EQ(ka.geometry.roll_rad, kb.geometry.roll_rad);
    EXPECT_NEAR(kb.geometry.heading_rad, ka.geometry.heading_rad + 1.1, 1e-13);
    EXPECT_LE((kb.geometry.p_WT_W - (shift + turn * ka.geometry.p_WT_W)).norm(), 1e-9) << "s " << s;
    EXPECT_LE((kb.R_WT - turn * ka.R_WT).cwiseAbs().maxCoeff(), 1e-13);
    // Quantities in T do not see the start pose.
    EXPECT_LE((kb.w_WT_T - ka.w_WT_T).norm(), 1e-15);
    EXPECT_LE((kb.alpha_WT_T - ka.alpha_WT_T).norm(), 1e-15);
    EXPECT_LE((kb.a_WT_T - ka.a_WT_T).norm(), 1e-12);
  }
}

// ---------------------------------------------------------------------------
// Validation.

// Building a Track from `spec` throws invalid_argument mentioning `needle`.
void expect_rejected(const TrackSpec& spec, const std::string& needle) {
  try {
    Track track(spec);
    ADD_FAILURE() << "expected std::invalid_argument mentioning \"" << needle << "\"";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
  }
}

TEST(TrackValidation, RejectsNonPositiveOrNonFiniteLength) {
  TrackSpec spec = seed_track();
  spec.segments[1].length_m = -5.0;
  expect_rejected(spec, "segment 1 (clothoid): length must be positive");
  spec.segments[1].length_m = 0.0;
  expect_rejected(spec, "segment 1");
  spec.segments[1].length_m = std::numeric_limits<double>::quiet_NaN();
  expect_rejected(spec, "segment 1");
  spec.segments[1].length_m = std::numeric_limits<double>::infinity();
  expect_rejected(spec, "segment 1");
}

TEST(TrackValidation, RejectsCantNotBelowContactDistance) {
  TrackSpec spec = seed_track();
  spec.segments[2].end_cant_m = 1.5;
  expect_rejected(spec, "segment 2 (arc): end cant");
  spec = seed_track();
  spec.segments[1].end_cant_m = -2.0;
  expect_rejected(spec, "segment 1 (clothoid): end cant");
  spec = seed_track();
  spec.start_cant_m = 1.6;
  expect_rejected(spec, "start cant");
}

TEST(TrackValidation, RejectsTangentWithNonzeroStartCurvature) {
  TrackSpec spec = seed_track();
  spec.start_curvature_per_m = 1e-4;
  expect_rejected(spec, "segment 0 (tangent): a tangent needs start curvature 0");
  spec = seed_track();
  spec.segments.push_back({Kind::tangent, 100.0, 0.0, 0.05});  // after the curved arc
  expect_rejected(spec, "segment 3 (tangent)");
}

TEST(TrackValidation, RejectsEmptyTrackAndBadContactDistance) {
  TrackSpec spec = seed_track();
  spec.segments.clear();
  expect_rejected(spec, "at least one segment");
  spec = seed_track();
  spec.rail_contact_distance_m = 0.0;
  expect_rejected(spec, "rail_contact_distance_m");
}

TEST(TrackValidation, ArcLengthOutsideTrackThrows) {
  const Track track(seed_track());
  EXPECT_NO_THROW(track.geometry_at(0.0));
  EXPECT_NO_THROW(track.geometry_at(4200.0));
  EXPECT_THROW(track.geometry_at(-1e-9), std::out_of_range);
  EXPECT_THROW(track.frame_at(4200.5, 10.0), std::out_of_range);
  EXPECT_THROW(track.geometry_at(std::numeric_limits<double>::quiet_NaN()), std::out_of_range);
  try {
    track.geometry_at(4300.0);
    ADD_FAILURE() << "expected std::out_of_range";
  } catch (const std::out_of_range& e) {
    EXPECT_EQ(std::string(e.what()), "arc length 4300 m is outside the track [0, 4200] m");
  }
}

}  // namespace
}  // namespace railstab
