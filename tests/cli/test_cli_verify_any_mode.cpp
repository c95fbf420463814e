// verify --any-mode: the least stable mode of any kind is fitted on the
// coordinate with the largest kinetic-energy share (the thesis bogie in the
// R = 1000 m arc on S1002/UIC60 at 48.5 m/s: the wheelset spin mode, on
// wheelset2's spin rate), and the critical-speed report names how the
// stability is lost (tests/stability/test_curve_stability_profiles.cpp has
// the numbers).
#include <gtest/gtest.h>

#include "cli/run_cli.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {
std::string read_all(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
}  // namespace

TEST(CliVerifyAnyMode, FitsTheSpinModeAndTheReportNamesTheCrossing) {
  const fs::path dir = fs::temp_directory_path() / ("railstab_any_mode_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string scene = std::string(RAILSTAB_CASES_DIR) + "/thesis_bogie_s1002_curve.toml";
  const railstab::test::CliRun run = railstab::test::run_railstab(
      {"verify", scene, "--arc-length", "2000", "--speed", "48.5", "--any-mode", "--amplitude",
       "1e-5", "--no-plots", "--out", "o"},
      dir);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("signal wheelset2.pitch_rad/s"), std::string::npos) << run.output;
  const std::string json = read_all(dir / "o" / "thesis_bogie_s1002_curve_arc2000m_verify_48.5mps.json");
  EXPECT_NE(json.find("\"signal\": \"wheelset2.pitch_rad/s\""), std::string::npos) << json;

  const railstab::test::CliRun cs = railstab::test::run_railstab(
      {"critical-speed", scene, "--arc-length", "2000", "--from", "45", "--to", "50", "--step",
       "2.5", "--no-plots", "--out", "o"},
      dir);
  ASSERT_EQ(cs.exit_code, 0) << cs.output;
  const std::string report =
      read_all(dir / "o" / "thesis_bogie_s1002_curve_arc2000m_critical_speed.json");
  EXPECT_NE(report.find("\"kind\": \"oscillatory_crossing\""), std::string::npos) << report;
  const std::string md = read_all(dir / "o" / "thesis_bogie_s1002_curve_arc2000m_critical_speed.md");
  EXPECT_NE(md.find("| loss of stability | an oscillatory mode crosses"), std::string::npos) << md;
  fs::remove_all(dir);
}

// dVc/dp needs a stability boundary: where the sweep finds none (the S1002
// thesis vehicle in the arc is stable through 45..50 m/s) the sensitivity
// command says so and writes nothing. (Its refusal of a loss by a jump lost
// its scenario: the jump at 47.5 m/s was an artefact of the tread slots
// counting their shared overlap twice, docs/model.md 6.1.)
TEST(CliVerifyAnyMode, SensitivityRefusesWhereThereIsNoBoundary) {
  const fs::path dir = fs::temp_directory_path() / ("railstab_jump_sens_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string scene = std::string(RAILSTAB_CASES_DIR) + "/thesis_vehicle_s1002_curve.toml";
  const railstab::test::CliRun run = railstab::test::run_railstab(
      {"sensitivity", scene, "--set", "scene.reference_arc_length_m=2000", "--from", "45", "--to",
       "50", "--no-plots", "--out", "o"},
      dir);
  EXPECT_NE(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("no critical speed between 45"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("no stability boundary to differentiate"), std::string::npos)
      << run.output;
  EXPECT_FALSE(fs::exists(dir / "o"));
  fs::remove_all(dir);
}
