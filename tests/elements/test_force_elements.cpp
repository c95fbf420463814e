// Force elements: springs conservative, dampers dissipate exactly
// -dd/dt^T C dd/dt, forces and moments equal and opposite (Drake's
// LinearSpringDamper test, Chrono's ValidateEnergy).
#include <railstab/elements/element.hpp>
#include <railstab/scene/scene_spec.hpp>

#include <gtest/gtest.h>

#include <random>

using namespace railstab;

namespace {

struct Pair {
  BodyTpl<double> body[2];
  TrackFrameKinematics frame[2];
  Eigen::Matrix<double, 6, 1> q[2], qd[2];
};

Pair random_pair(std::mt19937& rng, bool wheelset1) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Pair p;
  for (int i = 0; i < 2; ++i) {
    p.body[i].mass_kg = 1000.0;
    p.body[i].inertia_kg_m2 = Eigen::Vector3d(300, 400, 500);
    if (i == 0 && wheelset1) p.body[i].kind = WheelsetKind{};
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

// The element kinds under test, each with random parameters; `damped`
// false gives the purely elastic twin.
enum class Kind {
  spring_3d, rotational, series, line_linear, line_table, bump_stop, traction_rod, anti_roll_bar
};
const char* kind_name(Kind k) {
  switch (k) {
    case Kind::spring_3d: return "spring_3d";
    case Kind::rotational: return "rotational";
    case Kind::series: return "series";
    case Kind::line_linear: return "line_linear";
    case Kind::line_table: return "line_table";
    case Kind::bump_stop: return "bump_stop";
    case Kind::traction_rod: return "traction_rod";
    case Kind::anti_roll_bar: return "anti_roll_bar";
  }
  return "?";
}

ElementSpec element(Kind kind, std::mt19937& rng, bool damped) {
  std::uniform_real_distribution<double> u(0.2, 1.0);
  ElementEnds ends;
  ends.point1_m = Eigen::Vector3d(0.5, -0.3, 0.2);
  ends.point2_m = Eigen::Vector3d(-0.4, 0.6, 0.1);
  const double c = damped ? 1.0 : 0.0;
  switch (kind) {
    case Kind::spring_3d: {
      SpringDamper3d<double> e;
      e.ends = ends;
      e.stiffness_N_per_m = Eigen::Vector3d(1e5 * u(rng), 2e5 * u(rng), 3e5 * u(rng));
      e.damping_N_s_per_m = c * Eigen::Vector3d(1e3 * u(rng), 2e3 * u(rng), 3e3 * u(rng));
      e.preload_N = Eigen::Vector3d(100.0, -50.0, 30.0);
      e.free_vector_m = Eigen::Vector3d(0.1, 0.0, -0.05);
      return e;
    }
    case Kind::rotational: {
      RotationalSpringDamper<double> e;
      e.ends = ends;
      // Isotropic and without a constant moment: exactly conservative (a
      // constant moment is conservative only to first order in the rotation).
      e.stiffness_N_m_per_rad = Eigen::Vector3d::Constant(3e5);
      e.damping_N_m_s_per_rad = c * Eigen::Vector3d(1e3 * u(rng), 2e3 * u(rng), 3e3 * u(rng));
      return e;
    }
    case Kind::series: {
      SeriesSpringDamper<double> e;
      e.ends = ends;
      e.series_stiffness_N_per_m = 2e6 * u(rng);
      e.set_damper(ForceCharacteristic<double>::linear(1e4 * u(rng)));
      e.free_length_m = 1.1;
      return e;
    }
    case Kind::line_linear:
    case Kind::line_table: {
      LineSpringDamper<double> e;
      e.ends = ends;
      e.free_length_m = 1.1;
      e.preload_N = 250.0;
      if (kind == Kind::line_linear) {
        e.spring = ForceCharacteristic<double>::linear(1e5 * u(rng));
        e.damper = ForceCharacteristic<double>::linear(c * 2e3 * u(rng));
      } else {
        e.spring = ForceCharacteristic<double>::table({-0.5, -0.1, 0.0, 0.05, 0.4},
                                                      {-9e4, -1e4, 0.0, 4e3, 1.2e5});
        e.damper = ForceCharacteristic<double>::table({-2.0, -0.1, 0.1, 2.0},  // blow-off
                                                      {-c * 4e3, -c * 2e3, c * 2e3, c * 4e3});
      }
      return e;
    }
    case Kind::bump_stop: {
      BumpStop<double> e;
      e.ends = ends;
      e.axis = Eigen::Vector3d(0.2, 1.0, 0.1).normalized();
      e.clearance_m = 0.02;
      e.stiffness_N_per_m = 5e5 * u(rng);
      e.progressive_stiffness_N_per_m3 = 1e8 * u(rng);
      e.contact_smoothing_m = 0.005;
      e.free_vector_m = Eigen::Vector3d(0.1, 0.0, -0.05);
      return e;
    }
    case Kind::traction_rod: {
      TractionRod<double> e;
      e.ends = ends;
      e.stiffness_N_per_m = 5e6 * u(rng);
      e.damping_N_s_per_m = c * 5e3 * u(rng);
      e.preload_N = -300.0;
      e.free_length_m = 1.1;
      return e;
    }
    case Kind::anti_roll_bar: {
      AntiRollBar<double> e;
      e.ends = ends;
      e.roll_stiffness_N_m_per_rad = 3e6 * u(rng);
      e.link_half_spacing_m = 1.2;
      e.preload_N_m = 400.0;
      e.free_vector_left_m = Eigen::Vector3d(0.1, 0.0, -0.05);
      e.free_vector_right_m = Eigen::Vector3d(0.1, 0.0, 0.02);
      return e;
    }
  }
  throw std::logic_error("kind");
}

// Internal state of the element (series: damper elongation), held fixed.
const double kInternalState = 0.013;

double potential(const ElementSpec& e, std::array<BodyMotion<double>, 2>& m) {
  const Attachment<double> a1 = attachment_of(m[0]), a2 = attachment_of(m[1]);
  return std::visit([&](const auto& el) { return el.potential(a1, a2, &kInternalState); }, e);
}

// Power of the element's forces and moments on both bodies.
double element_power(const ElementSpec& e, std::array<BodyMotion<double>, 2>& m,
                     Eigen::Vector3d* net_force = nullptr, Eigen::Vector3d* net_moment = nullptr) {
  for (auto& mi : m) mi.force_W.setZero(), mi.moment_W.setZero();
  const Attachment<double> a1 = attachment_of(m[0]), a2 = attachment_of(m[1]);
  double z_rate = 0.0;
  std::visit([&](const auto& el) { el.apply(a1, a2, &kInternalState, &z_rate); }, e);
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

class ElementKinds : public ::testing::TestWithParam<std::tuple<Kind, bool>> {};

// Springs are conservative: element power = -dV/dt (internal states held),
// checked against a central difference of V along the motion (h = 1e-6 s:
// error ~1e-12 relative), to 1e-6 relative.
TEST_P(ElementKinds, SpringIsConservative) {
  const auto [kind, wheelset1] = GetParam();
  std::mt19937 rng(11);
  for (int trial = 0; trial < 20; ++trial) {
    Pair p = random_pair(rng, wheelset1);
    if (wheelset1) p.qd[0](4) = 0.0;  // the axle-box frame does not spin; V ignores pitch
    const ElementSpec e = element(kind, rng, false);
    const double h = 1e-6;
    auto mp = motions(p, h), mm = motions(p, -h), m0 = motions(p, 0.0);
    const double dVdt = (potential(e, mp) - potential(e, mm)) / (2 * h);
    const double power = element_power(e, m0);
    EXPECT_NEAR(power, -dVdt, 1e-6 * std::max(1.0, std::abs(dVdt))) << kind_name(kind);
  }
}

// Dampers dissipate: the damping part's power is <= 0 and, for the linear
// kinds, -r^T C r (r: dd/dt for the 3D element, the relative angular
// velocity for the rotational one, dl/dt for line elements).
// Instantiated only for the kinds with a parallel damper (DampedKinds below).
class DampedKinds : public ElementKinds {};
TEST_P(DampedKinds, DamperDissipates) {
  const auto [kind, wheelset1] = GetParam();
  std::mt19937 rng(5);
  for (int trial = 0; trial < 20; ++trial) {
    const Pair p = random_pair(rng, wheelset1);
    std::mt19937 rng_copy = rng;
    const ElementSpec damped = element(kind, rng, true);
    const ElementSpec elastic = element(kind, rng_copy, false);
    auto m = motions(p, 0.0);
    const double elastic_power = element_power(elastic, m);
    const double damper_power = element_power(damped, m) - elastic_power;
    const Attachment<double> a1 = attachment_of(m[0]), a2 = attachment_of(m[1]);
    const ElementEnds& ends = ends_of(damped);
    double expected = 0.0;
    if (const auto* e = std::get_if<SpringDamper3d<double>>(&damped)) {
      const Eigen::Vector3d r = axis_deflection(a1, ends.point1_m, a2, ends.point2_m).d_rate;
      expected = -r.dot(e->damping_N_s_per_m.cwiseProduct(r));
    } else if (const auto* e = std::get_if<RotationalSpringDamper<double>>(&damped)) {
      const Eigen::Vector3d r = a1.R_WF.transpose() * (a2.w_W - a1.w_W);
      expected = -r.dot(e->damping_N_m_s_per_rad.cwiseProduct(r));
    } else {
      const double r = line_motion(a1, ends.point1_m, a2, ends.point2_m).rate_m_per_s;
      if (const auto* e = std::get_if<LineSpringDamper<double>>(&damped))
        expected = -e->damper.value(r) * r;
      else if (const auto* e = std::get_if<TractionRod<double>>(&damped))
        expected = -e->damping_N_s_per_m * r * r;
    }
    EXPECT_LE(damper_power, 0.0) << kind_name(kind);
    // The damper's power is a difference of two evaluations: round-off of
    // the elastic part's power counts as well.
    EXPECT_NEAR(damper_power, expected, 1e-9 * (std::abs(expected) + std::abs(elastic_power)))
        << kind_name(kind);
  }
}

// Forces equal and opposite, no net moment (actio = reactio).
TEST_P(ElementKinds, EqualAndOpposite) {
  const auto [kind, wheelset1] = GetParam();
  std::mt19937 rng(2);
  for (int trial = 0; trial < 20; ++trial) {
    const Pair p = random_pair(rng, wheelset1);
    const ElementSpec e = element(kind, rng, true);
    auto m = motions(p, 0.0);
    Eigen::Vector3d F, M;
    element_power(e, m, &F, &M);
    const double scale = m[0].force_W.norm() * 20.0 + m[0].moment_W.norm() + 1.0;
    EXPECT_LT(F.norm(), 1e-12 * scale) << kind_name(kind);
    EXPECT_LT(M.norm(), 1e-11 * scale) << kind_name(kind);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Elements, ElementKinds,
    ::testing::Combine(::testing::Values(Kind::spring_3d, Kind::rotational, Kind::series,
                                         Kind::line_linear, Kind::line_table, Kind::bump_stop,
                                         Kind::traction_rod, Kind::anti_roll_bar),
                       ::testing::Bool()));
INSTANTIATE_TEST_SUITE_P(
    Elements, DampedKinds,
    ::testing::Combine(::testing::Values(Kind::spring_3d, Kind::rotational, Kind::line_linear,
                                         Kind::line_table, Kind::traction_rod),
                       ::testing::Bool()));
