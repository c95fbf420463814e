// `simulate` and `assess` on irregular track: the irregularities reach the
// contact (a vehicle started at rest in its steady state stays there on
// perfect track and moves on irregular track), and the outputs say which
// track was run.
#include <gtest/gtest.h>

#include "cli/run_cli.hpp"
#include "support/json_text.hpp"
#include "support/test_files.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace railstab {
namespace {

// Largest |wheelset1 lateral| in a motion CSV.
double largest_leading_lateral_m(const fs::path& csv) {
  std::ifstream in(csv);
  std::string header;
  std::getline(in, header);
  int column = -1, i = 0;
  std::stringstream names(header);
  for (std::string name; std::getline(names, name, ','); ++i)
    if (name == "wheelset1.y_m") column = i;
  EXPECT_GE(column, 0) << header;
  double largest = 0.0;
  for (std::string line; std::getline(in, line);) {
    std::stringstream row(line);
    std::string field;
    for (int k = 0; k <= column; ++k) std::getline(row, field, ',');
    largest = std::max(largest, std::abs(std::stod(field)));
  }
  return largest;
}

TEST(CliIrregularTrack, SimulateAndAssessRunOnTheIrregularities) {
  const fs::path dir = test::fresh_dir("cli", "irregular_run");
  const std::string base = test::read_text(test::case_path("thesis_vehicle_tangent"));
  std::ofstream(dir / "perfect.toml") << base;
  std::ofstream(dir / "irregular.toml") << base
                                        << "\n[track.irregularities]\npsd = \"erri_b176_low\"\nseed = 5\n"
                                           "length_m = 600.0\ncomponents = 400\namplitude_scale = 0.5\n";
  const std::vector<std::string> at_rest = {"--speed", "40", "--t-end", "2", "--offset", "wheelset1.y_m=0",
                                            "--no-plots"};
  auto args = [&](const std::string& command, const std::string& scene, const std::string& out) {
    std::vector<std::string> a = {command, (dir / scene).string(), "--out", out};
    a.insert(a.end(), at_rest.begin(), at_rest.end());
    return a;
  };
  auto run = test::run_railstab(args("simulate", "perfect.toml", "perfect"), dir);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  run = test::run_railstab(args("simulate", "irregular.toml", "irregular"), dir);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  // Outputs are named after each scene file (perfect.toml, irregular.toml).
  EXPECT_LT(largest_leading_lateral_m(dir / "perfect" / (std::string("perfect_40mps") + ".csv")), 1e-9);
  // Half ERRI B176 low: 1 mm rms alignment; the wheelset follows a good part of it.
  EXPECT_GT(largest_leading_lateral_m(dir / "irregular" / (std::string("irregular_40mps") + ".csv")), 0.5e-3);
  EXPECT_EQ(test::json_value(test::read_text(dir / "perfect" / (std::string("perfect_40mps") + "_run.json")), "track_irregularities"), "null");
  EXPECT_NE(test::read_text(dir / "irregular" / (std::string("irregular_40mps") + "_run.json"))
                .find("\"track_irregularities\": \"erri_b176_low, seed 5, wavelengths 3-150 m, 600 m from s = 0 m, amplitude scale 0.5"),
            std::string::npos);
  std::vector<std::string> assess = args("assess", "irregular.toml", "assess");
  assess[4 + 3] = "4";  // --t-end 4: 160 m, room for the 100 m windows
  run = test::run_railstab(assess, dir);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(test::read_text(dir / "assess" / (std::string("irregular_40mps") + "_assessment.md")).find("irregular track (erri_b176_low"),
            std::string::npos);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace railstab
