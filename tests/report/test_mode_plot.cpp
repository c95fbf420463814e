// Plan-view mode plots (report/mode_plot.hpp): the drawn outlines move as the
// small-yaw kinematics says; `railstab modes` writes a PNG, an SVG and an
// animated GIF per mode, named after the mode, and refuses a selection that
// matches nothing.
#include <gtest/gtest.h>

#include "cli/run_cli.hpp"
#include <railstab/io/gnuplot.hpp>
#include <railstab/report/mode_plot.hpp>
#include <railstab/setup/prepare_scene.hpp>

#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace railstab;
namespace fs = std::filesystem;

TEST(ModePlot, OutlineFollowsLateralAndYawAtEachPhase) {
  ModeShape shape;
  // Body 0: lateral 1 (phase 0), yaw 0.1 rad lagging by 90 degrees.
  shape.coordinates = {{0, 1, {1.0, 0.0}, 0.5, 0.5}, {0, 5, {0.0, -0.1}, 0.5, 0.5}};
  BodyOutline o;
  o.body = 0;
  o.x_m = 3.0;
  o.half_length_m = 2.0;
  o.half_width_m = 1.0;
  const double a = 0.2;
  for (const double phase : {0.0, 0.5 * M_PI, 1.3}) {
    const auto c = displaced_outline(o, shape, a, phase);
    const double y = a * std::cos(phase), psi = a * 0.1 * std::sin(phase);  // Re(-0.1 i e^{i phase})
    // Corner 0 is (+L, +W): x = x0 + L - psi W, y = W + y + psi L.
    EXPECT_NEAR(c[0][0], 3.0 + 2.0 - psi * 1.0, 1e-12) << phase;
    EXPECT_NEAR(c[0][1], 1.0 + y + psi * 2.0, 1e-12) << phase;
    EXPECT_NEAR(c[2][0], 3.0 - 2.0 + psi * 1.0, 1e-12) << phase;
    EXPECT_NEAR(c[2][1], -1.0 + y - psi * 2.0, 1e-12) << phase;
    EXPECT_EQ(c[4], c[0]);  // closed
  }
  // The exaggeration draws the largest lateral corner motion at kDrawnAmplitude_m.
  EXPECT_NEAR(plan_view_exaggeration({o}, shape), kDrawnAmplitude_m / (1.0 + 0.1 * 2.0), 1e-12);
}

TEST(ModePlot, OutlinesOfTheThesisVehicle) {
  const PreparedScene s =
      prepare_scene(std::string(RAILSTAB_CASES_DIR) + "/thesis_vehicle_tangent.toml", {});
  const std::vector<BodyOutline> outlines = plan_view_outlines(s.model, body_roles(s.model));
  ASSERT_EQ(outlines.size(), 7u);
  for (const BodyOutline& o : outlines) {
    if (o.role != BodyRole::car_body) continue;
    // The car body covers every other outline's centre.
    for (const BodyOutline& other : outlines)
      EXPECT_LT(std::abs(other.x_m - o.x_m), o.half_length_m) << s.model.bodies[size_t(other.body)].name;
  }
}

TEST(ModesCommand, WritesPngAndSvgPerModeAndRefusesAnEmptySelection) {
  if (find_gnuplot().empty()) {
    GTEST_SKIP() << "gnuplot not installed";
  }
  const fs::path dir = fs::temp_directory_path() / ("railstab_modes_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string scene = std::string(RAILSTAB_CASES_DIR) + "/thesis_bogie_tangent.toml";
  const test::CliRun ok =
      test::run_railstab({"modes", scene, "--speed", "30", "--mode", "hunting", "--out", "o"}, dir);
  ASSERT_EQ(ok.exit_code, 0) << ok.output;
  int png = 0, svg = 0, gif = 0;
  for (const auto& e : fs::directory_iterator(dir / "o")) {
    const std::string name = e.path().filename().string();
    if (name.find("hunting") == std::string::npos) continue;
    if (e.path().extension() == ".png") ++png;
    if (e.path().extension() == ".svg") ++svg;
    if (e.path().extension() == ".gif") {
      ++gif;
      std::ifstream in(e.path(), std::ios::binary);
      char magic[6] = {};
      in.read(magic, 6);
      EXPECT_EQ(std::string(magic, 6), "GIF89a") << name;
    }
    if (e.path().extension() == ".png" || e.path().extension() == ".svg") {
      EXPECT_GT(fs::file_size(e.path()), 1000u) << name;
    }
  }
  EXPECT_GE(png, 1);
  EXPECT_EQ(png, svg);
  EXPECT_EQ(png, gif);
  const test::CliRun none = test::run_railstab(
      {"modes", scene, "--speed", "30", "--mode", "no such mode", "--out", "p"}, dir);
  EXPECT_NE(none.exit_code, 0);
  EXPECT_NE(none.output.find("--mode"), std::string::npos) << none.output;
  EXPECT_FALSE(fs::exists(dir / "p") && !fs::is_empty(dir / "p"));
  fs::remove_all(dir);
}
