// Profile contact (geometry = "profiles") in the equations of motion: the
// thesis vehicle on new S1002 / UIC60 1:40 (cases/thesis_vehicle_s1002_tangent.toml).
// - the static equilibrium on the tangent carries the vehicle's weight on the
//   wheels (sum of the wheel loads' vertical components = m g) symmetrically;
// - the AD Jacobian of the right-hand side equals central differences at
//   lateral shifts from the tread through the tread-to-flange transition into
//   flange contact (two-point contact included);
// - scene errors name the contact's key and the file.
#include <railstab/contact/wheel_rail.hpp>
#include <railstab/equilibrium/equilibrium.hpp>
#include <railstab/scene_reading/load_scene.hpp>
#include <railstab/setup/contact_tables.hpp>
#include <railstab/linear/jacobian.hpp>
#include <railstab/model/equations_of_motion.hpp>
#include <railstab/setup/build_model.hpp>

#include "support/state_index.hpp"

#include <gtest/gtest.h>

#include <fstream>

using namespace railstab;

namespace {

const std::string kScene = std::string(RAILSTAB_CASES_DIR) + "/thesis_vehicle_s1002_tangent.toml";

std::string scene_text() {
  std::ifstream in(kScene);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

const Model& vehicle() {
  static const Model model = build_model(load_scene_file(kScene));
  return model;
}

}  // namespace

TEST(ProfileContact, TangentEquilibriumCarriesTheWeightSymmetrically) {
  const Model& model = vehicle();
  const double V = 20.0;
  EquilibriumOptions o;
  o.acceleration_tolerance = 1e-9;
  const Eigen::VectorXd x = solve_equilibrium(model, V, lowered_nominal_state(model, V), o).state;
  EvaluationDetails details;
  rhs(model, V, 0.0, x, &details);
  double mass = 0.0;
  for (const Body& b : model.bodies) mass += b.mass_kg;
  double vertical = 0.0;
  double load[4][2] = {};  // [wheelset][left, right] normal load
  for (const ContactSnapshot& c : details.contacts) {
    // force_I is in I, which is the track frame here up to a roll of ~1e-16.
    vertical += c.wheel.force_I.z();
    if (c.body < 4) load[c.body][c.wheel.side > 0 ? 0 : 1] += c.wheel.normal_force_N;
  }
  EXPECT_NEAR(vertical, mass * model.gravity_m_per_s2, 1e-6 * mass * 9.81);
  for (int b = 0; b < 4; ++b) {
    EXPECT_GT(load[b][0], 0.0);
    EXPECT_NEAR(load[b][0], load[b][1], 1e-6 * load[b][0]) << "wheelset " << b;
    EXPECT_NEAR(x(test::state_index(model, model.bodies[size_t(b)].name + ".y_m")), 0.0, 1e-9);
  }
}

// Central differences with step h = 1e-8 (m, rad) against the AD Jacobian on
// the rows of wheelset1's accelerations and the columns of its lateral,
// vertical, roll and yaw positions, at lateral shifts on the tread (0.5, 3 mm,
// two-point contact at 0.5 mm), across the flange root (4.8 mm) and onto the
// flange (6.2, 6.5, 7 mm).
TEST(ProfileContact, AdJacobianMatchesCentralDifferencesFromTreadToFlange) {
  const Model& model = vehicle();
  const double V = 30.0;
  Eigen::VectorXd x0 = lowered_nominal_state(model, V);
  const int y = test::state_index(model, "wheelset1.y_m"), z = test::state_index(model, "wheelset1.z_m");
  const std::vector<int> columns = {y, z, test::state_index(model, "wheelset1.roll_rad"),
                                    test::state_index(model, "wheelset1.yaw_rad")};
  const std::vector<int> rows = {model.n_coordinates + y, model.n_coordinates + z,
                                 model.n_coordinates + columns[2],
                                 model.n_coordinates + columns[3]};
  const ModelContact& contact = model.contacts[0];
  int flange_points = 0;
  // Off the table's nodes (0.1 mm apart): at a node the interpolant is only
  // C1 and a difference quotient across it carries an O(h f'') error.
  for (double shift : {0.00053, 0.00303, 0.00483, 0.00623, 0.00653, 0.00703}) {
    Eigen::VectorXd x = x0;
    x(y) = shift;
    // 0.1 mm of overlap at the lowest point of the shifted wheelset.
    const ProfileContactGeometry& g = *contact.spec.profile_geometry;
    double lowest = 1e300;
    for (int side : {1, -1})
      lowest = std::min(lowest, g.table.lowest_vertical_gap(
                                    wheel_pose_in_rail_frame<double>(g.pair, side, shift, x(z), 0.0)));
    x(z) -= lowest + 1e-4;
    EvaluationDetails details;
    rhs(model, V, 0.0, x, &details);
    for (const ContactSnapshot& c : details.contacts)
      if (c.body == 0 && c.wheel.contact_angle_rad > 0.5) ++flange_points;
    const Eigen::MatrixXd J = rhs_jacobian_ad(model, V, 0.0, x);
    const double h = 1e-8;
    for (int col : columns) {
      Eigen::VectorXd xp = x, xm = x;
      xp(col) += h;
      xm(col) -= h;
      const Eigen::VectorXd fd = (rhs(model, V, 0.0, xp) - rhs(model, V, 0.0, xm)) / (2.0 * h);
      for (int row : rows) {
        const double scale = std::max(1.0, J.col(col).cwiseAbs().maxCoeff());
        EXPECT_NEAR(J(row, col), fd(row), 1e-5 * scale)
            << "shift " << shift * 1e3 << " mm, d " << model.state_name(row) << " / d "
            << model.state_name(col);
      }
    }
  }
  EXPECT_GE(flange_points, 2);  // 6.5 and 7 mm: in flange contact (angle > 0.5 rad)
}

TEST(ProfileContact, MissingProfileFileIsNamedWithItsKey) {
  std::string text = scene_text();
  const std::string from = "profiles/MBench_S1002_v3.prw";
  text.replace(text.find(from), from.size(), "profiles/no_such_wheel.prw");
  SceneSpec spec;
  ASSERT_NO_THROW(spec = load_scene_text(text, kScene));  // the reader only records the file
  try {
    build_contact_tables(spec);  // the set-up step reads it
    FAIL() << "no error";
  } catch (const std::exception& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("contacts.s1002_uic60"), std::string::npos) << m;
    EXPECT_NE(m.find("no_such_wheel.prw"), std::string::npos) << m;
  }
  // A key of the flangeless models does not belong with profiles.
  std::string text2 = scene_text();
  text2.replace(text2.find("geometry = \"profiles\""), 21,
                "geometry = \"profiles\"\ncone_angle_rad = 0.05");
  try {
    load_scene_text(text2, kScene);
    FAIL() << "no error";
  } catch (const std::exception& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("contacts.s1002_uic60.cone_angle_rad"), std::string::npos) << m;
  }
}
