// critical-speed --amplitude / --amplitudes: the outputs exist and parse,
// the JSON carries the amplitude and the critical speed equals the
// library's quasi-linear search; bad values stop with a message naming the
// flag and write nothing.
#include <gtest/gtest.h>

#include "cli/run_cli.hpp"
#include "io/format_checks.hpp"
#include "support/json_text.hpp"
#include "support/test_files.hpp"

#include <railstab/setup/prepare_scene.hpp>
#include <railstab/stability/quasi_linear_critical_speed.hpp>

#include <filesystem>
#include <regex>

namespace fs = std::filesystem;
using namespace railstab;
using railstab::test::json_value;

TEST(CliQuasiLinear, AmplitudeRunWritesTheQuasiLinearCriticalSpeed) {
  const std::string scene = test::case_path("thesis_bogie_s1002_tangent");
  const fs::path dir = test::fresh_dir("cli_quasi_linear", "amplitude");
  const test::CliRun run = test::run_railstab(
      {"critical-speed", scene, "--amplitude", "0.003", "--from", "5", "--to", "150", "--step",
       "5", "--no-plots", "--out", "out"},
      dir);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const std::string stem = "thesis_bogie_s1002_tangent_quasi_linear";
  for (const char* ext : {"_critical_speed.json", "_critical_speed.md", "_eigenvalues.csv"})
    EXPECT_TRUE(fs::exists(dir / "out" / (stem + ext))) << ext;
  const std::string json = test::read_text(dir / "out" / (stem + "_critical_speed.json"));
  EXPECT_TRUE(test::is_valid_json(json));
  EXPECT_EQ(std::stod(json_value(json, "amplitude_m")), 0.003);
  const PreparedScene s = prepare_scene(scene, {});
  CriticalSpeedOptions o;
  o.from_m_per_s = 5;
  o.to_m_per_s = 150;
  o.grid_step_m_per_s = 5;
  const QuasiLinearCriticalSpeed q =
      find_quasi_linear_critical_speed(s.model, s.equilibrium.state, s.speed_m_per_s, 0.003, o);
  ASSERT_TRUE(q.result.critical_speed_found);
  EXPECT_NEAR(std::stod(json_value(json, "critical_speed_m_per_s")), q.result.critical_speed_m_per_s,
              1e-9 * q.result.critical_speed_m_per_s);
  EXPECT_NEAR(std::stod(json_value(json, "equivalent_conicity")), q.wheelsets[0].equivalent_conicity,
              1e-9);
  EXPECT_NE(test::read_text(dir / "out" / (stem + "_critical_speed.md")).find("Quasi-linear contact"),
            std::string::npos);
}

TEST(CliQuasiLinear, AmplitudeCurveWritesCsvAndJson) {
  const std::string scene = test::case_path("thesis_bogie_s1002_tangent");
  const fs::path dir = test::fresh_dir("cli_quasi_linear", "curve");
  const test::CliRun run = test::run_railstab(
      {"critical-speed", scene, "--amplitudes", "0.001:0.003:0.001", "--from", "5", "--to", "150",
       "--step", "5", "--no-plots", "--out", "out"},
      dir);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const std::string base = "thesis_bogie_s1002_tangent_quasi_linear_curve";
  const std::string json = test::read_text(dir / "out" / (base + ".json"));
  EXPECT_TRUE(test::is_valid_json(json));
  const auto csv = test::parse_csv(test::read_text(dir / "out" / (base + ".csv")));
  ASSERT_TRUE(csv.has_value());
  ASSERT_EQ(csv->size(), 4u);  // header and three amplitudes
  EXPECT_EQ((*csv)[0][0], "amplitude_m");
  for (size_t i = 1; i < 4; ++i) {
    EXPECT_NEAR(std::stod((*csv)[i][0]), 0.001 * double(i), 1e-12);
    EXPECT_EQ((*csv)[i][2], "1") << "no critical speed at row " << i;
    EXPECT_GT(std::stod((*csv)[i][3]), 5.0);
  }
  EXPECT_NE(run.output.find("amplitude 3/3"), std::string::npos) << run.output;
}

TEST(CliQuasiLinear, BadAmplitudesNameTheFlagAndWriteNothing) {
  const std::string scene = test::case_path("thesis_bogie_s1002_tangent");
  const fs::path dir = test::fresh_dir("cli_quasi_linear", "bad");
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--amplitude", "0"}, "--amplitude"},
      {{"--amplitude", "-0.001"}, "--amplitude"},
      {{"--amplitude", "nan"}, "--amplitude"},
      {{"--amplitude", "0.02"}, "--amplitude"},  // beyond the table's 12 mm less 1 mm
      {{"--amplitudes", "0.001:0.002"}, "--amplitudes"},
      {{"--amplitudes", "0.003:0.001:0.001"}, "--amplitudes"},
      {{"--amplitudes", "0.001:0.03:0.001"}, "--amplitudes"},
      {{"--amplitudes", "0.001:x:0.001"}, "--amplitudes"},
      {{"--amplitude", "0.001", "--amplitudes", "0.001:0.002:0.001"}, "--amplitude"},
  };
  for (const auto& [flags, name] : cases) {
    std::vector<std::string> args = {"critical-speed", scene, "--no-plots", "--out", "out"};
    args.insert(args.end(), flags.begin(), flags.end());
    const test::CliRun run = test::run_railstab(args, dir);
    EXPECT_NE(run.exit_code, 0) << flags[1];
    EXPECT_NE(run.output.find(name), std::string::npos) << flags[1] << ": " << run.output;
    EXPECT_FALSE(fs::exists(dir / "out")) << flags[1];
  }
}
