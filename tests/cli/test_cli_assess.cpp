// `railstab assess` on the thesis vehicle (knife-edge contact): passes well
// below its critical speed (linear 111 m/s), fails in hunting above it (at
// 140 m/s the hunting reaches the flange clearance within 0.75 s: the run
// stops there, outside the model's validity, and that is a fail).
#include <gtest/gtest.h>

#include "cli/run_cli.hpp"
#include "support/json_text.hpp"
#include "support/test_files.hpp"

#include <filesystem>

namespace fs = std::filesystem;

namespace railstab {
namespace {

TEST(CliAssess, PassesWellBelowTheCriticalSpeedAndFailsInHunting) {
  const fs::path dir = test::fresh_dir("cli", "assess");
  auto run = test::run_railstab({"assess", test::case_path("thesis_vehicle_tangent"), "--speed", "60", "--t-end",
                                 "4", "--out", "below"},
                                dir);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  std::string json = test::read_text(dir / "below" / "thesis_vehicle_tangent_60mps_assessment.json");
  EXPECT_EQ(test::json_value(json, "passed"), "true") << json;
  for (const std::string f : {"_assessment.md", "_assessment_windows.csv", "_assessment_rms.png"})
    EXPECT_TRUE(fs::is_regular_file(dir / "below" / ("thesis_vehicle_tangent_60mps" + f))) << f;
  run = test::run_railstab({"assess", test::case_path("thesis_vehicle_tangent"), "--speed", "140", "--t-end", "6",
                            "--out", "above", "--no-plots"},
                           dir);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  json = test::read_text(dir / "above" / "thesis_vehicle_tangent_140mps_assessment.json");
  EXPECT_EQ(test::json_value(json, "passed"), "false") << json;
  EXPECT_NE(run.output.find("FAIL"), std::string::npos) << run.output;
  EXPECT_NE(test::json_value(json, "stopped_early").find("flange clearance"), std::string::npos) << json;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace railstab
