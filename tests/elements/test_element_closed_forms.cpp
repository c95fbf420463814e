// Each suspension element against a closed form:
//  - series_spring_damper: the eigenvalues of a one-mass oscillator on a
//    parallel spring k0 and a series element (k, c) satisfy
//    m s^2 + k0 + k c s / (k + c s) = 0, i.e. they are the roots of the cubic
//    m c s^3 + m k s^2 + (k0 + k) c s + k0 k = 0; the damper elongation is a
//    state of the linear model and appears in the eigenvector;
//  - bump_stop: force at given deflections, k g + k3 g^3 beyond the
//    clearance, zero inside it, odd in the deflection;
//  - traction_rod: stiffness k along its line, only second order across it;
//  - line_spring_damper with a table: passes through the table points,
//    continues linearly, its potential is the integral of its force.
#include <railstab/eigen/eigen_analysis.hpp>
#include <railstab/equilibrium/equilibrium.hpp>
#include "integrate/integration_scenes.hpp"
#include <railstab/linear/linearization.hpp>
#include <railstab/setup/build_model.hpp>

#include <gtest/gtest.h>

#include <complex>

using namespace railstab;

namespace {

// An attachment fixed in W at `origin`, axes aligned with W, at rest.
Attachment<double> fixed_frame(const Eigen::Vector3d& origin) {
  Attachment<double> a;
  a.R_WF.setIdentity();
  a.origin_W = origin;
  a.origin_v_W.setZero();
  a.w_W.setZero();
  return a;
}

// Force on body 2 (an attachment with a body) by element e, with body 2's
// attachment at `offset` from body 1's.
template <class Element>
Eigen::Vector3d force_on_body2(const Element& e, const Eigen::Vector3d& offset) {
  BodyMotion<double> m2;
  m2.force_W.setZero();
  m2.moment_W.setZero();
  m2.spinning_moment_W.setZero();
  Attachment<double> a1 = fixed_frame(Eigen::Vector3d::Zero());
  Attachment<double> a2 = fixed_frame(offset);
  a2.body = &m2;
  double z = 0.0, zdot = 0.0;
  e.apply(a1, a2, &z, &zdot);
  return m2.force_W;
}

struct SeriesOscillator {
  double mass_kg = 1000.0;
  double k0 = 4.0e5;      // parallel spring, N/m
  double k = 2.0e6;       // series (rubber end) stiffness, N/m
  double c = 3.0e4;       // damper, N s/m

  SceneSpec scene() const {
    SceneSpec s = test::LateralOscillator{}.scene();
    auto& spring = std::get<SpringDamper3d<double>>(s.elements[0]);
    spring.stiffness_N_per_m = Eigen::Vector3d(0.0, k0, 0.0);
    spring.damping_N_s_per_m.setZero();
    SeriesSpringDamper<double> series;
    series.ends.name = "yaw_damper";
    series.ends.body1_name = kTrackBodyName;
    series.ends.body2_name = "body";
    series.ends.point1_m = Eigen::Vector3d(0.0, -0.8, 1.0);  // a lateral line, 0.8 m long
    series.ends.point2_m = Eigen::Vector3d::Zero();
    series.series_stiffness_N_per_m = k;
    series.set_damper(ForceCharacteristic<double>::linear(c));
    s.elements.push_back(series);
    s.bodies[0].initial_offset = {0, 0, 0, 0, 0, 0};
    return s;
  }
};

}  // namespace

TEST(SeriesSpringDamper, EigenvaluesSatisfyTheComplexStiffness) {
  const SeriesOscillator o;
  const SceneSpec spec = o.scene();
  const Model model = build_model(spec);
  ASSERT_EQ(model.n_internal_states, 1);
  ASSERT_EQ(model.state_size(), 3);  // y, y', damper elongation
  EXPECT_EQ(model.state_name(2), "yaw_damper.damper_elongation_m");
  const double V = spec.speed_m_per_s;
  const EquilibriumResult eq = solve_equilibrium(model, V, nominal_state(model, V));
  const LinearModel lin = linearize(model, V, eq.state);
  ASSERT_EQ(lin.A.rows(), 3);
  const std::vector<EigenPair> pairs = eigen_dense(lin.A);
  ASSERT_EQ(pairs.size(), 3u);
  // Roots of the cubic, from its companion matrix.
  const double a3 = o.mass_kg * o.c, a2 = o.mass_kg * o.k, a1 = (o.k0 + o.k) * o.c,
               a0 = o.k0 * o.k;
  Eigen::Matrix3d companion;
  companion << -a2 / a3, -a1 / a3, -a0 / a3, 1, 0, 0, 0, 1, 0;
  const Eigen::VectorXcd roots = companion.eigenvalues();
  for (const EigenPair& p : pairs) {
    const std::complex<double> s = p.value;
    const std::complex<double> K = o.k * o.c * s / (o.k + o.c * s);  // complex stiffness
    const std::complex<double> balance = o.mass_kg * s * s + o.k0 + K;
    EXPECT_LT(std::abs(balance), 1e-9 * o.mass_kg * std::norm(s)) << "s = " << s;
    double nearest = 1e300;
    for (int i = 0; i < 3; ++i) nearest = std::min(nearest, std::abs(roots(i) - s));
    EXPECT_LT(nearest, 1e-9 * std::abs(s)) << "s = " << s;
    // The damper elongation moves in every mode (it is a state like any other).
    EXPECT_GT(std::abs(p.vector(2)), 1e-6 * p.vector.norm());
  }
}

// Stiff series spring: the element is the damper alone (K -> c s); soft
// series spring: the oscillator's own frequency sqrt(k0 / m) is undamped
// in the limit. Both limits of the complex stiffness, to 1 %.
TEST(SeriesSpringDamper, LimitsOfTheSeriesStiffness) {
  SeriesOscillator stiff;
  stiff.k = 1e10;
  const SceneSpec stiff_spec = stiff.scene();
  const Model m1 = build_model(stiff_spec);
  const double V = stiff_spec.speed_m_per_s;
  const LinearModel lin1 = linearize(m1, V, nominal_state(m1, V));
  const double wn = std::sqrt(stiff.k0 / stiff.mass_kg);
  const double zeta = stiff.c / (2.0 * std::sqrt(stiff.k0 * stiff.mass_kg));
  bool found = false;
  for (const EigenPair& p : eigen_dense(lin1.A)) {
    if (std::abs(p.value.imag()) < 1e-9) continue;  // the fast real root k/c
    EXPECT_NEAR(-p.value.real(), zeta * wn, 0.01 * zeta * wn);
    EXPECT_NEAR(std::abs(p.value.imag()), wn * std::sqrt(1 - zeta * zeta), 0.01 * wn);
    found = true;
  }
  EXPECT_TRUE(found);

  SeriesOscillator soft;
  soft.k = 1.0;
  const Model m2 = build_model(soft.scene());
  const LinearModel lin2 = linearize(m2, V, nominal_state(m2, V));
  for (const EigenPair& p : eigen_dense(lin2.A)) {
    if (std::abs(p.value.imag()) < 1e-9) continue;
    EXPECT_NEAR(std::abs(p.value.imag()), wn, 1e-3 * wn);
    EXPECT_LT(-p.value.real(), 1e-3 * wn);
  }
}

TEST(BumpStop, ForceAtGivenDeflections) {
  BumpStop<double> stop;
  stop.axis = Eigen::Vector3d::UnitY();
  stop.clearance_m = 0.030;
  stop.stiffness_N_per_m = 1.0e6;
  stop.progressive_stiffness_N_per_m3 = 5.0e9;
  stop.contact_smoothing_m = 5e-4;
  stop.ends.point1_m.setZero();
  stop.ends.point2_m.setZero();
  stop.free_vector_m.setZero();
  // Beyond clearance + smoothing the force is exact: 5 mm into the stop.
  for (double sign : {1.0, -1.0}) {
    const double g = 0.005;
    const Eigen::Vector3d f = force_on_body2(stop, Eigen::Vector3d(0, sign * (0.030 + g), 0));
    const double expected = 1.0e6 * g + 5.0e9 * g * g * g;  // 5625 N
    EXPECT_NEAR(f.y(), -sign * expected, 1e-9 * expected);
    EXPECT_NEAR(f.x(), 0.0, 1e-12);
    EXPECT_NEAR(f.z(), 0.0, 1e-12);
  }
  // Inside the clearance (short of the smoothing zone): no force at all.
  for (double u : {0.0, 0.01, -0.0294})
    EXPECT_EQ(force_on_body2(stop, Eigen::Vector3d(0, u, 0)).y(), 0.0) << u;
  // Across the smoothing zone: continuous force and stiffness (C1), the
  // force at the clearance itself k w / 4 (the blend's midpoint).
  const double at_clearance = -force_on_body2(stop, Eigen::Vector3d(0, 0.030, 0)).y();
  EXPECT_NEAR(at_clearance, 1.0e6 * 5e-4 / 4.0 + 5.0e9 * std::pow(5e-4 / 4.0, 3), 1e-9);
  const double h = 1e-7;
  for (double u : {0.0295, 0.0305}) {  // the two ends of the blend
    auto F = [&](double x) { return -force_on_body2(stop, Eigen::Vector3d(0, x, 0)).y(); };
    const double left = (F(u) - F(u - h)) / h, right = (F(u + h) - F(u)) / h;
    EXPECT_NEAR(left, right, 1e-3 * 1.0e6 + 1e-6 * std::abs(right)) << u;
  }
}

TEST(TractionRod, StiffAlongItsLineFreeAcrossToFirstOrder) {
  TractionRod<double> rod;
  rod.ends.point1_m.setZero();
  rod.ends.point2_m.setZero();
  rod.stiffness_N_per_m = 2.0e7;
  rod.free_length_m = 0.5;
  const double e = 1e-4;
  const Eigen::Vector3d along = force_on_body2(rod, Eigen::Vector3d(0.5 + e, 0, 0));
  EXPECT_NEAR(along.x(), -2.0e7 * e, 1e-6 * 2.0e7 * e);
  // Across the rod by d: the length grows by ~d^2 / (2 L), the force with it.
  const double d = 1e-3;
  const Eigen::Vector3d across = force_on_body2(rod, Eigen::Vector3d(0.5, d, 0));
  const double stretch = std::sqrt(0.25 + d * d) - 0.5;
  EXPECT_NEAR(across.norm(), 2.0e7 * stretch, 1e-9 * 2.0e7 * stretch);
  EXPECT_LT(std::abs(across.y()), 1e-2 * 2.0e7 * d);  // vs 2e4 N for a bush of that stiffness
}

TEST(ForceCharacteristic, TablePassesThroughPointsAndIntegratesToItsPotential) {
  const std::vector<double> x = {-0.4, -0.1, 0.0, 0.05, 0.3};
  const std::vector<double> f = {-8e4, -1e4, 0.0, 4e3, 9e4};
  const auto k = ForceCharacteristic<double>::table(x, f);
  for (size_t i = 0; i < x.size(); ++i) EXPECT_NEAR(k.value(x[i]), f[i], 1e-9);
  // Linear continuation beyond the ends with the end segments' slopes.
  EXPECT_NEAR(k.value(0.5), 9e4 + (9e4 - 4e3) / 0.25 * 0.2, 1e-6);
  EXPECT_NEAR(k.value(-0.6), -8e4 + (7e4 / 0.3) * (-0.2), 1e-6);
  // Monotone table -> monotone curve (no overshoot between points).
  for (double u = -0.5; u < 0.5; u += 1e-3) EXPECT_LE(k.value(u), k.value(u + 1e-3));
  // Potential = integral of the force (Simpson, 2000 panels per segment).
  for (double end : {-0.55, -0.07, 0.02, 0.2, 0.45}) {
    const int n = 20000;
    const double h = end / n;
    double sum = k.value(0.0) + k.value(end);
    for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * k.value(i * h);
    EXPECT_NEAR(k.integral(end), sum * h / 3.0, 1e-7 * std::abs(sum * h / 3.0) + 1e-9) << end;
  }
}

// A body free in roll only, held by an anti-roll bar alone (links at its
// centre height, a = 1.1 m): the linearised roll is an undamped oscillator
// of frequency sqrt(k_roll / Jx); bounce does not twist the bar.
TEST(AntiRollBar, RollStiffnessIsTheBarsStiffness) {
  SceneSpec s = test::LateralOscillator{}.scene();
  s.elements.clear();
  s.bodies[0].free = {false, false, false, true, false, false};
  s.bodies[0].initial_offset = {0, 0, 0, 0, 0, 0};
  AntiRollBar<double> bar;
  bar.ends.name = "arb";
  bar.ends.body1_name = kTrackBodyName;
  bar.ends.body2_name = "body";
  bar.ends.point1_m = Eigen::Vector3d(0.3, 0.0, 1.0);  // arm ends at the body's centre height
  bar.ends.point2_m = Eigen::Vector3d(0.3, 0.0, 0.0);
  bar.roll_stiffness_N_m_per_rad = 2.5e6;
  bar.link_half_spacing_m = 1.1;
  s.elements.push_back(bar);
  const Model model = build_model(s);
  const double V = s.speed_m_per_s;
  const LinearModel lin = linearize(model, V, nominal_state(model, V));
  ASSERT_EQ(lin.A.rows(), 2);
  const double omega = std::sqrt(2.5e6 / s.bodies[0].inertia_kg_m2.x());
  for (const EigenPair& p : eigen_dense(lin.A)) {
    EXPECT_NEAR(std::abs(p.value.imag()), omega, 1e-9 * omega);
    EXPECT_NEAR(p.value.real(), 0.0, 1e-9 * omega);
  }
  // Bounce: both links deflect alike, no twist, no force.
  const Eigen::Vector3d f = force_on_body2(bar, Eigen::Vector3d(0.0, 0.0, 0.01));
  EXPECT_EQ(f.norm(), 0.0);
}
