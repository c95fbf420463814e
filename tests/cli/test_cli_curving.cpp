// `railstab curving` and `railstab equilibrium` in a curve on real profiles
// (docs/steady_curving.md): the issue's point found, the sweep's table with
// its columns and one row per condition, the flange-climbing limit stated
// with the forces (exit 0: it is a result), and bad flag values refused
// with the flag and what was expected, writing nothing. Each run below
// takes under 2 s (Release).
#include <gtest/gtest.h>

#include "cli/run_cli.hpp"
#include "io/format_checks.hpp"
#include "support/test_files.hpp"

#include <algorithm>
#include <sstream>

namespace fs = std::filesystem;
using namespace railstab;

namespace {

size_t lines_of(const std::string& text) { return size_t(std::count(text.begin(), text.end(), '\n')); }

}  // namespace

// Issue 23: "equilibrium finds the steady state at 55 m/s but none from
// 57.5 m/s (187 mm cant deficiency)".
TEST(CliCurving, EquilibriumFindsTheIssuePoint) {
  const fs::path dir = test::fresh_dir("cli_curving", "issue");
  const test::CliRun run = test::run_railstab(
      {"equilibrium", test::case_path("coach_s1002_curve"), "--speed", "57.5", "--out", "out"}, dir);
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_TRUE(fs::exists(dir / "out" / "coach_s1002_curve_arc2000m_equilibrium_57.5mps.json"))
      << run.output;
}

// From cant excess to 300 mm at R 1500 m: a header and one row per value
// (-100, -50, ..., 300 mm: 9 rows), every wheel's Y, Q, Y/Q, Nadal's limit
// and flange flag.
TEST(CliCurving, CantDeficiencySweepWritesOneRowPerCondition) {
  const fs::path dir = test::fresh_dir("cli_curving", "sweep");
  const test::CliRun run = test::run_railstab({"curving", test::case_path("coach_s1002_curve"),
                                               "--cant-deficiency", "-0.1:0.3:0.05", "--out", "out"},
                                              dir);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const std::string csv = test::read_text(dir / "out" / "coach_s1002_curve_curving.csv");
  EXPECT_EQ(lines_of(csv), 10u) << csv;
  for (const char* column : {"cant_deficiency_m", "speed_m_per_s", "radius_m",
                             "wheelset1_lateral_shift_m", "wheelset1_angle_of_attack_rad",
                             "wheelset1_sum_y_N", "wheelset1_right_Y_N", "wheelset1_right_Q_N",
                             "wheelset1_right_y_over_q", "wheelset1_right_nadal_limit",
                             "wheelset4_left_flange_contact"})
    EXPECT_NE(csv.find(column), std::string::npos) << column;
  const std::string json = test::read_text(dir / "out" / "coach_s1002_curve_curving.json");
  EXPECT_NE(json.find("\"no_steady_state\": null"), std::string::npos) << json.substr(0, 400);
}

// A radius sweep from 1500 m down to 250 m at 150 mm cant deficiency: the
// leading wheelset is on its outer flange at 250 m.
TEST(CliCurving, RadiusSweepDownToTwoHundredFiftyMetres) {
  const fs::path dir = test::fresh_dir("cli_curving", "radius");
  const test::CliRun run = test::run_railstab(
      {"curving", test::case_path("coach_s1002_curve"), "--radius", "1500:250:250",
       "--cant-deficiency", "0.15", "--out", "out"},
      dir);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const std::string csv = test::read_text(dir / "out" / "coach_s1002_curve_curving.csv");
  EXPECT_EQ(lines_of(csv), 7u) << csv;  // 1500, 1250, ..., 250
  EXPECT_NE(run.output.find("wheelset1 right wheel"), std::string::npos) << run.output;
}

// Beyond flange climbing (friction 1.0: Nadal's limit 0.467 in R 250 m) the
// command says so with the wheel's forces and writes the table up to there.
TEST(CliCurving, FlangeClimbingIsStatedWithTheForces) {
  const fs::path dir = test::fresh_dir("cli_curving", "limit");
  const test::CliRun run = test::run_railstab(
      {"curving", test::case_path("coach_s1002_curve"), "--radius", "250", "--cant-deficiency",
       "0:0.3:0.1", "--set", "contacts.s1002_uic60.friction_coefficient=1.0", "--out", "out"},
      dir);
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("no steady state physically"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("reaches Nadal's limit"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("kN"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("flange climbing"), std::string::npos) << run.output;
  const std::string json = test::read_text(dir / "out" / "coach_s1002_curve_curving.json");
  EXPECT_NE(json.find("\"statement\": \"no steady state physically"), std::string::npos) << json;
}

// Bad values name the flag and what was expected; nothing is written.
TEST(CliCurving, BadFlagValuesNameTheFlagAndWriteNothing) {
  const fs::path dir = test::fresh_dir("cli_curving", "bad");
  const std::string scene = test::case_path("coach_s1002_curve");
  struct Case {
    std::vector<std::string> flags;
    std::vector<std::string> said;
  };
  const std::vector<Case> cases = {
      {{"--radius", "-250"}, {"--radius", "in [10, 1e6] m", "'-250'"}},
      {{"--cant-deficiency", "0.1:0.3"}, {"--cant-deficiency", "FROM:TO:STEP", "not one value or three fields"}},
      {{"--cant-deficiency", "0.1:0.3:0"}, {"--cant-deficiency", "STEP is not positive"}},
      {{"--cant-deficiency", "0.1:abc:0.1"}, {"--cant-deficiency", "TO is not a number"}},
      {{"--cant-deficiency", "nan"}, {"--cant-deficiency", "not a finite number"}},
      {{"--cant-deficiency", "0:0.3:0.1", "--radius", "1000:500:100"}, {"two ranges"}},
      // 150 mm cant: a cant excess of 200 mm needs a negative speed.
      {{"--cant-deficiency", "-0.2"}, {"--cant-deficiency", "needs a speed of zero or less"}},
      {{}, {"--cant-deficiency FROM:TO:STEP", "--radius FROM:TO:STEP"}},
  };
  for (const Case& c : cases) {
    std::vector<std::string> args = {"curving", scene, "--out", "out"};
    args.insert(args.end(), c.flags.begin(), c.flags.end());
    const test::CliRun run = test::run_railstab(args, dir);
    std::ostringstream shown;
    for (const std::string& f : c.flags) shown << f << ' ';
    EXPECT_NE(run.exit_code, 0) << shown.str() << run.output;
    for (const std::string& s : c.said)
      EXPECT_NE(run.output.find(s), std::string::npos) << shown.str() << ": " << run.output;
    EXPECT_FALSE(fs::exists(dir / "out")) << shown.str();
  }
}

// Issue 24, item 1: `critical-speed` on the coach in its curve said "no
// steady state from 57.5 m/s". Its outputs now say where the branch folds
// and what loses stability below the fold (the wheelset2 spin mode, named
// by its shape there beside its track's name), the same in the JSON, the
// Markdown and the terminal (library checks: tests/stability/
// test_steady_state_fold.cpp). 1.5 s.
TEST(CliCurving, CriticalSpeedNamesTheFoldAndTheSpinModeShape) {
  const fs::path dir = test::fresh_dir("cli_curving", "fold");
  const test::CliRun run = test::run_railstab({"critical-speed", test::case_path("coach_s1002_curve"),
                                               "--from", "50", "--to", "60", "--no-plots", "--out",
                                               "out"},
                                              dir);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("critical speed 56.72 m/s"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("(its shape here: wheelset2 spin"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("the steady state's branch folds back at 56.7"), std::string::npos)
      << run.output;
  const std::string json = test::read_text(dir / "out/coach_s1002_curve_arc2000m_critical_speed.json");
  EXPECT_TRUE(test::is_valid_json(json));
  EXPECT_NE(json.find("\"steady_state_fold_m_per_s\": 56.7"), std::string::npos);
  EXPECT_NE(json.find("\"hunting_mode_shape_here\": \"wheelset2 spin"), std::string::npos);
  EXPECT_NE(json.find("\"kind\": \"oscillatory_crossing\""), std::string::npos);
  const std::string md = test::read_text(dir / "out/coach_s1002_curve_arc2000m_critical_speed.md");
  EXPECT_NE(md.find("its shape here: wheelset2 spin"), std::string::npos);
  fs::remove_all(dir);
}
