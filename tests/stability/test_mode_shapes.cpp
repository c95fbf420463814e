// Mode shapes and energy shares (stability/mode_shape.hpp) against closed
// forms: a two-mass chain on lateral springs (frequencies, shape ratio,
// kinetic and potential shares from the hand-derived 2 x 2 problem) and a
// body swaying on springs below its centre of mass (lower / upper sway from
// the roll centre of the hand-derived eigenvectors).
#include <gtest/gtest.h>

#include <railstab/eigen/eigen_analysis.hpp>
#include <railstab/equilibrium/equilibrium.hpp>
#include <railstab/linear/linearization.hpp>
#include "model/scene_builders.hpp"
#include <railstab/setup/build_model.hpp>
#include <railstab/stability/mode_names.hpp>
#include <railstab/stability/mode_shape.hpp>
#include <railstab/stability/modes.hpp>
#include <railstab/setup/prepare_scene.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace railstab;

namespace {

constexpr double kPi = 3.14159265358979323846;

// track -k1- a -k2- b along y; only y free; no damping, no gravity effect.
SceneSpec two_mass_chain(double m1, double m2, double k1, double k2, double c2 = 0.0) {
  SceneSpec s;
  s.name = "two_mass_chain";
  s.speed_m_per_s = 10.0;
  s.reference_arc_length_m = 100.0;
  s.track = test::straight_track();
  s.preload = PreloadMode::none;
  for (auto [name, m] : {std::pair{"a", m1}, std::pair{"b", m2}}) {
    BodySpec b = test::rigid_body(name, 0.0, 1.0);
    b.mass_kg = m;
    b.free = {false, true, false, false, false, false};
    s.bodies.push_back(b);
  }
  s.elements.push_back(test::spring("k1", kTrackBodyName, "a", {0, 0, 1}, {0, 0, 0}, {0, k1, 0}));
  s.elements.push_back(
      test::spring("k2", "a", "b", {0, 0, 0}, {0, 0, 0}, {0, k2, 0}, {0, c2, 0}));
  return s;
}

struct Linearised {
  Model model;
  Eigen::VectorXd x;
  LinearModel lin;
  std::vector<ModeReport> modes;
  Eigen::MatrixXd K;
};

Linearised linearise(const SceneSpec& spec) {
  Model model = build_model(spec);
  const double v = spec.speed_m_per_s;
  const EquilibriumResult eq = solve_equilibrium(model, v, initial_state(model, v));
  LinearModel lin = linearize(model, v, eq.state);
  std::vector<ModeReport> modes = describe_modes(model, lin, eigen_dense(lin.A), v);
  Eigen::MatrixXd K = suspension_stiffness(model, v, 0.0, eq.state);
  return {std::move(model), eq.state, std::move(lin), std::move(modes), std::move(K)};
}

}  // namespace

TEST(ModeShape, TwoMassChainMatchesClosedForm) {
  const double m1 = 1200.0, m2 = 500.0, k1 = 4e5, k2 = 1.5e5;
  const Linearised s = linearise(two_mass_chain(m1, m2, k1, k2));
  // The stiffness of the elements in y: [[k1 + k2, -k2], [-k2, k2]].
  ASSERT_EQ(s.K.rows(), 2);
  EXPECT_NEAR(s.K(0, 0), k1 + k2, 1e-6 * k1);
  EXPECT_NEAR(s.K(0, 1), -k2, 1e-6 * k1);
  EXPECT_NEAR(s.K(1, 0), -k2, 1e-6 * k1);
  EXPECT_NEAR(s.K(1, 1), k2, 1e-6 * k1);
  // Closed form: det(K - w^2 M) = 0; shape q = (1, r), r = (k1 + k2 - w^2 m1) / k2.
  const double a = m1 * m2, b = -(m1 * k2 + m2 * (k1 + k2)), c = k1 * k2;
  int checked = 0;
  for (const double w2 : {(-b - std::sqrt(b * b - 4 * a * c)) / (2 * a),
                          (-b + std::sqrt(b * b - 4 * a * c)) / (2 * a)}) {
    const double f = std::sqrt(w2) / (2 * kPi);
    const ModeReport* mode = nullptr;
    for (const ModeReport& m : s.modes)
      if (m.eigenvalue.imag() > 0 && std::abs(m.frequency_hz - f) < 1e-6 * f) mode = &m;
    ASSERT_NE(mode, nullptr) << "no mode at " << f << " Hz";
    const double r = (k1 + k2 - w2 * m1) / k2;
    const ModeShape shape = mode_shape(s.model, s.lin, s.K, mode->eigenvalue, mode->vector);
    ASSERT_EQ(shape.coordinates.size(), 2u);
    // Normalised to the larger lateral displacement (real, 1).
    const double q1 = std::abs(r) > 1 ? 1 / r : 1.0, q2 = std::abs(r) > 1 ? 1.0 : r;
    EXPECT_NEAR(shape.coordinates[0].displacement.real(), q1, 1e-8);
    EXPECT_NEAR(shape.coordinates[1].displacement.real(), q2, 1e-8);
    EXPECT_NEAR(shape.coordinates[0].displacement.imag(), 0.0, 1e-8);
    EXPECT_NEAR(shape.coordinates[1].displacement.imag(), 0.0, 1e-8);
    EXPECT_EQ(shape.reference, std::abs(r) > 1 ? 1 : 0);
    // Kinetic: m_i q_i^2 / sum; potential: q_i (K q)_i / q^T K q, by hand.
    const double t1 = m1, t2 = m2 * r * r;
    const double v1 = (k1 + k2) - k2 * r, v2 = k2 * r * (r - 1.0);
    ASSERT_TRUE(shape.potential_defined);
    EXPECT_NEAR(shape.coordinates[0].kinetic_share, t1 / (t1 + t2), 1e-9);
    EXPECT_NEAR(shape.coordinates[1].kinetic_share, t2 / (t1 + t2), 1e-9);
    EXPECT_NEAR(shape.coordinates[0].potential_share, v1 / (v1 + v2), 1e-9);
    EXPECT_NEAR(shape.coordinates[1].potential_share, v2 / (v1 + v2), 1e-9);
    // Undamped normal mode: K q = w^2 M q, so both splits agree.
    EXPECT_NEAR(shape.coordinates[0].potential_share, shape.coordinates[0].kinetic_share, 1e-9);
    ++checked;
  }
  EXPECT_EQ(checked, 2);
}

TEST(ModeShape, DampedChainSharesSumToOneAndPhaseIsRelative) {
  // With a damper the modes are complex: the reference keeps phase 0 and
  // amplitude 1 and each share set still sums to 1.
  const Linearised s = linearise(two_mass_chain(1200.0, 500.0, 4e5, 1.5e5, 3e3));
  for (const ModeReport& m : s.modes) {
    const ModeShape shape = mode_shape(s.model, s.lin, s.K, m.eigenvalue, m.vector);
    ASSERT_GE(shape.reference, 0);
    EXPECT_DOUBLE_EQ(std::abs(shape.coordinates[size_t(shape.reference)].displacement), 1.0);
    EXPECT_DOUBLE_EQ(std::arg(shape.coordinates[size_t(shape.reference)].displacement), 0.0);
    double t = 0, v = 0;
    for (const CoordinateMotion& c : shape.coordinates) {
      t += c.kinetic_share;
      v += c.potential_share;
      EXPECT_GE(c.kinetic_share, 0.0);
    }
    EXPECT_NEAR(t, 1.0, 1e-12);
    ASSERT_TRUE(shape.potential_defined);
    EXPECT_NEAR(v, 1.0, 1e-12);
  }
}

TEST(ModeShape, SizeMismatchIsRefused) {
  const Linearised s = linearise(two_mass_chain(1200.0, 500.0, 4e5, 1.5e5));
  EXPECT_THROW(mode_shape(s.model, s.lin, Eigen::MatrixXd::Zero(3, 3), s.modes[0].eigenvalue,
                          s.modes[0].vector),
               std::invalid_argument);
  EXPECT_THROW(mode_shape(s.model, s.lin, s.K, s.modes[0].eigenvalue, Eigen::VectorXcd::Zero(1)),
               std::invalid_argument);
}

// A body of mass m and roll inertia J on a lateral spring k_y at height -h
// below its centre of mass and two vertical springs k_z at y = +-w (roll
// stiffness 2 k_z w^2). A point at height z moves laterally by y - z roll,
// so the spring stretches by y + h roll:
//   K = [[k_y, k_y h], [k_y h, k_y h^2 + 2 k_z w^2]], M = diag(m, J).
// Roll centre of a mode: z_rc = y / roll. The hand-solved eigenvectors say
// which mode has its roll centre above the CM (lower sway) and which below
// (upper sway); the names must say the same.
TEST(ModeNames, SwayModesNamedByTheirRollCentre) {
  const double m = 30000.0, J = 50000.0, ky = 4e5, kz = 6e5, h = 1.2, w = 1.0;
  SceneSpec s;
  s.name = "sway";
  s.speed_m_per_s = 10.0;
  s.reference_arc_length_m = 100.0;
  s.track = test::straight_track();
  s.preload = PreloadMode::none;
  BodySpec body = test::rigid_body("car", 0.0, 2.0);
  body.mass_kg = m;
  body.inertia_kg_m2 = Eigen::Vector3d(J, 1e6, 1e6);
  body.free = {false, true, false, true, false, false};
  s.bodies.push_back(body);
  s.elements.push_back(
      test::spring("lateral", kTrackBodyName, "car", {0, 0, 2.0 - h}, {0, 0, -h}, {0, ky, 0}));
  for (double side : {-1.0, 1.0})
    s.elements.push_back(test::spring(side > 0 ? "left" : "right", kTrackBodyName, "car",
                                      {0, side * w, 2.0}, {0, side * w, 0}, {0, 0, kz}));
  const Linearised lin = linearise(s);
  Eigen::Matrix2d K, M;
  K << ky, ky * h, ky * h, ky * h * h + 2 * kz * w * w;
  M << m, 0, 0, J;
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d> hand(K, M);
  ASSERT_EQ(hand.info(), Eigen::Success);
  int named = 0;
  for (int k = 0; k < 2; ++k) {
    const double f = std::sqrt(hand.eigenvalues()(k)) / (2 * kPi);
    const double roll_centre = hand.eigenvectors()(0, k) / hand.eigenvectors()(1, k);
    for (const ModeReport& mode : lin.modes) {
      if (mode.eigenvalue.imag() <= 0 || std::abs(mode.frequency_hz - f) > 1e-6 * f) continue;
      EXPECT_EQ(mode.name, roll_centre > 0 ? "car body lower sway" : "car body upper sway")
          << f << " Hz, roll centre " << roll_centre << " m above the CM";
      ++named;
    }
  }
  EXPECT_EQ(named, 2);
}

TEST(ModeNames, SuffixesMakeNamesUniqueAndConjugatesShareTheirMatesName) {
  std::vector<std::string> names = {"car body yaw", "car body yaw", "x", "car body yaw", "x"};
  make_names_unique(names, {-1, -1, -1, -1, 2}, {3.0, 1.0, 2.0, 2.0, 2.0});
  EXPECT_EQ(names[1], "car body yaw");      // lowest key first
  EXPECT_EQ(names[3], "car body yaw (2)");
  EXPECT_EQ(names[0], "car body yaw (3)");
  EXPECT_EQ(names[2], "x");
  EXPECT_EQ(names[4], "x");  // a copy of entry 2, not counted
}

TEST(ModeRanking, LeastDampedIgnoresADecayingRealRootThatHasTheLargestRealPart) {
  std::vector<ModeReport> modes(3);
  modes[0].eigenvalue = {-0.1, 0.0};  // overdamped real root: ratio 1
  modes[1].eigenvalue = {-1.0, 2 * kPi * 5.0};
  modes[2].eigenvalue = {-1.0, -2 * kPi * 5.0};
  for (ModeReport& m : modes) {
    const ModeInfo i = mode_info(m.eigenvalue);
    m.frequency_hz = i.frequency_hz;
    m.damping_ratio = i.damping_ratio;
    m.lateral_share = 1.0;
  }
  EXPECT_EQ(least_stable_mode(modes, 20.0), 0);  // the real part decides stability
  EXPECT_EQ(least_damped_mode(modes, 20.0), 1);  // the tables rank by damping ratio
  EXPECT_EQ(least_damped_mode(modes, 1.0), 0);   // above the band: only the real root is left
  // A lightly damped mode outside the lateral plane (bounce, longitudinal)
  // is not ranked; it still counts for stability by its real part.
  modes.push_back(modes[1]);
  modes.back().eigenvalue = {-0.2, 2 * kPi * 1.0};
  modes.back().damping_ratio = mode_info(modes.back().eigenvalue).damping_ratio;
  modes.back().frequency_hz = 1.0;
  modes.back().lateral_share = 0.1;
  EXPECT_EQ(least_damped_mode(modes, 20.0), 1);
  EXPECT_EQ(least_damped_mode(modes, 20.0, 0.0), 3);
}

// describe_mode_shapes (what describe_modes names the modes from) takes a
// complex pair's partner's shape as the conjugate of
// the pair's, forms the shape basis once, and picks the six largest shares
// by a partial sort: each must give what the plain computation gives (the
// shape of every mode by mode_shape on its own, the participation by a
// stable sort of all shares), bit for bit, on the thesis vehicle (37
// complex pairs).
TEST(ModeShape, DescribeModesShortcutsMatchThePlainComputation) {
  const PreparedScene s =
      prepare_scene(std::string(RAILSTAB_CASES_DIR) + "/thesis_vehicle_tangent.toml", {});
  const LinearModel lin = linearize(s.model, s.speed_m_per_s, s.equilibrium.state);
  const std::vector<EigenPair> pairs = eigen_dense(lin.A);
  const std::vector<ModeReport> modes = describe_modes(s.model, lin, pairs, s.speed_m_per_s);
  const std::vector<ModeShape> shapes = describe_mode_shapes(s.model, lin, pairs);
  ASSERT_EQ(modes.size(), pairs.size());
  ASSERT_EQ(shapes.size(), pairs.size());
  int partners = 0;
  for (size_t i = 0; i < pairs.size(); ++i) {
    if (i > 0 && pairs[i].value == std::conj(pairs[i - 1].value)) ++partners;
    const ModeShape plain =
        mode_shape(s.model, lin, Eigen::MatrixXd(), pairs[i].value, pairs[i].vector);
    const ModeShape& got = shapes[i];
    EXPECT_EQ(got.reference, plain.reference) << i;
    ASSERT_EQ(got.coordinates.size(), plain.coordinates.size());
    std::vector<int> order;
    for (size_t k = 0; k < plain.coordinates.size(); ++k) {
      EXPECT_EQ(got.coordinates[k].displacement, plain.coordinates[k].displacement) << i << " " << k;
      EXPECT_EQ(got.coordinates[k].kinetic_share, plain.coordinates[k].kinetic_share) << i << " " << k;
      order.push_back(int(k));
    }
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
      return plain.coordinates[size_t(a)].kinetic_share > plain.coordinates[size_t(b)].kinetic_share;
    });
    ASSERT_EQ(modes[i].participation.size(), std::min<size_t>(6, order.size()));
    for (size_t k = 0; k < modes[i].participation.size(); ++k) {
      const CoordinateMotion& c = plain.coordinates[size_t(order[k])];
      EXPECT_EQ(modes[i].participation[k].body, s.model.bodies[size_t(c.body)].name) << i;
      EXPECT_EQ(modes[i].participation[k].coordinate, c.coordinate) << i;
      EXPECT_EQ(modes[i].participation[k].share, c.kinetic_share) << i;
    }
  }
  EXPECT_GE(partners, 30);  // the conjugate shortcut was exercised
}
