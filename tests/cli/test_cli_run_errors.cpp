// A time-domain run that fails says why in the model's words and the
// integrator's, and no message of a SUNDIALS call that does not apply (the
// root-function count of a run without root functions was reported as
// "arkGetNumGEvals: arkode_mem = NULL illegal" after the real cause).
#include <gtest/gtest.h>

#include "cli/run_cli.hpp"
#include "support/test_files.hpp"

namespace fs = std::filesystem;
using namespace railstab;

// The S1002 vehicle at 100 m/s hunts in flange contact and leaves the
// contact table's roll range just before 10 s (issue 23's reproduction).
TEST(CliRunErrors, LeavingTheContactTableNamesTheCauseAndNoLibraryNoise) {
  const fs::path dir = test::fresh_dir("cli_run_errors", "table");
  const test::CliRun run = test::run_railstab(
      {"simulate", test::case_path("thesis_vehicle_s1002_tangent"), "--speed", "100", "--t-end", "10",
       "--no-error-estimate", "--no-plots", "--out", "out"},
      dir, "", 300);
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_NE(run.output.find("outside the table"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("illegal"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("GetNumGEvals"), std::string::npos) << run.output;
  EXPECT_FALSE(fs::exists(dir / "out" / "thesis_vehicle_s1002_tangent_100mps.csv"));
}
