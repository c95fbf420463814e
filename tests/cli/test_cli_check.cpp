// `railstab check` and the model-check warnings every command prints first,
// run as a user would run them.
#include <gtest/gtest.h>

#include "cli/run_cli.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include "support/test_files.hpp"

using railstab::test::run_railstab;
namespace fs = std::filesystem;

namespace {

fs::path fresh_dir(const std::string& name) { return railstab::test::fresh_dir("cli_check", name); }

using railstab::test::read_text;

const std::string kBogie = std::string(RAILSTAB_CASES_DIR) + "/thesis_bogie_tangent.toml";

TEST(CliCheck, CleanSceneReportsQuantitiesWithoutWarnings) {
  const fs::path dir = fresh_dir("clean");
  const auto run = run_railstab({"check", kBogie, "--out", "out"}, dir);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("total mass 6020 kg"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("0 warning(s), 0 error(s)"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("lowest natural frequencies at rest"), std::string::npos) << run.output;
  const std::string md = read_text(dir / "out/thesis_bogie_tangent_check_20mps.md");
  const std::string json = read_text(dir / "out/thesis_bogie_tangent_check_20mps.json");
  EXPECT_NE(md.find("## Static deflections under the preloads"), std::string::npos) << md;
  EXPECT_NE(json.find("\"axle_loads\""), std::string::npos) << json;
  fs::remove_all(dir);
}

// A mistake is a warning, not an error: exit 0; every command prints it.
TEST(CliCheck, WarningsAtTheStartOfEveryCommand) {
  const fs::path dir = fresh_dir("mistake");
  std::string text = read_text(kBogie);
  const std::string from = "half_contact_distance_m = 0.75";
  ASSERT_NE(text.find(from), std::string::npos);
  text.replace(text.find(from), from.size(), "half_contact_distance_m = 0.7175");
  std::ofstream(dir / "gauge.toml") << text;

  const auto check = run_railstab({"check", "gauge.toml", "--no-frequencies", "--out", "out"}, dir);
  EXPECT_EQ(check.exit_code, 0) << check.output;
  EXPECT_NE(check.output.find("1 warning(s)"), std::string::npos) << check.output;
  EXPECT_NE(check.output.find("warning: contacts.thesis_knife_edge.half_contact_distance_m"),
            std::string::npos)
      << check.output;
  EXPECT_NE(read_text(dir / "out/gauge_check_20mps.json").find("contact_distance_mismatch"),
            std::string::npos);

  const auto eq = run_railstab({"equilibrium", "gauge.toml", "--out", "out"}, dir);
  EXPECT_EQ(eq.exit_code, 0) << eq.output;
  EXPECT_NE(eq.output.find("warning: contacts.thesis_knife_edge.half_contact_distance_m"),
            std::string::npos)
      << eq.output;
  // The clean case prints none.
  const auto clean = run_railstab({"equilibrium", kBogie, "--out", "out"}, dir);
  EXPECT_EQ(clean.exit_code, 0) << clean.output;
  EXPECT_EQ(clean.output.find("warning:"), std::string::npos) << clean.output;
  fs::remove_all(dir);
}

}  // namespace
