// `railstab sensitivity`: ranked CSV/JSON/Markdown and the tornado plot; an
// unknown --key or a scene without a critical speed in range is refused
// with the flag named and no output.
#include <gtest/gtest.h>

#include "cli/run_cli.hpp"

#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace fs = std::filesystem;

TEST(CliSensitivity, RankedFilesAndRefusals) {
  const fs::path dir = fs::temp_directory_path() / ("railstab_cli_sens_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string scene = std::string(RAILSTAB_CASES_DIR) + "/textbook_bogie.toml";
  const auto ok = railstab::test::run_railstab({"sensitivity", scene, "--out", "o"}, dir);
  ASSERT_EQ(ok.exit_code, 0) << ok.output;
  std::ifstream csv(dir / "o" / "textbook_bogie_sensitivity.csv");
  std::string header, first;
  std::getline(csv, header);
  std::getline(csv, first);
  EXPECT_EQ(header,
            "rank,parameter,value,critical_speed_derivative_m_per_s_per_unit,elasticity,"
            "eigenvalue_real_derivative_per_s_per_unit,eigenvalue_imag_derivative_per_s_per_unit");
  EXPECT_EQ(first.rfind("1,contacts.textbook_linear.conicity,0.1,", 0), 0u) << first;
  for (const char* f : {"textbook_bogie_sensitivity.json", "textbook_bogie_sensitivity.md",
                        "textbook_bogie_sensitivity_tornado.png", "textbook_bogie_sensitivity_tornado.svg"})
    EXPECT_GT(fs::file_size(dir / "o" / f), 0u) << f;
  // --set reaches it: a doubled conicity lowers the critical speed.
  const auto set = railstab::test::run_railstab(
      {"sensitivity", scene, "--set", "contacts.textbook_linear.conicity=0.2", "--key",
       "contacts.textbook_linear.conicity", "--no-plots", "--out", "s"},
      dir);
  ASSERT_EQ(set.exit_code, 0) << set.output;
  EXPECT_EQ(set.output.find("critical speed 102.46"), std::string::npos) << set.output;

  const auto bad_key = railstab::test::run_railstab(
      {"sensitivity", scene, "--key", "bodies.nothing.mass_kg", "--no-plots", "--out", "bad"}, dir);
  EXPECT_NE(bad_key.exit_code, 0);
  EXPECT_NE(bad_key.output.find("--key bodies.nothing.mass_kg"), std::string::npos) << bad_key.output;
  const auto no_crossing = railstab::test::run_railstab(
      {"sensitivity", scene, "--to", "50", "--no-plots", "--out", "bad"}, dir);
  EXPECT_NE(no_crossing.exit_code, 0);
  EXPECT_NE(no_crossing.output.find("no critical speed"), std::string::npos) << no_crossing.output;
  EXPECT_FALSE(fs::exists(dir / "bad"));
  fs::remove_all(dir);
}
