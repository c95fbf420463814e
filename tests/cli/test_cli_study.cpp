// `railstab study` and `railstab merge` from the command line: the files do
// not depend on --jobs, shards merge into the bytes of the unsharded run
// (also when spread by GNU parallel, scripts/study_parallel_example.sh, the
// README example), and bad input is refused naming the flag, with no output.
#include <gtest/gtest.h>

#include "cli/run_cli.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

std::string file_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  EXPECT_TRUE(in.good()) << p;
  return std::string(std::istreambuf_iterator<char>(in), {});
}

const std::string kScene = std::string(RAILSTAB_CASES_DIR) + "/textbook_wheelset.toml";
const std::string kStem = "textbook_wheelset_study";

std::vector<std::string> study(std::vector<std::string> extra) {
  std::vector<std::string> a = {"study", kScene,
                                "--vary", "contacts.textbook_linear.conicity=0.1:0.3:0.1",
                                "--vary", "bodies.wheelset1.mass_kg=1000:2000:500",
                                "--from", "5", "--to", "120", "--step", "5"};
  a.insert(a.end(), extra.begin(), extra.end());
  return a;
}

struct TempDir {
  fs::path path;
  explicit TempDir(const std::string& name)
      : path(fs::temp_directory_path() / (name + "_" + std::to_string(::getpid()))) {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
};

}  // namespace

TEST(CliStudy, FilesDoNotDependOnJobsAndShardsMergeIntoTheSameBytes) {
  const TempDir dir("railstab_cli_study");
  const auto one = railstab::test::run_railstab(study({"--jobs", "1", "--out", "j1"}), dir.path);
  ASSERT_EQ(one.exit_code, 0) << one.output;
  const auto two = railstab::test::run_railstab(study({"--jobs", "2", "--no-plots", "--out", "j2"}), dir.path);
  ASSERT_EQ(two.exit_code, 0) << two.output;
  EXPECT_NE(two.output.find("[9/9"), std::string::npos) << two.output;  // progress
  for (const std::string f : {".csv", ".json", "_record.toml"})
    EXPECT_EQ(file_text(dir.path / "j1" / (kStem + f)), file_text(dir.path / "j2" / (kStem + f))) << f;
  const std::string csv = file_text(dir.path / "j1" / (kStem + ".csv"));
  EXPECT_EQ(csv.rfind("index,contacts.textbook_linear.conicity,bodies.wheelset1.mass_kg,status,"
                      "critical_speed_m_per_s,hunting_frequency_Hz,hunting_mode,message\n0,0.1,1000,"
                      "critical_speed_found,", 0),
            0u)
      << csv;
  for (const std::string f : {"_map.png", "_map.svg", "_vs_key1.png", "_vs_key2.svg"})
    EXPECT_GT(fs::file_size(dir.path / "j1" / (kStem + f)), 0u) << f;
  EXPECT_FALSE(fs::exists(dir.path / "j2" / (kStem + "_map.png")));

  std::vector<std::string> shards;
  for (const std::string i : {"1", "2", "3"}) {
    const auto run = railstab::test::run_railstab(study({"--shard", i + "/3", "--out", "s" + i}), dir.path);
    ASSERT_EQ(run.exit_code, 0) << run.output;
    shards.push_back("s" + i);
  }
  const auto merged = railstab::test::run_railstab({"merge", "m", "s3", "s1", "s2"}, dir.path);
  ASSERT_EQ(merged.exit_code, 0) << merged.output;
  for (const std::string f : {".csv", ".json", "_record.toml", ".dat", "_plots.gp"})
    EXPECT_EQ(file_text(dir.path / "j1" / (kStem + f)), file_text(dir.path / "m" / (kStem + f))) << f;

  // Merge errors: a shard missing, one given twice, shards of another study.
  auto refused = [&](const std::vector<std::string>& args, const std::string& said) {
    const auto run = railstab::test::run_railstab(args, dir.path);
    EXPECT_NE(run.exit_code, 0);
    EXPECT_NE(run.output.find(said), std::string::npos) << run.output;
    EXPECT_FALSE(fs::exists(dir.path / "bad"));
  };
  refused({"merge", "bad", "s1", "s2", "--no-plots"}, "shard(s) 3/3 missing");
  refused({"merge", "bad", "s1", "s2", "s2", "--no-plots"}, "given twice");
  const auto other = railstab::test::run_railstab(
      study({"--shard", "3/3", "--hunting-band", "15", "--out", "other"}), dir.path);
  ASSERT_EQ(other.exit_code, 0) << other.output;
  refused({"merge", "bad", "s1", "s2", "other", "--no-plots"}, "different study");
  refused({"merge", "bad", "s1", "j1", "--no-plots"}, "shard 1/1 but");
  refused({"merge", "bad", "s1", ".", "--no-plots"}, "expected one *_study_record.toml");
}

TEST(CliStudy, BadFlagsAreRefusedNamingTheFlagWithNoOutput) {
  const TempDir dir("railstab_cli_study_bad");
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"study", kScene, "--vary", "bodies.carbody.mass_kg=1:2:1", "--out", "bad"},
       "--vary bodies.carbody.mass_kg=1:2:1"},
      {{"study", kScene, "--vary", "bodies.wheelset1.mass_kg=1:2", "--out", "bad"}, "--vary"},
      {{"study", kScene, "--vary", "bodies.wheelset1.mass_kg=2:1:1", "--out", "bad"}, "FROM <= TO"},
      {{"study", kScene, "--vary", "bodies.wheelset1.mass_kg=1:2:1", "--shard", "4/3", "--out", "bad"},
       "--shard"},
      {{"study", kScene, "--vary", "bodies.wheelset1.mass_kg=1:2:1", "--jobs", "0", "--out", "bad"},
       "--jobs"},
      {{"study", kScene, "--out", "bad"}, "--vary"},
      {{"study", kScene, "--vary", "bodies.wheelset1.mass_kg=1:2:1", "--set",
        "bodies.wheelset1.mass_kg=3", "--out", "bad"},
       "also varied"},
  };
  for (const auto& [args, said] : cases) {
    const auto run = railstab::test::run_railstab(args, dir.path);
    EXPECT_NE(run.exit_code, 0) << said;
    EXPECT_NE(run.output.find(said), std::string::npos) << run.output;
    EXPECT_FALSE(fs::exists(dir.path / "bad")) << said;
  }
}

TEST(CliStudy, GnuParallelExampleOfTheReadmeEqualsTheUnshardedRun) {
  ASSERT_EQ(std::system("command -v parallel >/dev/null 2>&1"), 0)
      << "GNU parallel is not installed (scripts/install_deps.sh installs it)";
  const TempDir dir("railstab_cli_study_parallel");
  const std::string script = std::string(RAILSTAB_CASES_DIR) + "/../scripts/study_parallel_example.sh";
  const std::string command = "bash '" + script + "' '" + RAILSTAB_EXE + "' '" + kScene + "' '" +
                              dir.path.string() + "' > '" + (dir.path / "log.txt").string() + "' 2>&1";
  const int status = std::system(command.c_str());
  EXPECT_EQ(status, 0) << file_text(dir.path / "log.txt");
  EXPECT_NE(file_text(dir.path / "log.txt").find("merged == unsharded"), std::string::npos);
}
