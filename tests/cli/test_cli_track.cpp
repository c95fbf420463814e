// `railstab track SCENE` (synthesised and measured irregularities) and the
// refusal of irregular track by the analyses of the design track
// (docs/irregular_track.md).
#include <gtest/gtest.h>

#include "cli/run_cli.hpp"
#include "support/json_text.hpp"
#include "support/test_files.hpp"

#include <filesystem>
#include <cmath>
#include <fstream>
#include <numbers>

namespace fs = std::filesystem;

namespace railstab {
namespace {

fs::path irregular_scene(const fs::path& dir, const std::string& table) {
  const fs::path scene = dir / "irregular.toml";
  std::ofstream(scene) << test::read_text(test::case_path("thesis_vehicle_tangent")) << "\n[track.irregularities]\n"
                       << table;
  return scene;
}

TEST(CliTrack, WritesChannelsPsdsAndPlotsWithTheRmsOfTheTarget) {
  const fs::path dir = test::fresh_dir("cli", "track");
  const fs::path scene = irregular_scene(dir, "psd = \"erri_b176_high\"\nseed = 11\nlength_m = 2000.0\n");
  const auto run = test::run_railstab({"track", scene.string(), "--out", "out"}, dir);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const fs::path out = dir / "out";
  for (const std::string f : {"irregular_irregularities.csv", "irregular_irregularity_psd.csv",
                              "irregular_irregularities.json", "irregular_irregularities.png",
                              "irregular_irregularity_psd.png"})
    EXPECT_TRUE(fs::is_regular_file(out / f)) << f;
  const std::string json = test::read_text(out / "irregular_irregularities.json");
  // The first channel (alignment): one 2 km realisation within 30 % of the
  // target rms (the estimate's scatter: IrregularitySynthesis.*).
  const double rms = std::stod(test::json_value(json, "sample_rms_m"));
  const double target = std::stod(test::json_value(json, "target_rms_m"));
  EXPECT_NEAR(rms, target, 0.3 * target);
  EXPECT_NEAR(target, 3.53e-3, 0.02e-3);  // ERRI B176 high alignment, 3-150 m
  fs::remove_all(dir);
}

TEST(CliTrack, RefusesBadKeysAndAnalysesOfIrregularTrack) {
  const fs::path dir = test::fresh_dir("cli", "track_refusals");
  auto run = test::run_railstab({"track", irregular_scene(dir, "psd = \"erri_b177\"\n").string()}, dir);
  EXPECT_NE(run.exit_code, 0);
  EXPECT_NE(run.output.find("track.irregularities.psd"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("erri_b176_low"), std::string::npos) << run.output;  // the choices
  run = test::run_railstab(
      {"track", irregular_scene(dir, "psd = \"fra_class_5\"\nsample_interval_m = 2.0\n").string()}, dir);
  EXPECT_NE(run.exit_code, 0);
  EXPECT_NE(run.output.find("track.irregularities.sample_interval_m"), std::string::npos) << run.output;
  run = test::run_railstab({"track", test::case_path("thesis_vehicle_tangent")}, dir);
  EXPECT_NE(run.exit_code, 0);
  EXPECT_NE(run.output.find("track.irregularities"), std::string::npos) << run.output;
  // A linearisation is of the design track: refused, nothing written.
  run = test::run_railstab(
      {"critical-speed", irregular_scene(dir, "psd = \"fra_class_6\"\n").string(), "--out", "out"}, dir);
  EXPECT_NE(run.exit_code, 0);
  EXPECT_NE(run.output.find("applied by the time-domain commands"), std::string::npos) << run.output;
  EXPECT_FALSE(fs::exists(dir / "out"));
  // A measured file that is not there, and one beside psd.
  run = test::run_railstab({"track", irregular_scene(dir, "file = \"absent.csv\"\n").string()}, dir);
  EXPECT_NE(run.exit_code, 0);
  EXPECT_NE(run.output.find("irregular.toml: track.irregularities.file: "), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("absent.csv: track irregularity file not found"), std::string::npos) << run.output;
  run = test::run_railstab({"track", irregular_scene(dir, "file = \"a.csv\"\npsd = \"fra_class_6\"\n").string()}, dir);
  EXPECT_NE(run.exit_code, 0);
  EXPECT_NE(run.output.find("either psd (synthesised) or file (measured)"), std::string::npos) << run.output;
  std::ofstream(dir / "a.csv") << "s_m,level_mm\n0,0\n1,0\n2,0\n3,0\n";
  run = test::run_railstab({"track", irregular_scene(dir, "file = \"a.csv\"\nseed = 3\n").string()}, dir);
  EXPECT_NE(run.exit_code, 0);
  EXPECT_NE(run.output.find("track.irregularities.seed: expected no synthesis key beside `file`"), std::string::npos)
      << run.output;
  fs::remove_all(dir);
}

// A measured record (a 40 m wave of 1 mm in level, 2 km at 0.5 m): the
// channels and their PSD, with no target; the level's rms is the wave's,
// a0 / sqrt(2), over the stretch between the fades.
TEST(CliTrack, MeasuredFileWritesItsChannelsAndPsdWithoutATarget) {
  const fs::path dir = test::fresh_dir("cli", "track_measured");
  {
    std::ofstream csv(dir / "recorded.csv");
    csv << "# a test record\narc_length_m,level_mm,gauge_mm\n";
    for (int i = 0; i <= 4000; ++i) csv << 0.5 * i << "," << std::sin(2 * std::numbers::pi * 0.5 * i / 40.0) << ",0\n";
  }
  const fs::path scene = irregular_scene(dir, "file = \"recorded.csv\"\nsample_interval_m = 0.5\n");
  const auto run = test::run_railstab({"track", scene.string(), "--out", "out", "--no-plots"}, dir);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const std::string json = test::read_text(dir / "out" / "irregular_irregularities.json");
  EXPECT_EQ(test::json_value(json, "psd"), "null") << json;
  EXPECT_NE(json.find("recorded.csv"), std::string::npos);
  EXPECT_EQ(json.find("target_rms_m"), std::string::npos);
  EXPECT_NEAR(std::stod(test::json_value(json, "length_m")), 2000.0, 1e-9);
  // Channels in the order alignment, level, ...: the second sample_rms_m.
  const size_t level = json.find("\"name\": \"level\"");
  ASSERT_NE(level, std::string::npos);
  EXPECT_NEAR(std::stod(test::json_value(json.substr(level), "sample_rms_m")), 1e-3 / std::sqrt(2.0), 0.01e-3);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace railstab
