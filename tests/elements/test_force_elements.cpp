// Force elements: springs conservative, dampers dissipate exactly
// -dd/dt^T C dd/dt, forces and moments equal and opposite (Drake's
// LinearSpringDamper test, Chrono's ValidateEnergy).
#include "elements/spring_damper.hpp"

#include <gtest/gtest.h>

#include <random>

using namespace railstab;

namespace {

struct Pair {
  ModelBody body[2];
  TrackFrameKinematics frame[2];
  Eigen::Matrix<double, 6, 1> q[2], qd[2];
};

Pair random_pair(std::mt19937& rng, bool wheelset1) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Pair p;
  for (int i = 0; i < 2; ++i) {
    p.body[i].mass_kg = 1000.0;
    p.body[i].inertia_kg_m2 = Eigen::Vector3d(300, 400, 500);
    p.body[i].is_wheelset = (i == 0 && wheelset1);
    p.frame[i].R_WT = track_rotation(0.3 * u(rng), 0.0, 0.05 * u(rng));
    p.frame[i].geometry.p_WT_W = Eigen::Vector3d(10 * u(rng), u(rng), 0.0);
    for (int c = 0; c < 6; ++c) {
      p.q[i](c) = 0.3 * u(rng);
      p.qd[i](c) = u(rng);
    }
  }
  return p;
}

// Positions advanced along the rates by h (track frames at rest).
std::array<BodyMotion<double>, 2> motions(const Pair& p, double h) {
  std::array<BodyMotion<double>, 2> m;
  for (int i = 0; i < 2; ++i)
    compute_body_motion(p.body[i], p.frame[i], Eigen::Matrix<double, 6, 1>(p.q[i] + h * p.qd[i]),
                        p.qd[i], m[i]);
  return m;
}

ModelElement element(ElementKind kind, std::mt19937& rng, bool damped) {
  std::uniform_real_distribution<double> u(0.2, 1.0);
  ModelElement e;
  e.kind = kind;
  e.point1_m = Eigen::Vector3d(0.5, -0.3, 0.2);
  e.point2_m = Eigen::Vector3d(-0.4, 0.6, 0.1);
  e.stiffness = kind == ElementKind::rotational_spring_damper
                    ? Eigen::Vector3d::Constant(3e5)  // isotropic: exactly conservative
                    : Eigen::Vector3d(1e5 * u(rng), 2e5 * u(rng), 3e5 * u(rng));
  if (damped) e.damping = Eigen::Vector3d(1e3 * u(rng), 2e3 * u(rng), 3e3 * u(rng));
  // A constant moment is conservative only to first order in the rotation
  // (the rotation vector is not a set of coordinates whose gradient is it),
  // so the rotational element is tested without one.
  if (kind == ElementKind::spring_damper_3d) e.preload = Eigen::Vector3d(100.0, -50.0, 30.0);
  e.free_vector_m = Eigen::Vector3d(0.1, 0.0, -0.05);
  return e;
}

double potential(const ModelElement& e, std::array<BodyMotion<double>, 2>& m) {
  const Attachment<double> a1 = attachment_of(m[0]), a2 = attachment_of(m[1]);
  if (e.kind == ElementKind::spring_damper_3d) {
    const Eigen::Vector3d dd = spring_deflection(e, a1, a2).d - e.free_vector_m;
    return 0.5 * dd.dot(e.stiffness.cwiseProduct(dd)) + e.preload.dot(dd);
  }
  const Eigen::Vector3d th = rotation_vector<double>(a1.R_WF.transpose() * a2.R_WF);
  return 0.5 * th.dot(e.stiffness.cwiseProduct(th)) + e.preload.dot(th);
}

// Power of the element's forces and moments on both bodies.
double element_power(const ModelElement& e, std::array<BodyMotion<double>, 2>& m,
                     Eigen::Vector3d* net_force = nullptr, Eigen::Vector3d* net_moment = nullptr) {
  for (auto& mi : m) mi.force_W.setZero(), mi.moment_W.setZero();
  const Attachment<double> a1 = attachment_of(m[0]), a2 = attachment_of(m[1]);
  if (e.kind == ElementKind::spring_damper_3d) apply_spring_damper_3d(e, a1, a2);
  else apply_rotational_spring_damper(e, a1, a2);
  double power = 0.0;
  Eigen::Vector3d F = Eigen::Vector3d::Zero(), M = Eigen::Vector3d::Zero();
  for (auto& mi : m) {
    power += mi.force_W.dot(mi.v_W) + mi.moment_W.dot(mi.w_F_W);
    F += mi.force_W;
    M += mi.moment_W + mi.p_W.cross(mi.force_W);  // about the W origin
  }
  if (net_force) *net_force = F;
  if (net_moment) *net_moment = M;
  return power;
}

}  // namespace

class ElementKinds : public ::testing::TestWithParam<std::tuple<ElementKind, bool>> {};

// Springs (3D: with preload) are conservative: element power = -dV/dt, checked
// against a central difference of V along the motion (h = 1e-6 s: error
// ~1e-12 relative), to 1e-6 relative.
TEST_P(ElementKinds, SpringIsConservative) {
  const auto [kind, wheelset1] = GetParam();
  std::mt19937 rng(11);
  for (int trial = 0; trial < 20; ++trial) {
    Pair p = random_pair(rng, wheelset1);
    if (wheelset1) p.qd[0](4) = 0.0;  // the axle-box frame does not spin; V ignores pitch
    const ModelElement e = element(kind, rng, false);
    const double h = 1e-6;
    auto mp = motions(p, h), mm = motions(p, -h), m0 = motions(p, 0.0);
    const double dVdt = (potential(e, mp) - potential(e, mm)) / (2 * h);
    const double power = element_power(e, m0);
    EXPECT_NEAR(power, -dVdt, 1e-6 * std::max(1.0, std::abs(dVdt)));
  }
}

// Dampers dissipate: power of the damping part = -r^T C r <= 0, r = dd/dt
// for the 3D element, r = relative angular velocity for the rotational one.
TEST_P(ElementKinds, DamperDissipates) {
  const auto [kind, wheelset1] = GetParam();
  std::mt19937 rng(5);
  for (int trial = 0; trial < 20; ++trial) {
    const Pair p = random_pair(rng, wheelset1);
    ModelElement damped = element(kind, rng, true);
    ModelElement elastic = damped;
    elastic.damping.setZero();
    auto m = motions(p, 0.0);
    const double damper_power = element_power(damped, m) - element_power(elastic, m);
    const Attachment<double> a1 = attachment_of(m[0]), a2 = attachment_of(m[1]);
    const Eigen::Vector3d rate = kind == ElementKind::spring_damper_3d
                                     ? spring_deflection(damped, a1, a2).d_rate
                                     : Eigen::Vector3d(a1.R_WF.transpose() * (a2.w_W - a1.w_W));
    const double expected = -rate.dot(damped.damping.cwiseProduct(rate));
    EXPECT_LE(damper_power, 0.0);
    EXPECT_NEAR(damper_power, expected, 1e-9 * std::abs(expected));
  }
}

// Forces equal and opposite, no net moment (actio = reactio).
TEST_P(ElementKinds, EqualAndOpposite) {
  const auto [kind, wheelset1] = GetParam();
  std::mt19937 rng(2);
  for (int trial = 0; trial < 20; ++trial) {
    const Pair p = random_pair(rng, wheelset1);
    const ModelElement e = element(kind, rng, true);
    auto m = motions(p, 0.0);
    Eigen::Vector3d F, M;
    element_power(e, m, &F, &M);
    const double scale = m[0].force_W.norm() * 20.0 + m[0].moment_W.norm() + 1.0;
    EXPECT_LT(F.norm(), 1e-12 * scale);
    EXPECT_LT(M.norm(), 1e-11 * scale);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Elements, ElementKinds,
    ::testing::Combine(::testing::Values(ElementKind::spring_damper_3d,
                                         ElementKind::rotational_spring_damper),
                       ::testing::Bool()));
