// simulate and verify with --offset and --mode (cli/start_flags.hpp): what
// the run JSON says of the start, the errors that name the flag (non-zero
// exit, nothing written), and verify's CPU times of both its runs.
#include <gtest/gtest.h>

#include "cli/run_cli.hpp"
#include "support/json_text.hpp"
#include "support/test_files.hpp"

#include <algorithm>
#include <cmath>
#include <regex>

namespace fs = std::filesystem;
using namespace railstab;
using railstab::test::json_value;

namespace {

const std::string kBogie = test::case_path("thesis_bogie_tangent");

}  // namespace

TEST(CliStartFlags, SimulateOnTheHuntingModeSaysSoInItsRunJson) {
  const fs::path dir = test::fresh_dir("cli_start", "mode");
  const test::CliRun run = test::run_railstab(
      {"simulate", kBogie, "--speed", "30", "--t-end", "0.3", "--mode", "hunting", "--mode-amplitude",
       "0.002", "--no-plots", "--no-error-estimate", "--out", "out"},
      dir);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const std::string json = test::read_text(dir / "out" / "thesis_bogie_tangent_30mps_run.json");
  EXPECT_EQ(json_value(json, "kind"), "\"mode\"");
  EXPECT_EQ(json_value(json, "leading_wheelset"), "\"wheelset1\"");
  EXPECT_EQ(std::stod(json_value(json, "leading_wheelset_y_m")), 0.002);
  // The CSV's first row: wheelset1 at the centred steady state (|y| < 1e-9 m
  // on tangent track) plus 2 mm.
  const std::string csv = test::read_text(dir / "out" / "thesis_bogie_tangent_30mps.csv");
  const size_t header_end = csv.find('\n');
  const std::string header = csv.substr(0, header_end);
  const std::string row = csv.substr(header_end + 1, csv.find('\n', header_end + 1) - header_end - 1);
  auto split = [](const std::string& line) {
    std::vector<std::string> fields;
    size_t from = 0;
    for (size_t comma; (comma = line.find(',', from)) != std::string::npos; from = comma + 1)
      fields.push_back(line.substr(from, comma - from));
    fields.push_back(line.substr(from));
    return fields;
  };
  const std::vector<std::string> names = split(header), values = split(row);
  const auto column = std::find(names.begin(), names.end(), "wheelset1.y_m");
  ASSERT_NE(column, names.end()) << header;
  EXPECT_NEAR(std::stod(values[size_t(column - names.begin())]), 0.002, 1e-9);
}

// --arc-length places the reference point as --set scene.reference_arc_length_m
// does (docs/commands.md): the same bytes; and it acts: starting 100 m further
// on, past the clothoid into the arc, gives another motion.
TEST(CliStartFlags, SimulateArcLengthIsTheSceneKey) {
  const std::string curve = test::case_path("thesis_bogie_curve");
  const fs::path dir = test::fresh_dir("cli_start", "arc_length");
  auto run_at = [&](const std::string& out, const std::vector<std::string>& place) {
    std::vector<std::string> args = {"simulate", curve, "--speed", "20", "--t-end", "0.2",
                                     "--no-plots", "--no-error-estimate", "--out", out};
    args.insert(args.end(), place.begin(), place.end());
    const test::CliRun run = test::run_railstab(args, dir);
    EXPECT_EQ(run.exit_code, 0) << run.output;
    return test::read_text(dir / out / "thesis_bogie_curve_20mps.csv");
  };
  const std::string by_flag = run_at("flag", {"--arc-length", "1300"});
  const std::string by_key = run_at("key", {"--set", "scene.reference_arc_length_m=1300"});
  const std::string by_default = run_at("default", {});
  ASSERT_FALSE(by_flag.empty());
  EXPECT_EQ(by_flag, by_key);
  EXPECT_NE(by_flag, by_default);
}

TEST(CliStartFlags, MistakesNameTheFlagAndWriteNothing) {
  const fs::path dir = test::fresh_dir("cli_start", "mistakes");
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--offset", "wheelset9.y_m=0.001"}, "--offset 'wheelset9.y_m=0.001': no body named 'wheelset9'"},
      {{"--offset", "wheelset1.lateral=0.001"}, "a coordinate key of initial_offset"},
      {{"--offset", "wheelset1.y_m=abc"}, "a finite number after '='"},
      {{"--mode", "hunting"}, "expected --mode-amplitude M too"},
      {{"--mode-amplitude", "0.001"}, "--mode-amplitude: expected --mode hunting or --mode NAME too"},
      {{"--mode", "hunting", "--mode-amplitude", "0.001", "--offset", "wheelset1.y_m=0.001"},
       "--mode and --offset: give one of them"},
      {{"--mode", "wobble", "--mode-amplitude", "0.001"}, "--mode 'wobble': no mode of that name"},
      {{"--mode", "hunting", "--mode-amplitude", "1"}, "--mode-amplitude"},
  };
  for (const auto& [flags, message] : cases) {
    for (const std::string command : {"simulate", "verify"}) {
      std::vector<std::string> args = {command, kBogie, "--no-plots", "--out", "out"};
      args.insert(args.end(), flags.begin(), flags.end());
      const test::CliRun run = test::run_railstab(args, dir);
      EXPECT_NE(run.exit_code, 0) << command << " " << flags.front();
      EXPECT_NE(run.output.find(message), std::string::npos) << command << ": " << run.output;
      EXPECT_FALSE(fs::exists(dir / "out")) << command << " " << flags.front();
    }
  }
}

TEST(CliStartFlags, VerifyReportsTheCpuTimeOfItsReferenceRun) {
  const fs::path dir = test::fresh_dir("cli_start", "verify_cpu");
  const test::CliRun run = test::run_railstab(
      {"verify", kBogie, "--speed", "30", "--offset", "wheelset1.y_m=0.0005", "--periods", "4",
       "--settle-periods", "1", "--no-plots", "--out", "out"},
      dir);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const std::string json = test::read_text(dir / "out" / "thesis_bogie_tangent_verify_30mps.json");
  for (const std::string key : {"integration_cpu_s", "reference_integration_cpu_s",
                                "reference_integration_wall_s"}) {
    const double v = std::stod(json_value(json, key));
    EXPECT_TRUE(std::isfinite(v)) << key;
    EXPECT_GT(v, 0.0) << key;
  }
  EXPECT_NE(json.find("\"start\": \"scene initial offsets, --offset wheelset1.y_m=0.0005\""),
            std::string::npos)
      << json;
  EXPECT_NE(run.output.find("tighter reference run: wall"), std::string::npos) << run.output;
}
