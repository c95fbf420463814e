// `--no-plots` on every command that makes plots: gnuplot is not run at all
// (a stand-in `gnuplot` on PATH records every call), no plot data, script or
// PNG is written, and the data files (JSON, CSV, Markdown) still are. The
// stand-in is shown to be found and called when plots are asked for, so a
// command that ignored the flag would be caught.
#include "cli/run_cli.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <ostream>
#include <set>
#include <string>
#include <vector>

#include <sys/stat.h>
#include <unistd.h>

namespace fs = std::filesystem;
using railstab::test::run_railstab;

namespace {

const std::string kCases = RAILSTAB_CASES_DIR;
const std::string kWheelset = kCases + "/textbook_wheelset.toml";

struct NoPlotsDir {
  fs::path root, bin, marker;
};

// A fresh folder with bin/gnuplot: a script that appends a line to `marker`
// and fails (so a command that runs it cannot succeed either).
NoPlotsDir make_dir(const std::string& name) {
  NoPlotsDir d;
  d.root = fs::temp_directory_path() / ("railstab_noplots_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(d.root);
  d.bin = d.root / "bin";
  fs::create_directories(d.bin);
  d.marker = d.root / "gnuplot_was_called";
  const fs::path fake = d.bin / "gnuplot";
  std::ofstream(fake) << "#!/bin/sh\necho called >> '" << d.marker.string() << "'\nexit 1\n";
  ::chmod(fake.c_str(), 0755);
  return d;
}

std::set<std::string> extensions_under(const fs::path& dir) {
  std::set<std::string> ext;
  if (!fs::exists(dir)) return ext;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) ext.insert(e.path().extension().string());
  return ext;
}

struct PlottingCommand {
  std::vector<std::string> args;
  std::set<std::string> data_extensions;  // what the command still writes
};

void PrintTo(const PlottingCommand& c, std::ostream* os) { *os << c.args[0]; }

class NoPlots : public ::testing::TestWithParam<PlottingCommand> {};

}  // namespace

TEST_P(NoPlots, SkipsGnuplotAndWritesTheData) {
  const PlottingCommand& c = GetParam();
  const NoPlotsDir d = make_dir(c.args[0]);
  std::vector<std::string> args = c.args;
  args.insert(args.end(), {"--no-plots", "--out", "out"});
  const auto run = run_railstab(args, d.root, d.bin.string(), 300);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_FALSE(fs::exists(d.marker)) << c.args[0] << " ran gnuplot despite --no-plots";
  EXPECT_EQ(extensions_under(d.root / "out"), c.data_extensions) << c.args[0] << ": " << run.output;
  fs::remove_all(d.root);
}

INSTANTIATE_TEST_SUITE_P(
    EveryPlottingCommand, NoPlots,
    ::testing::Values(
        PlottingCommand{{"simulate", kWheelset, "--t-end", "0.2", "--no-error-estimate"},
                        {".csv", ".json"}},
        PlottingCommand{{"critical-speed", kWheelset, "--from", "10", "--to", "20", "--step", "5"},
                        {".csv", ".json", ".md"}},
        PlottingCommand{{"sweep", kWheelset, "--from", "10", "--to", "20", "--step", "5"},
                        {".csv", ".json", ".md"}},
        PlottingCommand{{"verify", kWheelset}, {".json"}},
        PlottingCommand{{"work-precision", kWheelset, "--t-end", "0.2", "--integrators",
                         "cvode_bdf", "--rtols", "1e-3"},
                        {".csv", ".md"}},
        PlottingCommand{{"contact-geometry", kCases + "/s1002_uic60_contact.toml"},
                        {".csv", ".json"}}),
    [](const auto& info) {
      std::string name = info.param.args[0];
      for (char& ch : name)
        if (ch == '-') ch = '_';
      return name;
    });

// The control: without --no-plots the stand-in is found and called (and its
// failure is reported), so the test above would see a command that ignores
// the flag.
TEST(NoPlotsControl, WithoutTheFlagTheStandInGnuplotIsCalled) {
  const NoPlotsDir d = make_dir("control");
  const auto run = run_railstab({"contact-geometry", kCases + "/s1002_uic60_contact.toml",
                                 "--out", "out"},
                                d.root, d.bin.string(), 300);
  EXPECT_NE(run.exit_code, 0) << run.output;
  EXPECT_TRUE(fs::exists(d.marker)) << run.output;
  fs::remove_all(d.root);
}
