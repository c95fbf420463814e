// The critical-speed report states the Hopf point's criticality: the JSON's
// first_lyapunov_coefficient and hopf_kind equal the library's
// hopf_criticality at the same search (12 printed digits), the Markdown and
// the terminal say it in words; with profile contact both keys are null and
// the reason says why (the tables are only C1).
#include <gtest/gtest.h>

#include "cli/run_cli.hpp"
#include "support/json_text.hpp"
#include "support/test_files.hpp"

#include <railstab/nonlinear/hopf_assessment.hpp>
#include <railstab/setup/prepare_scene.hpp>
#include <railstab/stability/speed_analysis.hpp>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

namespace fs = std::filesystem;
using namespace railstab;
using railstab::test::json_value;

TEST(CliHopf, CriticalSpeedJsonCarriesTheLibrarysFirstLyapunovCoefficient) {
  const std::string scene = std::string(RAILSTAB_CASES_DIR) + "/thesis_bogie_tangent.toml";
  const fs::path dir = test::fresh_dir("cli_hopf", "knife_edge");
  const test::CliRun run = test::run_railstab({"critical-speed", scene, "--no-plots", "--out", "out"}, dir);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const std::string json = test::read_text(dir / "out" / "thesis_bogie_tangent_critical_speed.json");
  // The library on the same search (the command's defaults: 5..150 m/s, grid 2.5 m/s).
  const PreparedScene s = prepare_scene(scene, {});
  CriticalSpeedOptions opt;
  opt.from_m_per_s = 5.0;
  opt.to_m_per_s = 150.0;
  opt.grid_step_m_per_s = 2.5;
  const CriticalSpeedResult r = find_critical_speed(s.model, s.equilibrium.state, s.speed_m_per_s, opt);
  const HopfAssessment h = assess_hopf(s.model, r);
  ASSERT_TRUE(h.computed) << h.not_computed_reason;
  const double l1 = std::stod(json_value(json, "first_lyapunov_coefficient"));
  EXPECT_NEAR(l1, h.result.first_lyapunov_coefficient,
              1e-10 * std::abs(h.result.first_lyapunov_coefficient));
  EXPECT_EQ(json_value(json, "hopf_kind"), "\"" + hopf_kind_name(h.result.kind) + "\"");
  EXPECT_EQ(json_value(json, "computed"), "true");
  EXPECT_EQ(json_value(json, "amplitude_state"), "\"wheelset1.y_m\"");
  const double coefficient = std::stod(json_value(json, "cycle_amplitude_coefficient_m_per_sqrt_m_per_s"));
  EXPECT_NEAR(coefficient, h.amplitude_coefficient_m_per_sqrt_m_per_s,
              1e-10 * h.amplitude_coefficient_m_per_sqrt_m_per_s);
  EXPECT_GT(coefficient, 0.0);
  const std::string md = test::read_text(dir / "out" / "thesis_bogie_tangent_critical_speed.md");
  EXPECT_NE(md.find("| Hopf bifurcation | " + hopf_kind_name(h.result.kind)), std::string::npos);
  EXPECT_NE(run.output.find("Hopf bifurcation: " + hopf_kind_name(h.result.kind)), std::string::npos)
      << run.output;
}

TEST(CliHopf, ProfileContactLeavesTheCoefficientNullAndSaysWhy) {
  const std::string scene = std::string(RAILSTAB_CASES_DIR) + "/thesis_bogie_s1002_tangent.toml";
  const fs::path dir = test::fresh_dir("cli_hopf", "profiles");
  const test::CliRun run = test::run_railstab({"critical-speed", scene, "--no-plots", "--out", "out"}, dir);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const std::string json = test::read_text(dir / "out" / "thesis_bogie_s1002_tangent_critical_speed.json");
  ASSERT_NE(json_value(json, "critical_speed_m_per_s"), "null");
  EXPECT_EQ(json_value(json, "first_lyapunov_coefficient"), "null");
  EXPECT_EQ(json_value(json, "hopf_kind"), "null");
  EXPECT_EQ(json_value(json, "computed"), "false");
  EXPECT_NE(json_value(json, "not_computed_reason").find("profile contact"), std::string::npos);
}
