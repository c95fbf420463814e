// Parameters as AD variables: the exact derivative of the state matrix with
// respect to a scene parameter (equilibrium shift and preloads included)
// against central differences of the whole pipeline (scene -> preloads ->
// equilibrium -> linearisation -> eigenvalues), on the thesis vehicle at
// 100 m/s for three parameters of different kinds: a secondary lateral
// damping (enters A directly), a primary longitudinal stiffness (moves the
// hunting mode most) and the car-body mass (moves the preloads and the
// equilibrium: the implicit-function terms).
#include <railstab/eigen/eigen_analysis.hpp>
#include <railstab/equilibrium/equilibrium.hpp>
#include <railstab/scene_reading/load_scene.hpp>
#include <railstab/linear/linearization.hpp>
#include <railstab/sensitivity/parameter_derivative.hpp>
#include <railstab/setup/build_model.hpp>
#include <railstab/stability/modes.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <complex>

using namespace railstab;

namespace {

const double kSpeed = 100.0;

SceneSpec vehicle() {
  return load_scene_file(std::string(RAILSTAB_CASES_DIR) + "/thesis_vehicle_tangent.toml");
}

LinearModel linear_model(const SceneSpec& scene) {
  SceneSpec s = scene;
  s.speed_m_per_s = kSpeed;
  const Model model = build_model(s);
  EquilibriumOptions eq;
  eq.acceleration_tolerance = 1e-9;
  const Eigen::VectorXd x = solve_equilibrium(model, kSpeed, lowered_nominal_state(model, kSpeed), eq).state;
  return linearize(model, kSpeed, x);
}

// The least stable lateral mode below 20 Hz (hunting, 4.2 Hz near the
// critical speed) and its right eigenvector.
EigenPair hunting_pair(const Model& model, const LinearModel& lin) {
  const std::vector<EigenPair> pairs = eigen_dense(lin.A);
  const std::vector<ModeReport> modes = describe_modes(model, lin, pairs, kSpeed);
  const int i = least_stable_lateral_mode(modes, 20.0);
  EXPECT_GE(i, 0);
  return pairs[size_t(std::max(i, 0))];
}

std::complex<double> nearest(const Eigen::MatrixXd& A, std::complex<double> target) {
  const std::vector<EigenPair> pairs = eigen_dense(A);
  std::complex<double> best = pairs.front().value;
  for (const EigenPair& p : pairs)
    if (std::abs(p.value - target) < std::abs(best - target)) best = p.value;
  return best;
}

// dA/dp and the hunting eigenvalue's d(lambda)/dp against central
// differences of the whole pipeline.
void check_against_central_differences(const SceneSpec& scene, const std::string& key) {
  const StateMatrixDerivative d = state_matrix_derivative(scene, kSpeed, key);
  const double p = d.parameter_value;
  ASSERT_GT(p, 0.0);

  // Central differences of the whole pipeline, step 1e-3 p: truncation
  // ~1e-6 relative; the equilibria (residual 1e-9) add noise ~1e-9 / 1e-3
  // relative to the change of A, which for a weak parameter (the primary
  // longitudinal stiffness moves the lateral mode by 1e-4 per unit of
  // relative change) sets the tolerances below.
  const double h = 1e-3 * p;
  const LinearModel plus = linear_model(with_parameter(scene, key, p + h));
  const LinearModel minus = linear_model(with_parameter(scene, key, p - h));
  ASSERT_EQ(plus.A.rows(), d.linear.A.rows());
  const Eigen::MatrixXd dA_fd = (plus.A - minus.A) / (2.0 * h);
  const double scale = d.A_derivative.cwiseAbs().maxCoeff();
  ASSERT_GT(scale, 0.0);
  EXPECT_LT((d.A_derivative - dA_fd).cwiseAbs().maxCoeff(), 1e-5 * scale) << key;

  // The hunting eigenvalue's derivative, (w^H dA v)/(w^H v).
  SceneSpec at_speed = scene;
  at_speed.speed_m_per_s = kSpeed;
  const EigenPair hunting = hunting_pair(build_model(at_speed), d.linear);
  const std::complex<double> dl =
      eigenvalue_derivative(d.linear.A, d.A_derivative, hunting.value, hunting.vector);
  const std::complex<double> dl_fd =
      (nearest(plus.A, hunting.value) - nearest(minus.A, hunting.value)) / (2.0 * h);
  std::printf("  %s = %g: d(lambda)/dp AD %.9g%+.9gi, central %.9g%+.9gi (lambda %.6g%+.6gi)\n",
              key.c_str(), p, dl.real(), dl.imag(), dl_fd.real(), dl_fd.imag(),
              hunting.value.real(), hunting.value.imag());
  EXPECT_GT(std::abs(dl) * p, 1e-6);  // the parameter matters for hunting
  EXPECT_LT(std::abs(dl - dl_fd), 2e-4 * std::abs(dl_fd)) << key;
}

}  // namespace

class ParameterDerivative : public ::testing::TestWithParam<const char*> {};

TEST_P(ParameterDerivative, StateMatrixAndEigenvalueAgreeWithCentralDifferences) {
  check_against_central_differences(vehicle(), GetParam());
}

INSTANTIATE_TEST_SUITE_P(ThesisVehicle, ParameterDerivative,
                         ::testing::Values("elements.secondary_bogie1.damping_N_s_per_m[1]",
                                           "elements.primary_ws1.stiffness_N_per_m[0]",
                                           "bodies.carbody.mass_kg",
                                           // Contact parameters (contact/model_contact.hpp):
                                           "contacts.thesis_knife_edge.cone_angle_rad"));

// The Kalker reduction factor (linear law), the friction coefficient and
// Polach's reduction factors (saturating laws): the thesis vehicle with each law (its knife-edge
// spin creepage, ~0.2 1/m at equilibrium, already loads the contact, so the
// friction coefficient moves the hunting mode at 100 m/s).
struct ContactLawCase {
  const char* law;
  const char* key;
};
class ContactParameterDerivative : public ::testing::TestWithParam<ContactLawCase> {};

TEST_P(ContactParameterDerivative, StateMatrixAndEigenvalueAgreeWithCentralDifferences) {
  SceneSpec scene = vehicle();
  ASSERT_EQ(scene.contacts.size(), 1u);
  const std::string law = GetParam().law;
  if (law == "linear_kalker") {  // reduction 0.8: room for the +h step below 1
    scene.contacts[0].creep_law = LinearKalkerCreep<double>{0.8};
  } else if (law == "shen_hedrick_elkins") {
    ShenHedrickElkinsCreep<double> she;
    she.friction_coefficient = 0.3;
    scene.contacts[0].creep_law = she;
  } else {
    PolachCreep<double> polach;
    polach.friction_coefficient = 0.3;
    scene.contacts[0].creep_law = polach;
  }
  const std::vector<std::string> keys = parameter_keys(scene);
  ASSERT_NE(std::find(keys.begin(), keys.end(), GetParam().key), keys.end()) << GetParam().key;
  check_against_central_differences(scene, GetParam().key);
}

INSTANTIATE_TEST_SUITE_P(
    CreepLaws, ContactParameterDerivative,
    ::testing::Values(
        ContactLawCase{"linear_kalker", "contacts.thesis_knife_edge.kalker_reduction_factor"},
        ContactLawCase{"shen_hedrick_elkins", "contacts.thesis_knife_edge.friction_coefficient"},
        ContactLawCase{"polach", "contacts.thesis_knife_edge.friction_coefficient"},
        ContactLawCase{"polach", "contacts.thesis_knife_edge.polach_slip_reduction_factor"}));

TEST(ParameterDerivativeKeys, UnknownKeyIsNamedWithTheKeysThatExist) {
  const SceneSpec scene = vehicle();
  try {
    state_matrix_derivative(scene, kSpeed, "elements.primary_ws9.stiffness_N_per_m[0]");
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("elements.primary_ws9.stiffness_N_per_m[0]"), std::string::npos) << m;
    EXPECT_NE(m.find("elements.primary_ws1.stiffness_N_per_m[0]"), std::string::npos) << m;
    EXPECT_NE(m.find("bodies.carbody.mass_kg"), std::string::npos) << m;
  }
  // Mirrored pairs are one scene entry: listed once, by the scene name.
  const std::vector<std::string> keys = parameter_keys(scene);
  EXPECT_EQ(std::count(keys.begin(), keys.end(), "elements.secondary_bogie2.damping_N_s_per_m[1]"), 1);
  EXPECT_EQ(std::count(keys.begin(), keys.end(), "elements.secondary_bogie2_left.damping_N_s_per_m[1]"), 0);
  // Contact keys by geometry and law: the knife-edge cone's angle, linear
  // Kalker's reduction factor; no friction coefficient (linear creep has none).
  EXPECT_EQ(std::count(keys.begin(), keys.end(), "contacts.thesis_knife_edge.cone_angle_rad"), 1);
  EXPECT_EQ(std::count(keys.begin(), keys.end(), "contacts.thesis_knife_edge.kalker_reduction_factor"), 1);
  EXPECT_EQ(std::count(keys.begin(), keys.end(), "contacts.thesis_knife_edge.conicity"), 0);
  EXPECT_EQ(std::count(keys.begin(), keys.end(), "contacts.thesis_knife_edge.friction_coefficient"), 0);
}

// The linear conicity (textbook bogie: r = r0 +/- lambda y).
TEST(ContactParameterDerivativeConicity, TextbookBogieAgreesWithCentralDifferences) {
  const SceneSpec scene =
      load_scene_file(std::string(RAILSTAB_CASES_DIR) + "/textbook_bogie.toml");
  ASSERT_EQ(scene.contacts.size(), 1u);
  check_against_central_differences(scene, "contacts." + scene.contacts[0].name + ".conicity");
}

// A table characteristic is a parameter through its scale factor (issue 24:
// the coach's yaw dampers, force-velocity tables in series with their end
// stiffness, had no parameter, so `sensitivity` left out the most influential
// element). dA/da of the scale a against central differences of the whole
// pipeline at a +- 1e-3 (A is linear in a through the damper's force; the
// series element divides the tension by a): the same tolerance as above.
TEST(TableScaleDerivative, CoachYawDamperScaleAgreesWithCentralDifferences) {
  const SceneSpec coach = load_scene_file(std::string(RAILSTAB_CASES_DIR) + "/coach_tangent.toml");
  const std::string key = "elements.yaw_damper_bogie1.damper_force_scale";
  const std::vector<std::string> keys = parameter_keys(coach);
  ASSERT_NE(std::find(keys.begin(), keys.end(), key), keys.end());
  // The table elements have no damping key (the table is not a coefficient).
  EXPECT_EQ(std::find(keys.begin(), keys.end(), "elements.yaw_damper_bogie1.damping_N_s_per_m"), keys.end());
  EXPECT_EQ(parameter_value(coach, key), 1.0);
  const StateMatrixDerivative d = state_matrix_derivative(coach, kSpeed, key);
  const double h = 1e-3;
  const Eigen::MatrixXd dA_fd =
      (linear_model(with_parameter(coach, key, 1.0 + h)).A - linear_model(with_parameter(coach, key, 1.0 - h)).A) /
      (2.0 * h);
  const double scale = d.A_derivative.cwiseAbs().maxCoeff();
  ASSERT_GT(scale, 0.0);
  EXPECT_LT((d.A_derivative - dA_fd).cwiseAbs().maxCoeff(), 1e-5 * scale);
  // The scale of 2 is the table with every force doubled (PCHIP slopes are
  // linear in the forces, so the interpolants agree to rounding).
  SceneSpec doubled = coach;
  for (ElementSpec& e : doubled.elements)
    if (auto* s = std::get_if<SeriesSpringDamper<double>>(&e); s && ends_of(e).name.rfind("yaw_damper_bogie1", 0) == 0) {
      ForceCharacteristic<double> table = s->damper;
      for (double& f : table.f) f *= 2.0;
      s->set_damper(ForceCharacteristic<double>::table(table.x, table.f));
    }
  const Eigen::MatrixXd A_scaled = linear_model(with_parameter(coach, key, 2.0)).A;
  const Eigen::MatrixXd A_doubled = linear_model(doubled).A;
  EXPECT_LT((A_scaled - A_doubled).cwiseAbs().maxCoeff(), 1e-9 * A_doubled.cwiseAbs().maxCoeff());
}
