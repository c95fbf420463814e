// The passenger coach (cases/coach_tangent.toml): its static equilibrium is
// the nominal configuration (preloads), and its critical speed behaves as
// the yaw dampers' series stiffness says it must: a damper in series with a
// spring k_s has the complex stiffness k_s c s / (k_s + c s), which tends to
// the plain damper's c s as k_s -> infinity.
#include <railstab/scene_reading/load_scene.hpp>
#include <railstab/scene_reading/scene_checker.hpp>
#include <railstab/model/equations_of_motion.hpp>
#include <railstab/setup/prepare_scene.hpp>
#include <railstab/stability/speed_analysis.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <variant>

using namespace railstab;

namespace {

const std::string kCoach = std::string(RAILSTAB_CASES_DIR) + "/coach_tangent.toml";

// The coach with every yaw damper's series stiffness set to k_s.
SceneSpec with_series_stiffness(double k_s) {
  SceneSpec spec = load_scene_file(kCoach);
  int changed = 0;
  for (ElementSpec& e : spec.elements)
    if (auto* s = std::get_if<SeriesSpringDamper<double>>(&e)) {
      s->series_stiffness_N_per_m = k_s;
      ++changed;
    }
  EXPECT_EQ(changed, 4);  // two per bogie
  return spec;
}

// The coach with every yaw damper replaced by a plain damper (same ends,
// same force-velocity characteristic, no series spring).
SceneSpec with_plain_dampers() {
  SceneSpec spec = load_scene_file(kCoach);
  int changed = 0;
  for (ElementSpec& e : spec.elements)
    if (const auto* s = std::get_if<SeriesSpringDamper<double>>(&e)) {
      LineSpringDamper<double> plain;
      plain.ends = s->ends;
      plain.spring = ForceCharacteristic<double>::linear(0.0);
      plain.damper = s->damper;
      e = plain;
      ++changed;
    }
  EXPECT_EQ(changed, 4);
  return spec;
}

// Critical speed searched on [from, to] (a narrow bracket keeps the test fast).
double critical_speed(SceneSpec spec, double from, double to, double step) {
  validate_scene(spec);
  const PreparedScene s = prepare_scene(std::move(spec));
  CriticalSpeedOptions opt;
  opt.from_m_per_s = from;
  opt.to_m_per_s = to;
  opt.grid_step_m_per_s = step;
  const CriticalSpeedResult r = find_critical_speed(s.model, s.equilibrium.state, s.speed_m_per_s, opt);
  EXPECT_TRUE(r.critical_speed_found) << "no crossing in [" << from << ", " << to << "] m/s";
  EXPECT_FALSE(r.unstable_at_start);
  return r.critical_speed_m_per_s;
}

}  // namespace

// Preloads (ERRATA 13) make the nominal configuration the static
// equilibrium: the only offset is the rigid drop of the whole vehicle by the
// Hertz approach of the wheels, every suspension keeps its nominal deflection,
// and the vertical wheel-rail forces carry exactly the weight.
TEST(Coach, NominalIsTheStaticEquilibrium) {
  const PreparedScene s = prepare_scene(kCoach, {});
  const Model& model = s.model;
  EXPECT_LE(s.equilibrium.max_acceleration, 1e-7);
  Eigen::MatrixXd q6, qd6;
  model.full_coordinates(0.0, s.speed_m_per_s, s.equilibrium.state, q6, qd6);
  const int ws1 = model.find_body("wheelset1");
  const double drop_m = q6(2, ws1) - model.bodies[ws1].nominal_q(2);
  // The Hertz approach under ~54 kN: a fraction of a millimetre.
  EXPECT_LT(drop_m, 0.0);
  EXPECT_GT(drop_m, -0.2e-3);
  double mass_kg = 0.0;
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    mass_kg += model.bodies[b].mass_kg;
    SCOPED_TRACE(model.bodies[b].name);
    EXPECT_NEAR(q6(2, b) - model.bodies[b].nominal_q(2), drop_m, 1e-6);  // m
    EXPECT_NEAR(q6(1, b), model.bodies[b].nominal_q(1), 1e-9);           // lateral, m
    EXPECT_NEAR(q6(3, b), model.bodies[b].nominal_q(3), 1e-9);           // roll, rad
    EXPECT_NEAR(q6(5, b), model.bodies[b].nominal_q(5), 1e-9);           // yaw, rad
    if (!model.bodies[b].wheelset()) {
      EXPECT_NEAR(q6(4, b), model.bodies[b].nominal_q(4), 1e-5);  // pitch, rad
    }
  }
  EXPECT_NEAR(mass_kg, 32000.0 + 2 * 2615.0 + 4 * 1813.0, 1e-9);

  EvaluationDetails details;
  rhs(model, s.speed_m_per_s, 0.0, s.equilibrium.state, &details);
  ASSERT_EQ(details.contacts.size(), 8u);
  double vertical_N = 0.0;
  for (const ContactSnapshot& c : details.contacts) vertical_N += c.wheel.force_I.z();
  const double weight_N = mass_kg * s.spec.gravity_m_per_s2;
  EXPECT_NEAR(vertical_N / weight_N, 1.0, 1e-6);
}

// k_s -> infinity: the series element becomes the plain damper. At the
// hunting frequency (~3.3 Hz here) c w = 450e3 * 20.6 = 9.3e6 N/m, so
// k_s = 1e10 N/m differs from a rigid mount by ~0.1 % in the element's
// complex stiffness; the critical speeds agree to 0.5 %.
TEST(Coach, VeryStiffSeriesSpringIsThePlainDamper) {
  const double plain = critical_speed(with_plain_dampers(), 110.0, 130.0, 5.0);
  const double stiff = critical_speed(with_series_stiffness(1e10), 110.0, 130.0, 5.0);
  EXPECT_NEAR(stiff / plain, 1.0, 0.005) << "plain " << plain << " m/s, k_s = 1e10: " << stiff;
}

// On the soft side (k_s below c w at the hunting frequency) a stiffer series
// spring lets the damper act at the hunting frequency: the critical speed
// rises with k_s.
TEST(Coach, CriticalSpeedRisesWithSoftSeriesStiffness) {
  const double v1 = critical_speed(with_series_stiffness(1e6), 90.0, 230.0, 10.0);
  const double v2 = critical_speed(with_series_stiffness(2e6), 90.0, 230.0, 10.0);
  const double v5 = critical_speed(with_series_stiffness(5e6), 90.0, 230.0, 10.0);
  EXPECT_LT(v1, v2);
  EXPECT_LT(v2, v5);
  // The rise is substantial, not a numerical artefact (bisection to 0.01 m/s).
  EXPECT_GT(v2 - v1, 1.0);
  EXPECT_GT(v5 - v2, 1.0);
}

// Traction rods (bogie to car body, longitudinal) are adjusted at the loaded
// position and take no part in the gravity sag: with them the nominal
// configuration is still the static equilibrium (before: a rod fighting the
// 0.18 m air-spring sag got an 83 kN preload along its tilted line, and the
// car body settled 1.05 mm low at nominal).
TEST(Coach, TractionRodsKeepNominalTheStaticEquilibrium) {
  SceneSpec spec = load_scene_file(kCoach);
  for (const auto& bogie_and_side : {std::pair{"bogie1", 10.0}, std::pair{"bogie2", -10.0}}) {
    // (no structured binding: clang 14 cannot capture one in the lambda below)
    const std::string bogie = bogie_and_side.first;
    const double x_carbody = bogie_and_side.second;
    TractionRod<double> rod;
    rod.ends.name = "traction_rod_" + bogie;
    rod.ends.body1_name = bogie;
    rod.ends.body2_name = "carbody";
    rod.ends.point1_m = Eigen::Vector3d(x_carbody > 0 ? -0.5 : 0.5, 0.0, 0.0);
    const int b = [&] {
      for (size_t i = 0; i < spec.bodies.size(); ++i)
        if (spec.bodies[i].name == bogie) return int(i);
      return -1;
    }();
    ASSERT_GE(b, 0);
    // The car body point at the bogie frame's height, 0.5 m inboard.
    const BodySpec* carbody = nullptr;
    for (const BodySpec& body : spec.bodies)
      if (body.name == "carbody") carbody = &body;
    ASSERT_NE(carbody, nullptr);
    const double dx = spec.bodies[size_t(b)].track_offset_m - carbody->track_offset_m;
    rod.ends.point2_m = Eigen::Vector3d(dx + (x_carbody > 0 ? -1.0 : 1.0), 0.0,
                                        spec.bodies[size_t(b)].position_m.z() -
                                            carbody->position_m.z());
    rod.stiffness_N_per_m = 5e6;
    spec.elements.push_back(rod);
  }
  validate_scene(spec);
  const PreparedScene s = prepare_scene(std::move(spec));
  Eigen::MatrixXd q6, qd6;
  s.model.full_coordinates(0.0, s.speed_m_per_s, s.equilibrium.state, q6, qd6);
  const int ws1 = s.model.find_body("wheelset1"), car = s.model.find_body("carbody");
  const double drop_m = q6(2, ws1) - s.model.bodies[ws1].nominal_q(2);
  EXPECT_NEAR(q6(2, car) - s.model.bodies[car].nominal_q(2), drop_m, 1e-6);
  EXPECT_NEAR(q6(4, car), 0.0, 1e-7);  // no pitch
}
