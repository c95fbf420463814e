// --min-damping-ratio: a value outside (0, 1) is refused while parsing, with
// the flag and the range named; a valid one reaches the terminal summary.
#include <gtest/gtest.h>

#include "cli/run_cli.hpp"

#include <filesystem>
#include <unistd.h>

namespace fs = std::filesystem;

TEST(CliDampingFlag, OutOfRangeIsRefusedAndValidOneIsReported) {
  const fs::path dir = fs::temp_directory_path() / ("railstab_damping_flag_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string scene = std::string(RAILSTAB_CASES_DIR) + "/textbook_wheelset.toml";
  for (const char* bad : {"1.5", "0", "-0.1", "nan"}) {
    const railstab::test::CliRun run = railstab::test::run_railstab(
        {"critical-speed", scene, "--min-damping-ratio", bad, "--no-plots", "--out", "o"}, dir);
    EXPECT_NE(run.exit_code, 0) << bad;
    EXPECT_NE(run.output.find("--min-damping-ratio"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("(0, 1)"), std::string::npos) << run.output;
    EXPECT_FALSE(fs::exists(dir / "o")) << bad;
  }
  const railstab::test::CliRun ok = railstab::test::run_railstab(
      {"critical-speed", scene, "--from", "5", "--to", "80", "--step", "5", "--min-damping-ratio",
       "0.05", "--no-plots", "--out", "o"},
      dir);
  ASSERT_EQ(ok.exit_code, 0) << ok.output;
  EXPECT_NE(ok.output.find("damping ratio below 0.05 from "), std::string::npos) << ok.output;
  fs::remove_all(dir);
}
