// `--set` from the command line: the same files as an edited copy of the
// scene, and bad settings refused with the flag and the key named, exit
// non-zero, no output folder.
#include <gtest/gtest.h>

#include "cli/run_cli.hpp"

#include <filesystem>
#include <fstream>
#include <unistd.h>
#include "support/test_files.hpp"

namespace fs = std::filesystem;

namespace {
using railstab::test::read_text;
}  // namespace

TEST(CliSet, SameFilesAsAnEditedSceneAndBadSettingsRefused) {
  const fs::path dir = fs::temp_directory_path() / ("railstab_cli_set_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string scene = std::string(RAILSTAB_CASES_DIR) + "/textbook_wheelset.toml";
  std::string text = read_text(scene);
  const std::string from = "conicity = 0.1 ";
  ASSERT_NE(text.find(from), std::string::npos);
  text.replace(text.find(from), from.size(), "conicity = 0.2 ");
  // The same file name in its own folder: outputs are named after the file.
  fs::create_directories(dir / "edited");
  std::ofstream(dir / "edited" / "textbook_wheelset.toml") << text;

  const std::vector<std::string> flags = {"--from", "5", "--to", "100", "--step", "5", "--no-plots"};
  auto args = [&](std::vector<std::string> a) {
    a.insert(a.end(), flags.begin(), flags.end());
    return a;
  };
  const auto by_set = railstab::test::run_railstab(
      args({"critical-speed", scene, "--set", "contacts.textbook_linear.conicity=0.2", "--out", "a"}), dir);
  ASSERT_EQ(by_set.exit_code, 0) << by_set.output;
  const auto by_file = railstab::test::run_railstab(args({"critical-speed", "edited/textbook_wheelset.toml", "--out", "b"}), dir);
  ASSERT_EQ(by_file.exit_code, 0) << by_file.output;
  int compared = 0;
  for (const fs::directory_entry& f : fs::directory_iterator(dir / "a")) {
    if (f.path().extension() != ".csv") continue;
    EXPECT_EQ(read_text(f.path()), read_text(dir / "b" / f.path().filename())) << f.path();
    ++compared;
  }
  EXPECT_GT(compared, 0);
  const auto unchanged = railstab::test::run_railstab(args({"critical-speed", scene, "--out", "c"}), dir);
  ASSERT_EQ(unchanged.exit_code, 0);
  EXPECT_NE(unchanged.output, by_set.output);

  const std::vector<std::pair<std::string, std::string>> bad = {
      {"bodies.carbody.mass_kg=1", "no 'carbody'"},
      {"bodies.wheelset1.mass_kg=abc", "expected a finite number"},
      {"bodies.wheelset1.inertia_kg_m2[7]=1", "out of range"},
      {"no_equals_sign", "expected KEY=VALUE"},
      // A TOML value: malformed, or of the wrong kind for its key.
      {"bodies.wheelset1.initial_offset={y_m = }", "expected a number or one TOML value"},
      {"bodies.wheelset1.initial_offset={y_mm = 0.001}", "y_mm"},
      {"bodies.wheelset1.initial_offset=0.001", "not a number"},
  };
  for (const auto& [setting, said] : bad) {
    const auto run = railstab::test::run_railstab(
        {"eigen", scene, "--set", "scene.speed_m_per_s=20", "--set", setting, "--out", "bad"}, dir);
    EXPECT_NE(run.exit_code, 0) << setting;
    EXPECT_NE(run.output.find("--set"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find(setting.substr(0, setting.find('='))), std::string::npos) << run.output;
    EXPECT_NE(run.output.find(said), std::string::npos) << run.output;
    EXPECT_FALSE(fs::exists(dir / "bad")) << setting;
  }
  fs::remove_all(dir);
}

// A table given by --set (issue 24): the run equals the run of the edited
// file, for a table the scene has (replaced) and one it lacks (added).
TEST(CliSet, ATableValueEqualsTheEditedFile) {
  const fs::path dir = fs::temp_directory_path() / ("railstab_cli_set_table_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string scene = std::string(RAILSTAB_CASES_DIR) + "/textbook_wheelset.toml";
  std::string text = read_text(scene);
  const std::string from = "initial_offset = { y_m = 0.001 }";
  ASSERT_NE(text.find(from), std::string::npos);
  text.replace(text.find(from), from.size(),
               "initial_offset = { y_m = 0.002 }\ninitial_rate = { yaw_rad_per_s = 0.01 }");
  // The same file stem, in its own folder: the output names are equal.
  fs::create_directories(dir / "edited");
  std::ofstream(dir / "edited" / "textbook_wheelset.toml") << text;
  const std::vector<std::string> flags = {"--speed", "20", "--t-end", "0.1", "--no-plots"};
  auto args = [&](std::vector<std::string> a) {
    a.insert(a.end(), flags.begin(), flags.end());
    return a;
  };
  const auto by_set = railstab::test::run_railstab(
      args({"simulate", scene, "--set", "bodies.wheelset1.initial_offset={ y_m = 0.002 }", "--set",
            "bodies.wheelset1.initial_rate={yaw_rad_per_s = 0.01}", "--out", "a"}),
      dir);
  ASSERT_EQ(by_set.exit_code, 0) << by_set.output;
  const auto by_file = railstab::test::run_railstab(
      args({"simulate", "edited/textbook_wheelset.toml", "--out", "b"}), dir);
  ASSERT_EQ(by_file.exit_code, 0) << by_file.output;
  int compared = 0;
  for (const fs::directory_entry& f : fs::directory_iterator(dir / "a")) {
    if (f.path().extension() != ".csv") continue;
    EXPECT_EQ(read_text(f.path()), read_text(dir / "b" / f.path().filename())) << f.path();
    ++compared;
  }
  EXPECT_GT(compared, 0);
  // ... and differs from the scene as shipped (the trajectories start elsewhere).
  const auto shipped = railstab::test::run_railstab(args({"simulate", scene, "--out", "c"}), dir);
  ASSERT_EQ(shipped.exit_code, 0) << shipped.output;
  const std::string name = "textbook_wheelset_20mps.csv";
  ASSERT_TRUE(fs::exists(dir / "a" / name));
  EXPECT_NE(read_text(dir / "a" / name), read_text(dir / "c" / name));
  fs::remove_all(dir);
}
