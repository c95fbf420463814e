// The railstab command line under hostile input (issue 10), run as a user
// would run it: numeric flags out of range, scene names that try to leave
// --out or run shell/gnuplot commands, names that break CSV and JSON,
// gnuplot missing or failing, and scene paths that are not regular files.
// Every error exits non-zero with a message naming its cause; every failing
// run leaves --out as it was.
#include <gtest/gtest.h>

#include "cli/run_cli.hpp"
#include "io/format_checks.hpp"

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sys/stat.h>
#include "support/test_files.hpp"

using namespace railstab;
using railstab::test::run_railstab;
namespace fs = std::filesystem;

namespace {

const std::string kScene = std::string(RAILSTAB_CASES_DIR) + "/textbook_wheelset.toml";

fs::path fresh_dir(const std::string& name) { return railstab::test::fresh_dir("cli", name); }

using railstab::test::read_text;

// Every file (relative path -> content) under `dir`, hidden ones included.
std::map<std::string, std::string> contents(const fs::path& dir) {
  std::map<std::string, std::string> all;
  if (!fs::exists(dir)) return all;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    all[fs::relative(e.path(), dir).string()] = e.is_regular_file() ? read_text(e.path()) : "<dir>";
  return all;
}

// A TOML basic string holding `text` exactly (\uXXXX for controls).
std::string toml_string(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    const unsigned char u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') out += std::string("\\") + c;
    else if (u < 0x20 || u == 0x7F) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", u);
      out += buf;
    } else out += c;
  }
  return out + "\"";
}

// The textbook wheelset scene with its scene name and body name replaced.
fs::path hostile_scene(const fs::path& dir, const std::string& scene_name,
                       const std::string& body_name = "wheelset1") {
  std::string text = read_text(kScene);
  text = std::regex_replace(text, std::regex("name = \"textbook_wheelset\""),
                            "name = " + toml_string(scene_name));
  text = std::regex_replace(text, std::regex("\"wheelset1\""), toml_string(body_name));
  const fs::path path = dir / "scene.toml";
  std::ofstream(path) << text;
  return path;
}

// A file called exactly `marker` anywhere under `dir` (what `touch` makes).
bool any_file_named(const fs::path& dir, const std::string& marker) {
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.path().filename().string() == marker) return true;
  return false;
}

// A folder holding a fake `gnuplot` that runs `body` (a /bin/sh script).
std::string fake_gnuplot_path(const fs::path& dir, const std::string& body) {
  const fs::path bin = dir / "fakebin";
  fs::create_directories(bin);
  std::ofstream(bin / "gnuplot") << "#!/bin/sh\n" << body << "\n";
  fs::permissions(bin / "gnuplot", fs::perms::owner_all);
  return bin.string();
}

}  // namespace

// --- numeric flags ----------------------------------------------------------------

TEST(CliHostile, NumericFlagsOutOfRangeNameTheFlagValueAndRange) {
  const fs::path dir = fresh_dir("flags");
  struct Case {
    std::vector<std::string> args;
    std::string must_mention;
    std::string bad_value = "";  // the value the message quotes; default: the last argument
  };
  const std::vector<Case> cases = {
      {{"critical-speed", kScene, "--hunting-band", "-1"}, "--hunting-band"},
      {{"work-precision", kScene, "--budget", "nan"}, "--budget"},
      {{"work-precision", kScene, "--rtols", "1e-3,nan"}, "--rtols", "nan"},
      {{"verify", kScene, "--amplitude", "0"}, "--amplitude"},
      {{"simulate", kScene, "--t-end", "1e20"}, "--t-end"},
      {{"simulate", kScene, "--t-end", "inf"}, "--t-end"},
      {{"simulate", kScene, "--rtol", "nan"}, "--rtol"},
      {{"critical-speed", kScene, "--step", "1e-12"}, "--step"},
      {{"critical-speed", kScene, "--to", "1e12"}, "--to"},
      {{"sweep", kScene, "--from", "-5"}, "--from"},
      {{"eigen", kScene, "--speed", "1e6"}, "--speed"},
      {{"equilibrium", kScene, "--arc-length", "nan"}, "--arc-length"},
      {{"verify", kScene, "--periods", "1e9"}, "--periods"},
      {{"critical-speed", kScene, "--step", "abc"}, "--step"},
  };
  for (const Case& c : cases) {
    std::vector<std::string> args = c.args;
    args.insert(args.end(), {"--out", "out"});
    const auto run = run_railstab(args, dir);
    EXPECT_NE(run.exit_code, 0) << run.output;
    EXPECT_NE(run.output.find(c.must_mention + ": expected a finite number in"), std::string::npos)
        << run.output;
    const std::string bad = c.bad_value.empty() ? c.args.back() : c.bad_value;
    EXPECT_NE(run.output.find("got \"" + bad + "\""), std::string::npos) << run.output;
    EXPECT_EQ(run.output.find("-inf"), std::string::npos) << run.output;
    EXPECT_FALSE(fs::exists(dir / "out")) << c.args[0];
  }
  // Cross-flag limits: an empty range and a grid too large to hold.
  auto run = run_railstab({"critical-speed", kScene, "--from", "50", "--to", "40"}, dir);
  EXPECT_NE(run.exit_code, 0);
  EXPECT_NE(run.output.find("--from 50 m/s must be below --to 40 m/s"), std::string::npos)
      << run.output;
  run = run_railstab({"sweep", kScene, "--from", "1", "--to", "300", "--step", "0.01"}, dir);
  EXPECT_NE(run.exit_code, 0);
  EXPECT_NE(run.output.find("would have 29901 points; at most 10000"), std::string::npos)
      << run.output;
  run = run_railstab({"verify", kScene, "--periods", "3", "--settle-periods", "5"}, dir);
  EXPECT_NE(run.exit_code, 0);
  EXPECT_NE(run.output.find("--settle-periods 5 must be below --periods 3"), std::string::npos)
      << run.output;
  fs::remove_all(dir);
}

// --- output paths ------------------------------------------------------------------

TEST(CliHostile, SceneNamesCannotLeaveTheOutputFolder) {
  for (const std::string& name : {std::string("../evil"), std::string("/tmp/../../evil"),
                                  std::string(100, 'n')}) {
    const fs::path dir = fresh_dir("escape");
    const fs::path scene = hostile_scene(dir, name);
    fs::create_directories(dir / "work");
    const auto run = run_railstab({"eigen", scene.string(), "--out", "out"}, dir / "work");
    ASSERT_EQ(run.exit_code, 0) << run.output;
    // Only the scene and work/out/<one JSON> exist: nothing beside or above out.
    const auto all = contents(dir);
    ASSERT_EQ(all.size(), 4u) << run.output;  // scene.toml, work, work/out, the JSON
    std::string json_name;
    for (const auto& [path, text] : all)
      if (path.rfind("work/out/", 0) == 0) json_name = path.substr(9);
    // Outputs are named after the scene file, never the scene's name.
    EXPECT_EQ(json_name, "scene_eigen_30mps.json");
    EXPECT_TRUE(test::is_valid_json(read_text(dir / "work/out" / json_name)));
    fs::remove_all(dir);
  }
  // A 4,000-character name (it used to fail late with "cannot write") is
  // refused by the scene reader, naming the key, before anything is written.
  const fs::path dir = fresh_dir("escape_long");
  const fs::path scene = hostile_scene(dir, std::string(4000, 'n'));
  const auto run = run_railstab({"eigen", scene.string(), "--out", "out"}, dir);
  EXPECT_NE(run.exit_code, 0);
  EXPECT_NE(run.output.find("scene.name: expected a name of 1 to 100 bytes without control "
                            "characters, got a name of 4000 bytes"),
            std::string::npos)
      << run.output;
  EXPECT_FALSE(fs::exists(dir / "out"));
  fs::remove_all(dir);
}

// --- shell and gnuplot injection ---------------------------------------------------

TEST(CliHostile, NamesAndOutFolderRunNoCommands) {
  const fs::path dir = fresh_dir("inject");
  const fs::path scene =
      hostile_scene(dir, "x'; touch PWNED_SCENE; echo '",
                    "w'; system(\"touch PWNED_BODY\"); print '`touch PWNED_TICK`");
  const std::string out = "o'$(touch PWNED_OUT)'";
  const auto run = run_railstab(
      {"simulate", scene.string(), "--t-end", "0.2", "--no-error-estimate", "--out", out}, dir);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  for (const char* marker : {"PWNED_SCENE", "PWNED_BODY", "PWNED_TICK", "PWNED_OUT"})
    EXPECT_FALSE(any_file_named(dir, marker)) << marker << "\n" << run.output;
  // The promised plots exist and are non-empty.
  int pngs = 0;
  for (const auto& e : fs::directory_iterator(dir / out))
    if (e.path().extension() == ".png") {
      ++pngs;
      EXPECT_GT(fs::file_size(e.path()), 0u) << e.path();
    }
  EXPECT_GE(pngs, 3) << run.output;
  // The same body name in a scene with a plain name and a plain --out: the
  // gnuplot script itself is reached, and its title strings must hold.
  const fs::path plain = hostile_scene(dir, "plain",
                                       "w'; system(\"touch PWNED_GNUPLOT\"); print '");
  const auto run2 = run_railstab(
      {"simulate", plain.string(), "--t-end", "0.2", "--no-error-estimate", "--out", "out2"}, dir);
  EXPECT_EQ(run2.exit_code, 0) << run2.output;
  EXPECT_FALSE(any_file_named(dir, "PWNED_GNUPLOT")) << run2.output;
  EXPECT_TRUE(fs::exists(dir / "out2/scene_30mps_wheelset_lateral.png")) << run2.output;
  fs::remove_all(dir);
}

// --- names in CSV and JSON -----------------------------------------------------------

TEST(CliHostile, HostileBodyNamesGiveValidCsvAndJson) {
  const fs::path dir = fresh_dir("names");
  // Control characters are refused by the scene reader (tests/hostile/
  // test_scene_ranges.cpp); every other character must survive CSV and JSON.
  const std::string body = "w,1\"q\";|x\\";
  const fs::path scene = hostile_scene(dir, "names", body);
  auto run = run_railstab(
      {"simulate", scene.string(), "--t-end", "0.2", "--no-error-estimate", "--out", "out"}, dir);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  for (const char* csv : {"scene_30mps.csv", "scene_30mps_absolute_roll.csv"}) {
    const auto rows = test::parse_csv(read_text(dir / "out" / csv));
    ASSERT_TRUE(rows.has_value()) << csv;
    ASSERT_GT(rows->size(), 2u);
    for (const auto& row : *rows) ASSERT_EQ(row.size(), (*rows)[0].size()) << csv;
    EXPECT_EQ((*rows)[0][1].rfind(body + ".", 0), 0u) << (*rows)[0][1];
  }
  EXPECT_TRUE(test::is_valid_json(read_text(dir / "out/scene_30mps_run.json")));
  run = run_railstab({"eigen", scene.string(), "--out", "out"}, dir);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  std::vector<std::string> strings;
  EXPECT_TRUE(test::is_valid_json(read_text(dir / "out/scene_eigen_30mps.json"), &strings));
  bool named = false;  // mode names carry the body name, decoded intact
  for (const std::string& s : strings) named = named || s.find(body) != std::string::npos;
  EXPECT_TRUE(named);
  run = run_railstab({"equilibrium", scene.string(), "--out", "out"}, dir);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  strings.clear();
  EXPECT_TRUE(test::is_valid_json(read_text(dir / "out/scene_equilibrium_30mps.json"), &strings));
  EXPECT_NE(std::find(strings.begin(), strings.end(), body), strings.end());
  fs::remove_all(dir);
}

// --- all-or-nothing outputs ----------------------------------------------------------

TEST(CliHostile, GnuplotMissingOrFailingLeavesOutAsItWas) {
  const fs::path dir = fresh_dir("gnuplot");
  fs::create_directories(dir / "out");
  std::ofstream(dir / "out/textbook_wheelset_30mps.csv") << "old run";
  std::ofstream(dir / "out/textbook_wheelset_critical_speed.json") << "{\"old\": true}";
  const auto before = contents(dir / "out");
  const fs::path empty_bin = dir / "emptybin";
  fs::create_directories(empty_bin);
  struct Case {
    std::string path_env, expected;
  };
  const std::vector<Case> cases = {
      {empty_bin.string(), "gnuplot is not on PATH"},
      {fake_gnuplot_path(dir / "fails", "exit 3"), "gnuplot failed (exit status 3)"},
      {fake_gnuplot_path(dir / "silent", "exit 0"), "did not make"},
  };
  for (const Case& c : cases) {
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{"simulate", kScene, "--t-end", "0.2", "--no-error-estimate"},
          std::vector<std::string>{"critical-speed", kScene, "--from", "10", "--to", "20",
                                   "--step", "5"},
          std::vector<std::string>{"work-precision", kScene, "--t-end", "0.2", "--integrators",
                                   "cvode_bdf", "--rtols", "1e-3"}}) {
      std::vector<std::string> full = args;
      full.insert(full.end(), {"--out", "out"});
      const auto run = run_railstab(full, dir, c.path_env);
      EXPECT_NE(run.exit_code, 0) << args[0] << ": " << run.output;
      EXPECT_NE(run.output.find(c.expected), std::string::npos) << args[0] << ": " << run.output;
      EXPECT_EQ(run.output.find("wrote "), std::string::npos) << run.output;
      EXPECT_EQ(contents(dir / "out"), before) << args[0] << " with " << c.path_env;
    }
  }
  fs::remove_all(dir);
}

// A rerun replaces the run's files as a set: after a run without plots, the
// plots of an earlier run of the same name are gone, not left beside it.
TEST(CliHostile, ARerunReplacesTheWholeSet) {
  const fs::path dir = fresh_dir("rerun");
  const std::vector<std::string> args = {"simulate", kScene, "--t-end", "0.2",
                                         "--no-error-estimate", "--out", "out"};
  auto run = run_railstab(args, dir);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_TRUE(fs::exists(dir / "out/textbook_wheelset_30mps_wheelset_lateral.png"));
  std::vector<std::string> no_plots = args;
  no_plots.push_back("--no-plots");
  run = run_railstab(no_plots, dir);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  for (const auto& [path, text] : contents(dir / "out")) {
    EXPECT_NE(fs::path(path).extension(), ".png") << path;
    EXPECT_NE(fs::path(path).extension(), ".gp") << path;
    EXPECT_NE(path.front(), '.') << path;  // no staging folder left
  }
  EXPECT_TRUE(fs::exists(dir / "out/textbook_wheelset_30mps_run.json"));
  fs::remove_all(dir);
}

// --- scene paths that are not regular files ----------------------------------------

TEST(CliHostile, ANamedPipeAsSceneIsRefusedWithoutHanging) {
  const fs::path dir = fresh_dir("fifo");
  const fs::path fifo = dir / "scene.toml";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const auto run = run_railstab({"equilibrium", fifo.string(), "--out", "out"}, dir, "", 20);
  EXPECT_NE(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("named pipe (not a regular file)"), std::string::npos) << run.output;
  EXPECT_FALSE(fs::exists(dir / "out"));
  fs::remove_all(dir);
}
