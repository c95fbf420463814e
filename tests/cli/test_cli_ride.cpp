// simulate's and equilibrium's ride quantities from the command line: the
// files, their columns, the measure points of the scene, the summary's
// Prud'homme limits, and the reader's refusals (docs/ride_quantities.md).
#include <gtest/gtest.h>

#include "cli/run_cli.hpp"
#include "support/json_text.hpp"
#include "support/test_files.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace railstab {
namespace {

// The thesis vehicle in the arc with a measure point on the car body (the
// last [[bodies]] table of the file, so an appended
// [[bodies.measure_points]] belongs to it).
fs::path scene_with_measure_point(const fs::path& dir, const std::string& extra = "") {
  const fs::path scene = dir / "vehicle.toml";
  std::ofstream(scene) << test::read_text(test::case_path("thesis_vehicle_curve")) << "\n"
                       << "[[bodies.measure_points]]\nname = \"seat\"\nposition_m = [8.0, 1.0, 0.5]\n"
                       << extra;
  return scene;
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream in(line);
  for (std::string f; std::getline(in, f, ',');) fields.push_back(f);
  if (!line.empty() && line.back() == ',') fields.push_back("");
  return fields;
}

std::vector<std::string> lines(const fs::path& p) {
  std::vector<std::string> out;
  std::ifstream in(p);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

TEST(CliRide, SimulateWritesWheelForcesAndAccelerationsWithPlots) {
  const fs::path dir = test::fresh_dir("cli", "ride_simulate");
  const fs::path scene = scene_with_measure_point(dir);
  const auto run = test::run_railstab({"simulate", scene.string(), "--arc-length", "1400", "--t-end", "0.5",
                                       "--no-error-estimate", "--out", "out"},
                                      dir);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const fs::path out = dir / "out";
  const std::string stem = "vehicle_20mps";  // the scene file's stem
  for (const std::string suffix : {"_wheel_forces.csv", "_accelerations.csv", "_sum_y.png", "_y_over_q.png",
                                   "_lateral_acceleration.png", "_vertical_acceleration.png",
                                   "_ride_plots.gp"})
    EXPECT_TRUE(fs::is_regular_file(out / (stem + suffix))) << suffix;
  const std::vector<std::string> forces = lines(out / (stem + "_wheel_forces.csv"));
  ASSERT_GE(forces.size(), 51u);  // header and 51 output times
  const std::vector<std::string> header = split(forces[0]);
  ASSERT_EQ(header.size(), 1u + 4u * 10u);
  EXPECT_EQ(header[1], "wheelset1.sum_y_N");
  EXPECT_EQ(header[5], "wheelset1.left.y_over_q");
  EXPECT_EQ(header[10], "wheelset1.right.delta_q_over_q0");
  for (size_t i = 1; i < forces.size(); ++i) {
    const std::vector<std::string> row = split(forces[i]);
    ASSERT_EQ(row.size(), header.size()) << forces[i];
    for (const std::string& f : row) EXPECT_FALSE(f.empty()) << "no lifted wheel here: " << forces[i];
  }
  const std::vector<std::string> acc = split(lines(out / (stem + "_accelerations.csv"))[0]);
  // bogie1, bogie2, carbody and carbody.seat, three components each.
  ASSERT_EQ(acc.size(), 1u + 4u * 3u);
  EXPECT_EQ(acc[11], "carbody.seat.lateral_acceleration_m_per_s2");
  // The summary: Prud'homme's limit from the static axle load.
  const std::string json = test::read_text(out / (stem + "_run.json"));
  const double left = std::stod(test::json_value(json, "static_wheel_load_left_N"));
  const double right = std::stod(test::json_value(json, "static_wheel_load_right_N"));
  const double limit = std::stod(test::json_value(json, "prudhomme_limit_N"));
  EXPECT_NEAR(limit, 10e3 + (left + right) / 3.0, 1e-6 * limit);
  EXPECT_GT(left, 50e3);  // the thesis vehicle: ~74 kN per wheel
  // 20 m/s at 0.01 s: 0.2 m between outputs, so the 2 m means are given.
  const double mean_2m = std::stod(test::json_value(json, "max_abs_sum_y_2m_N"));
  EXPECT_LE(mean_2m, std::stod(test::json_value(json, "max_abs_sum_y_N")) + 1e-6);
  EXPECT_GT(mean_2m, 1e3);  // steady curving: Sum Y ~ 27 kN
  fs::remove_all(dir);
}

TEST(CliRide, EquilibriumReportsSumYAngleOfAttackAndUnloading) {
  const fs::path dir = test::fresh_dir("cli", "ride_equilibrium");
  const auto run = test::run_railstab(
      {"equilibrium", test::case_path("thesis_vehicle_curve"), "--arc-length", "1400", "--out", "out"}, dir);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const std::string json =
      test::read_text(dir / "out" / "thesis_vehicle_curve_arc1400m_equilibrium_20mps.json");
  for (const std::string key : {"sum_y_N", "angle_of_attack_rad", "prudhomme_limit_N",
                                "sum_y_over_prudhomme_limit", "delta_q_over_q0", "static_wheel_load_N"})
    EXPECT_NE(test::json_value(json, key), "<missing>") << key;
  EXPECT_NE(run.output.find("Sum Y"), std::string::npos) << run.output;
  fs::remove_all(dir);
}

TEST(CliRide, MeasurePointsOnAWheelsetAndBadFactorsAreRefusedByKey) {
  const fs::path dir = test::fresh_dir("cli", "ride_refusals");
  // A wheelset as the last body: the point would belong to it.
  const fs::path on_wheelset = dir / "wheelset.toml";
  std::ofstream(on_wheelset) << test::read_text(test::case_path("textbook_wheelset")) << "\n"
                             << "[[bodies.measure_points]]\nname = \"p\"\nposition_m = [0, 0, 0]\n";
  auto run = test::run_railstab({"equilibrium", on_wheelset.string()}, dir);
  EXPECT_NE(run.exit_code, 0);
  EXPECT_NE(run.output.find("measure_points"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("wheelset"), std::string::npos) << run.output;
  const fs::path twice = scene_with_measure_point(
      dir, "[[bodies.measure_points]]\nname = \"seat\"\nposition_m = [1.0, 0.0, 0.0]\n");
  run = test::run_railstab({"equilibrium", twice.string()}, dir);
  EXPECT_NE(run.exit_code, 0);
  EXPECT_NE(run.output.find("unique"), std::string::npos) << run.output;
  const fs::path bad_factor = scene_with_measure_point(dir, "[assessment]\nprudhomme_factor = -1\n");
  run = test::run_railstab({"equilibrium", bad_factor.string(), "--out", "out"}, dir);
  EXPECT_NE(run.exit_code, 0);
  EXPECT_NE(run.output.find("assessment.prudhomme_factor"), std::string::npos) << run.output;
  EXPECT_FALSE(fs::exists(dir / "out"));  // nothing written
  fs::remove_all(dir);
}

}  // namespace
}  // namespace railstab
