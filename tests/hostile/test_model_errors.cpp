// Issue 10, model half: errors raised deep in the model say where they arose
// (file, stage, speed, arc length, the body or contact, the scene key most
// likely responsible) and never start with an internal function name; a
// sweep that loses its steady state half-way still reports what it found,
// marked partial; a lateral initial offset starts with both wheels on the
// rails.
#include <gtest/gtest.h>

#include <railstab/scene_reading/load_scene.hpp>
#include <railstab/model/equations_of_motion.hpp>
#include <railstab/setup/model_error_context.hpp>
#include <railstab/setup/prepare_scene.hpp>
#include <railstab/stability/speed_analysis.hpp>

#include <fstream>
#include <sstream>
#include <string>

using namespace railstab;

namespace {

const std::string kCases = RAILSTAB_CASES_DIR;

const PreparedScene& bogie_tangent() {
  static const PreparedScene scene = prepare_scene(kCases + "/thesis_bogie_tangent.toml", {});
  return scene;
}

bool has(const std::string& message, const std::string& fragment) {
  return message.find(fragment) != std::string::npos;
}

}  // namespace

// The Hertz message of issue 10, raised at a state where wheelset1 is far
// off centre: the rethrown error names the file, the stage, the speed and
// place, the wheelset and its offset, and the contact table to look at.
TEST(ModelErrors, HertzFailureNamesWheelsetContactSpeedAndPlace) {
  const PreparedScene& s = bogie_tangent();
  Eigen::VectorXd x = s.equilibrium.state;
  const int ky = s.model.bodies[0].state_index[int(CoordinateIndex::y)];
  ASSERT_GE(ky, 0);
  x(ky) += 0.1886;
  EvaluationPlace place{"steady state", 20.0, 0.0, &x};
  std::string message;
  try {
    with_model_context(s.model, place, [&]() -> int {
      throw std::domain_error(
          "hertz_shape: relative curvatures must be positive and finite, got A = -0.2 1/m");
    });
  } catch (const ModelError& e) {  // a runtime_error: a sweep can stop on it
    message = e.what();
  }
  EXPECT_EQ(message.rfind(kCases + "/thesis_bogie_tangent.toml: steady state of scene "
                                   "'thesis_bogie_tangent' at V = 20 m/s, reference point at arc "
                                   "length 100 m: Hertz contact ellipse: relative curvatures",
                          0),
            0u)
      << message;
  EXPECT_TRUE(has(message, "bodies[0] ('wheelset1') is 188.6 mm off centre (flange clearance "
                           "7.5 mm)"))
      << message;
  EXPECT_TRUE(has(message, "Most likely responsible: contacts.thesis_knife_edge "
                           "(nominal_rolling_radius_m"))
      << message;
  EXPECT_TRUE(has(message, "primary_ws1_left")) << message;  // the elements on wheelset1
  EXPECT_FALSE(has(message, "hertz_shape")) << message;
}

// A non-finite entry in the linear model (masses of 1e-300 did that before
// the ranges): the column's body is named with its mass and inertia keys.
TEST(ModelErrors, NonFiniteMatrixNamesTheBodyOfTheColumn) {
  const PreparedScene& s = bogie_tangent();
  Eigen::MatrixXd A = Eigen::MatrixXd::Identity(3, 3);
  A(1, 2) = std::nan("");
  const std::vector<std::string> names = {"wheelset1.y_m", "wheelset2.yaw_m", "bogie1.yaw_rad"};
  EvaluationPlace place{"eigen-analysis", 30.0, 0.0};
  place.matrix = &A;
  place.matrix_state_names = &names;
  std::string message;
  try {
    with_model_context(s.model, place, [&]() -> int {
      throw std::invalid_argument("eigen_dense: matrix has NaN or infinite entries");
    });
  } catch (const ModelError& e) {
    message = e.what();
  }
  EXPECT_TRUE(has(message, "eigen-analysis of scene 'thesis_bogie_tangent' at V = 30 m/s"))
      << message;
  EXPECT_TRUE(has(message, "eigenvalues (dense solver): matrix has NaN or infinite entries"))
      << message;
  EXPECT_TRUE(has(message, "Most likely responsible: bodies[2] ('bogie1'): its mass_kg and "
                           "inertia_kg_m2"))
      << message;
  EXPECT_FALSE(has(message, "eigen_dense")) << message;
}

// Past the end of the track during a run: the reference arc length, the
// offsets and t_end_s are named, with the track length.
TEST(ModelErrors, OffTheTrackNamesArcLengthKeysAndTrackLength) {
  const PreparedScene& s = bogie_tangent();
  std::string message;
  try {
    with_model_context(s.model, {"time integration", 20.0, 300.0}, [&] {
      return rhs(s.model, 20.0, 300.0, s.equilibrium.state);  // 100 + 6000 m > 4200 m
    });
  } catch (const ModelError& e) {
    message = e.what();
  }
  EXPECT_TRUE(has(message, "reference point at arc length 6100 m (t = 300 s)")) << message;
  EXPECT_TRUE(has(message, "Most likely responsible: scene.reference_arc_length_m (or "
                           "--arc-length)"))
      << message;
  EXPECT_TRUE(has(message, "simulation.t_end_s")) << message;
  EXPECT_TRUE(has(message, "the track is 4200 m long")) << message;
}

// Issue 10: "a y initial offset leaves one wheel out of contact at t = 0".
// The naive start (equilibrium + offset) has a wheel out of contact (so this
// test can fail); the start state solves z and roll: both wheels of
// wheelset1 carry load, z and roll accelerations vanish, y is as given.
TEST(ModelErrors, LateralInitialOffsetStartsWithBothWheelsInContact) {
  const PreparedScene& s = bogie_tangent();
  const Model& m = s.model;
  const Body& ws = m.bodies[0];
  const int n = m.n_coordinates;
  const int ky = ws.state_index[int(CoordinateIndex::y)];
  const int kz = ws.state_index[int(CoordinateIndex::z)];
  const int kroll = ws.state_index[int(CoordinateIndex::roll)];
  auto loads = [&](const Eigen::VectorXd& x) {
    EvaluationDetails details;
    rhs(m, s.speed_m_per_s, 0.0, x, &details);
    std::vector<double> n_N;
    for (const ContactSnapshot& c : details.contacts)
      if (c.body == 0) n_N.push_back(c.wheel.normal_force_N);
    return n_N;
  };
  Eigen::VectorXd naive = s.equilibrium.state;
  naive(ky) += 0.001;
  const std::vector<double> naive_loads = loads(naive);
  ASSERT_EQ(naive_loads.size(), 2u);
  EXPECT_EQ(std::min(naive_loads[0], naive_loads[1]), 0.0) << "precondition: a wheel lifts";

  const Eigen::VectorXd x0 = perturbed_initial_state(s);
  EXPECT_DOUBLE_EQ(x0(ky), s.equilibrium.state(ky) + 0.001);
  const std::vector<double> start_loads = loads(x0);
  ASSERT_EQ(start_loads.size(), 2u);
  // Both wheels carry about half the wheelset's share of the weight (~25 kN).
  EXPECT_GT(std::min(start_loads[0], start_loads[1]), 1e4);
  const Eigen::VectorXd xdot = rhs(m, s.speed_m_per_s, 0.0, x0);
  EXPECT_LT(std::abs(xdot(n + kz)), 1e-6);
  EXPECT_LT(std::abs(xdot(n + kroll)), 1e-6);
  // The roll follows the cones: lambda y / (e0 - r0 lambda) for the knife-edge
  // contact (the value the extreme_* cases give by hand, 1.4235e-4 per mm).
  const double lambda = std::tan(0.1);
  EXPECT_NEAR(x0(kroll) - s.equilibrium.state(kroll), lambda * 0.001 / (0.75 - 0.45 * lambda), 2e-6);
}

// No vertical primary stiffness: the bogie has nothing to rest on, so the
// preload sag has no equilibrium. The message names the stage (on the
// straight twin, so no arc length of the user's track), the bogie and the
// elements that should hold it.
TEST(ModelErrors, PreloadSagWithoutSupportNamesTheBodyAndItsElements) {
  std::ifstream in(kCases + "/thesis_bogie_tangent.toml");
  std::stringstream text;
  text << in.rdbuf();
  std::string scene = text.str();
  const std::string stiff = "stiffness_N_per_m = [3.9e7, 7.85e6, 9.75e5]";
  for (size_t at = scene.find(stiff); at != std::string::npos; at = scene.find(stiff, at))
    scene.replace(at, stiff.size(), "stiffness_N_per_m = [3.9e7, 7.85e6, 0.0]");
  std::string message;
  try {
    prepare_scene(load_scene_text(scene, "soft.toml"));
  } catch (const ModelError& e) {
    message = e.what();
  }
  EXPECT_EQ(message.rfind("soft.toml: static sag on straight, level track for the suspension "
                          "preloads (preload = 'balance_gravity_at_nominal') of scene "
                          "'thesis_bogie_tangent' at V = 20 m/s: no equilibrium",
                          0),
            0u)
      << message;
  EXPECT_FALSE(has(message, "arc length")) << message;
  EXPECT_TRUE(has(message, "state bogie1.z_m/s")) << message;
  EXPECT_TRUE(has(message, "Most likely responsible: the elements that hold bodies[2] ('bogie1') "
                           "(primary_ws1_left, primary_ws1_right, primary_ws2_left, "
                           "primary_ws2_right)"))
      << message;
}
