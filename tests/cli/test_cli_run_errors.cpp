// A time-domain run that fails says why in the model's words and the
// integrator's, and no message of a SUNDIALS call that does not apply (the
// root-function count of a run without root functions was reported as
// "arkGetNumGEvals: arkode_mem = NULL illegal" after the real cause).
#include <gtest/gtest.h>

#include "cli/run_cli.hpp"
#include "support/test_files.hpp"

namespace fs = std::filesystem;
using namespace railstab;

// The S1002 vehicle at 100 m/s hunts in flange contact and reaches the edge
// of the contact table's roll range before 10 s (issue 23's reproduction):
// the run stops there with a physical statement (the wheel, where it sits in
// its table, its lift, and Y, Q and Y/Q or that it is in the air) and keeps
// what it computed, never with
// the table's or a library's internal message.
TEST(CliRunErrors, ReachingTheTableEdgeStopsWithThePhysicalStateAndNoLibraryNoise) {
  const fs::path dir = test::fresh_dir("cli_run_errors", "table");
  const test::CliRun run = test::run_railstab(
      {"simulate", test::case_path("thesis_vehicle_s1002_tangent"), "--speed", "100", "--t-end", "10",
       "--no-error-estimate", "--no-plots", "--out", "out"},
      dir, "", 300);
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("stopped early: wheelset"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("reached the edge of its contact table"), std::string::npos) << run.output;
  // Measured: wheelset1's left wheel at 9.97 s, roll 19 mrad, 28.6 mm
  // above a centred wheel (on top of its rail) and unloaded.
  EXPECT_NE(run.output.find("mm above a centred wheel"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("flange climbing"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("outside the table"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("illegal"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("GetNumGEvals"), std::string::npos) << run.output;
  EXPECT_TRUE(fs::exists(dir / "out" / "thesis_vehicle_s1002_tangent_100mps.csv"));
}
