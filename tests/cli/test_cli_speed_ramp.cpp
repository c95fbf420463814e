// simulate --ramp-rate (two rates) on the thesis bogie with knife-edge
// cones, from its hunting cycle above the Hopf point (36.90 m/s): one output
// set with both rates, their hunting end speeds below the Hopf point, the
// slower rate's nearer to it, and the note that the answer depends on the rate.
#include <gtest/gtest.h>

#include "cli/run_cli.hpp"
#include "support/test_files.hpp"

#include <regex>

namespace fs = std::filesystem;
using namespace railstab;

namespace {

// The ramps' hunting end speeds in a ramp JSON, in the order of the rates.
std::vector<double> hunting_end_speeds(const std::string& json) {
  const std::regex end_speed("\"hunting_end_speed_m_per_s\": ([0-9.]+)");
  std::vector<double> ends;
  for (auto it = std::sregex_iterator(json.begin(), json.end(), end_speed); it != std::sregex_iterator(); ++it)
    ends.push_back(std::stod((*it)[1].str()));
  return ends;
}

}  // namespace

TEST(CliSpeedRamp, TwoRatesInOneReport) {
  const fs::path dir = test::fresh_dir("cli_ramp", "two_rates");
  const test::CliRun run = test::run_railstab(
      {"simulate", test::case_path("thesis_bogie_tangent"), "--speed", "36.95", "--mode", "hunting",
       "--mode-amplitude", "0.0045", "--ramp-rate", "0.1", "--ramp-rate", "0.2", "--ramp-to", "25",
       "--set", "track.segments[0].length_m=8000", "--out", "out"},
      dir);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const std::string json = test::read_text(dir / "out" / "thesis_bogie_tangent_36.95mps_ramp.json");
  const std::vector<double> ends = hunting_end_speeds(json);
  ASSERT_EQ(ends.size(), 2u) << json;
  // Below the Hopf point (36.90 m/s) and the slower ramp (0.1) nearer to it.
  EXPECT_LT(ends[0], 36.90);
  EXPECT_LT(ends[1], ends[0]);
  EXPECT_NE(json.find("depends on the ramp rate"), std::string::npos);
  EXPECT_NE(json.find("\"hunting_end_speed_spread_m_per_s\": "), std::string::npos);
  const std::string md = test::read_text(dir / "out" / "thesis_bogie_tangent_36.95mps_ramp.md");
  EXPECT_NE(md.find("| 0.1 | "), std::string::npos) << md;
  EXPECT_NE(md.find("| 0.2 | "), std::string::npos) << md;
  const std::string csv = test::read_text(dir / "out" / "thesis_bogie_tangent_36.95mps_ramp_envelope.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "ramp_rate_m_per_s2,time_s,speed_m_per_s,peak_to_peak_m");
  EXPECT_NE(run.output.find("note: The hunting end speed of a ramp depends on the ramp rate"),
            std::string::npos);
}

// Issue 22: the ramp method against the continuation on S1002/UIC60. The
// thesis bogie's flange-hunting cycle (5.2 mm at 41 m/s, the run from 5 mm)
// is stable down to the fold of its branch at 34.99 m/s (`bifurcation
// --cycle-speed 41 --no-hopf-branch`, docs/nonlinear.md); a ramp follows the
// stable cycle, so it cannot lose its hunting above the fold, and it loses it
// below by a delay that shrinks with the rate. Measured: 30.36 m/s at
// 0.5 m/s^2, 32.33 m/s at 0.2 m/s^2 (11 s CPU for both).
TEST(CliSpeedRamp, S1002BogieEndsHuntingBelowTheFoldOfItsCycleBranch) {
  const fs::path dir = test::fresh_dir("cli_ramp", "s1002");
  const test::CliRun run = test::run_railstab(
      {"simulate", test::case_path("thesis_bogie_s1002_tangent"), "--speed", "41", "--offset",
       "wheelset1.y_m=0.005", "--ramp-rate", "0.5", "--ramp-rate", "0.2", "--ramp-to", "30", "--set",
       "track.segments[0].length_m=5000", "--no-plots", "--out", "out"},
      dir);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const std::string json = test::read_text(dir / "out" / "thesis_bogie_s1002_tangent_41mps_ramp.json");
  const std::vector<double> ends = hunting_end_speeds(json);
  ASSERT_EQ(ends.size(), 2u) << json;
  const double fold_m_per_s = 34.99;
  EXPECT_LT(ends[0], fold_m_per_s);
  EXPECT_LT(ends[1], fold_m_per_s);
  EXPECT_GT(ends[1], ends[0]);  // the slower ramp (0.2) nearer the fold
  fs::remove_all(dir);
}
