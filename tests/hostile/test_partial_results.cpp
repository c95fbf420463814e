// Issue 10: a run that cannot finish (no steady state at some speed in the
// middle of a sweep) still writes what it found, marked partial: JSON
// "partial": true with the reason, the Markdown report says so, the terminal
// too; a complete run says "partial": false.
#include <gtest/gtest.h>

#include "cli/run_cli.hpp"
#include "io/format_checks.hpp"

#include <filesystem>
#include <fstream>
#include <unistd.h>
#include "support/test_files.hpp"

namespace fs = std::filesystem;
using railstab::test::run_railstab;

namespace {

using railstab::test::read_text;

fs::path fresh_dir(const std::string& name) { return railstab::test::fresh_dir("partial", name); }

}  // namespace

// The thesis bogie in the R = 1000 m arc has no steady state from 100 m/s on
// (cant deficiency beyond what the flangeless contact carries: the wheelsets
// drift off; the one at 90 m/s is already past the flange clearance, which
// the run warns about): a grid to 150 m/s stops at 100 m/s; the speeds below
// are analysed and written.
TEST(PartialResults, SweepThatLosesItsSteadyStateWritesWhatItFoundMarkedPartial) {
  const fs::path dir = fresh_dir("sweep");
  const std::string scene = std::string(RAILSTAB_CASES_DIR) + "/thesis_bogie_curve.toml";
  const auto run = run_railstab({"critical-speed", scene, "--arc-length", "2000", "--from", "10",
                                 "--to", "150", "--step", "10", "--no-plots", "--out", "out"},
                                dir);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("partial result: the speed grid stopped at 100 m/s"), std::string::npos)
      << run.output;
  EXPECT_NE(run.output.find("warning from 90 m/s: wheelset1 steady lateral shift"), std::string::npos)
      << run.output;
  const std::string json = read_text(dir / "out/thesis_bogie_curve_arc2000m_critical_speed.json");
  EXPECT_TRUE(railstab::test::is_valid_json(json));
  EXPECT_NE(json.find("\"partial\": true"), std::string::npos) << json.substr(0, 600);
  EXPECT_NE(json.find("\"partial_reason\": \"the speed grid stopped at 100 m/s"), std::string::npos);
  // The reason says where: the stage, the speed, the place and a body.
  EXPECT_NE(json.find("steady state of scene 'thesis_bogie_curve' at V = 100 m/s, reference point "
                      "at arc length 2000 m"),
            std::string::npos);
  // What was found is there: the grid below 100 m/s and the critical speed
  // in the arc (39.6 m/s, bracketed by 30 and 40 m/s).
  EXPECT_NE(json.find("\"critical_speed_m_per_s\": 39.6"), std::string::npos) << json.substr(0, 900);
  const std::string md = read_text(dir / "out/thesis_bogie_curve_arc2000m_critical_speed.md");
  EXPECT_NE(md.find("**Partial result**"), std::string::npos) << md.substr(0, 600);
  EXPECT_NE(md.find("| 90 |"), std::string::npos);
  EXPECT_EQ(md.find("| 100 |"), std::string::npos);

  // The same scene over a range it can finish: not partial.
  const auto complete = run_railstab({"critical-speed", scene, "--arc-length", "2000", "--from",
                                      "20", "--to", "45", "--step", "12.5", "--no-plots", "--out",
                                      "out2"},
                                     dir);
  ASSERT_EQ(complete.exit_code, 0) << complete.output;
  const std::string json2 = read_text(dir / "out2/thesis_bogie_curve_arc2000m_critical_speed.json");
  EXPECT_NE(json2.find("\"partial\": false"), std::string::npos) << json2.substr(0, 600);
  EXPECT_NE(json2.find("\"partial_reason\": null"), std::string::npos);
  fs::remove_all(dir);
}
