// An asymmetric wheelset in a scene and in the vehicle model: the right
// wheel's tape-circle radius 1 mm smaller (right_nominal_rolling_radius_m;
// EN 15302's 920/918 mm wheelsets). With 1 mm the equilibrium (-3.2 mm) lies
// on a smooth part of S1002's delta r; with 0.5 mm it would sit on the
// tread's contact jump near -0.3 mm (delta r jumps there from 0.47 to
// 0.98 mm), where no smooth steady state exists to converge to.
// - The scene builds a right pair and a right table of its own.
// - The vehicle model uses them: on the tangent the thesis bogie's steady
//   state puts each wheelset where its rolling radii are equal (no
//   longitudinal creep: pure rolling), which is the rigid-contact
//   equilibrium of contact-geometry (delta_r = 0, independently found from
//   the profiles), to 5 % of the offset (the suspension's and gravity's
//   lateral forces shift it slightly; measured below).
#include <railstab/contact_geometry/contact_geometry_summary.hpp>
#include <railstab/contact_geometry/profile_contact_geometry.hpp>
#include <railstab/equilibrium/equilibrium.hpp>
#include <railstab/scene_reading/load_scene.hpp>
#include <railstab/setup/build_model.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include "support/state_index.hpp"
#include "support/test_files.hpp"

using namespace railstab;

namespace {

// The thesis bogie on S1002 with `extra` added to its contact table (profile
// paths made absolute so the copy may live anywhere).
std::string bogie_scene_with(const std::string& extra, const std::string& name) {
  std::string text = test::read_text(test::case_path("thesis_bogie_s1002_tangent"));
  const std::string rel = "\"profiles/";
  for (size_t at = text.find(rel); at != std::string::npos; at = text.find(rel, at))
    text.replace(at, rel.size(), "\"" + std::string(RAILSTAB_CASES_DIR) + "/profiles/");
  const std::string header = "[contacts.s1002_uic60]\n";
  const size_t at = text.find(header);
  EXPECT_NE(at, std::string::npos);
  text.insert(at + header.size(), extra);
  const auto dir = test::fresh_dir("asymmetric", name);
  const std::string path = (dir / "bogie.toml").string();
  std::ofstream(path) << text;
  return path;
}

}  // namespace

TEST(AsymmetricWheelset, VehicleModelRunsWhereTheRadiiAreEqual) {
  const double dr = 0.001;
  const SceneSpec spec = load_scene_file(
      bogie_scene_with("right_nominal_rolling_radius_m = " + std::to_string(0.45 - dr) + "\n",
                       "radii"));
  const Model model = build_model(spec);
  const ProfileContactGeometry& g = *model.contacts.front().spec.profile_geometry;
  ASSERT_TRUE(g.asymmetric());
  ASSERT_TRUE(g.right_table.has_value());
  EXPECT_DOUBLE_EQ(g.pair_for(-1).parameters.nominal_rolling_radius_m, 0.45 - dr);
  // The rigid-contact equilibrium from the profiles: delta_r = 0 at y_EN;
  // the wheelset centre lies r0_mean sin(roll) from it.
  const ContactGeometrySummary rigid = summarise_contact_geometry(g.pairs());
  ASSERT_TRUE(std::isfinite(rigid.equilibrium.low_m));
  const RigidContactSolution at_eq = solve_rigid_contact(
      g.pairs(), rigid.equilibrium.centre_m(), 0.0, LateralShiftReference::en15302);
  const double y_c = at_eq.centre_lateral_m;
  EXPECT_LT(y_c, -1e-4);  // towards the smaller right wheel

  const double V = 20.0;
  EquilibriumOptions o;
  o.acceleration_tolerance = 1e-9;
  const Eigen::VectorXd x = solve_equilibrium(model, V, lowered_nominal_state(model, V), o).state;
  for (const char* ws : {"wheelset1.y_m", "wheelset2.y_m"}) {
    SCOPED_TRACE(ws);
    const double y = x(test::state_index(model, ws));
    EXPECT_NEAR(y, y_c, 0.05 * std::abs(y_c)) << "rigid-contact equilibrium " << y_c;
    std::cout << ws << " = " << y * 1e3 << " mm; rigid-contact equilibrium (wheelset centre) "
              << y_c * 1e3 << " mm\n";
  }
}

// A scene that builds a vehicle model still needs the force models: without
// `normal` the error names the key (a contact-only file for
// contact-geometry does not need it: test_cli_contact_geometry_en15302).
TEST(AsymmetricWheelset, AVehicleSceneStillNeedsItsNormalForceModel) {
  const std::string path = bogie_scene_with("", "normal");
  std::string text = test::read_text(path);
  const size_t at = text.find("normal = \"hertz\"");
  ASSERT_NE(at, std::string::npos);
  text.erase(at, std::string("normal = \"hertz\"").size());
  std::ofstream(path) << text;
  try {
    (void)load_scene_file(path);
    ADD_FAILURE() << "expected an error";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("contacts.s1002_uic60.normal"), std::string::npos)
        << e.what();
  }
}

