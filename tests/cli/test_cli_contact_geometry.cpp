// railstab contact-geometry SCENE [--contact NAME] reads its contact with the
// scene loader: from a whole scene (the thesis vehicle on S1002/UIC60) as
// from a file of contacts alone, with the same equivalent conicity; a wrong
// --contact or a scene without profile contacts is a clear error naming the
// file and the flag or key, exit code non-zero, nothing written.
#include "cli/run_cli.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <unistd.h>
#include "support/test_files.hpp"

namespace fs = std::filesystem;
using railstab::test::run_railstab;

namespace {

fs::path fresh_dir(const std::string& name) { return railstab::test::fresh_dir("cg", name); }

std::string conicity_line(const std::string& output) {
  const size_t at = output.find("equivalent conicity (EN 15302) at 3 mm:");
  return at == std::string::npos ? "" : output.substr(at, output.find('\n', at) - at);
}

}  // namespace

TEST(CliContactGeometry, SceneAndContactFileGiveTheSameConicityAndBadChoicesAreNamed) {
  const fs::path dir = fresh_dir("choice");
  const std::string cases = RAILSTAB_CASES_DIR;
  const auto whole = run_railstab({"contact-geometry", cases + "/thesis_vehicle_s1002_tangent.toml",
                                   "--no-plots", "--out", "a"},
                                  dir);
  ASSERT_EQ(whole.exit_code, 0) << whole.output;
  EXPECT_TRUE(fs::exists(dir / "a/thesis_vehicle_s1002_tangent_s1002_uic60.json"));
  // The contact file places the pair with r0 = 0.46 m, the vehicle with
  // 0.45 m: the delta-r function and so the conicity do not depend on r0 to
  // the four digits printed (the radius only shifts both wheels alike).
  const auto alone = run_railstab(
      {"contact-geometry", cases + "/s1002_uic60_contact.toml", "--no-plots", "--out", "b"}, dir);
  ASSERT_EQ(alone.exit_code, 0) << alone.output;
  EXPECT_FALSE(conicity_line(whole.output).empty()) << whole.output;
  EXPECT_EQ(conicity_line(whole.output), conicity_line(alone.output));

  const auto wrong = run_railstab({"contact-geometry", cases + "/thesis_vehicle_s1002_tangent.toml",
                                   "--contact", "nope", "--no-plots", "--out", "c"},
                                  dir);
  EXPECT_NE(wrong.exit_code, 0);
  EXPECT_NE(wrong.output.find("thesis_vehicle_s1002_tangent.toml: --contact 'nope'"),
            std::string::npos)
      << wrong.output;
  EXPECT_NE(wrong.output.find("profile contacts: 's1002_uic60'"), std::string::npos)
      << wrong.output;
  EXPECT_FALSE(fs::exists(dir / "c"));

  const auto cone = run_railstab(
      {"contact-geometry", cases + "/thesis_vehicle_tangent.toml", "--no-plots", "--out", "d"}, dir);
  EXPECT_NE(cone.exit_code, 0);
  EXPECT_NE(cone.output.find("thesis_vehicle_tangent.toml: contacts: expected exactly one contact "
                             "with geometry = \"profiles\""),
            std::string::npos)
      << cone.output;
  EXPECT_FALSE(fs::exists(dir / "d"));
  fs::remove_all(dir);
}

// A scene file whose name holds a quote and a gnuplot command: the plots
// are made (the name is a string literal in the script, nothing runs), the
// files land in --out under a safe name; a re-run with --no-plots removes
// the earlier plots so old plots never sit beside new data.
TEST(CliContactGeometry, HostileSceneNameIsQuotedAndStalePlotsAreRemoved) {
  const fs::path dir = fresh_dir("hostile");
  const std::string cases = RAILSTAB_CASES_DIR;
  // The contact file next to its profiles, under a hostile name.
  fs::create_directories(dir / "in/profiles");
  for (const char* f : {"MBench_S1002_v3.prw", "MBench_UIC60_v3.prr"})
    fs::copy_file(cases + "/profiles/" + f, dir / "in/profiles" / f);
  // Unquoted, gnuplot would read: set title 'x'; system "touch pwned"; print '...'
  const std::string hostile = "x'; system \"touch pwned\"; print '.toml";
  fs::copy_file(cases + "/s1002_uic60_contact.toml", dir / "in" / hostile);
  const auto run = run_railstab({"contact-geometry", "in/" + hostile, "--out", "o"}, dir);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_FALSE(fs::exists(dir / "pwned"));
  EXPECT_FALSE(fs::exists(dir / "in/pwned"));
  EXPECT_FALSE(fs::exists(dir / "o/pwned"));
  int pngs = 0;
  std::string png_name;
  for (const auto& e : fs::directory_iterator(dir / "o"))
    if (e.path().extension() == ".png") {
      ++pngs;
      png_name = e.path().filename().string();
      EXPECT_GT(fs::file_size(e.path()), 1000u) << e.path();
    }
  EXPECT_EQ(pngs, 3);
  EXPECT_EQ(png_name.find('\''), std::string::npos) << png_name;

  const auto again = run_railstab({"contact-geometry", "in/" + hostile, "--out", "o", "--no-plots"},
                                  dir);
  ASSERT_EQ(again.exit_code, 0) << again.output;
  int left = 0;
  for (const auto& e : fs::directory_iterator(dir / "o"))
    if (e.path().extension() == ".png" || e.path().extension() == ".gp") ++left;
  EXPECT_EQ(left, 0);
  fs::remove_all(dir);
}

// --set on contact-geometry changes the contact as an edited file would: a
// gauge 2 mm wider (1.437 m) reaches the JSON and lowers the equivalent
// conicity at 3 mm (the wheels sit further from the flange); a key the
// contact does not have is refused naming --set and the key.
TEST(CliContactGeometry, SetOverridesTheContactsValues) {
  const fs::path dir = fresh_dir("set");
  const std::string scene = std::string(RAILSTAB_CASES_DIR) + "/s1002_uic60_contact.toml";
  const auto base = run_railstab({"contact-geometry", scene, "--no-plots", "--out", "a"}, dir);
  ASSERT_EQ(base.exit_code, 0) << base.output;
  const auto wide = run_railstab({"contact-geometry", scene, "--no-plots", "--out", "b", "--set",
                                  "contacts.s1002_uic60.track_gauge_m=1.437"},
                                 dir);
  ASSERT_EQ(wide.exit_code, 0) << wide.output;
  std::ifstream in(dir / "b/s1002_uic60_contact_s1002_uic60.json");
  std::stringstream json;
  json << in.rdbuf();
  EXPECT_NE(json.str().find("\"track_gauge_m\": 1.437"), std::string::npos) << json.str();
  auto conicity = [](const std::string& line) {
    return std::stod(line.substr(line.find(':') + 1));
  };
  EXPECT_LT(conicity(conicity_line(wide.output)), conicity(conicity_line(base.output)));
  const auto bad = run_railstab({"contact-geometry", scene, "--no-plots", "--out", "c", "--set",
                                 "contacts.nope.track_gauge_m=1.437"},
                                dir);
  EXPECT_NE(bad.exit_code, 0);
  EXPECT_NE(bad.output.find("--set contacts.nope.track_gauge_m"), std::string::npos) << bad.output;
  EXPECT_FALSE(fs::exists(dir / "c"));
  fs::remove_all(dir);
}

// contact-geometry writes the contact table; a contact file with geometry =
// "table" naming it is reported from the table (the conicity at 3 mm within
// 1 % of the profiles'); a table that is not there is an error naming the
// scene, the key and the file; nothing is written then.
TEST(CliContactGeometry, WritesTheContactTableAndReadsItBack) {
  const fs::path dir = fresh_dir("table");
  const std::string cases = RAILSTAB_CASES_DIR;
  const auto written = run_railstab(
      {"contact-geometry", cases + "/s1002_uic60_contact.toml", "--no-plots", "--out", "a"}, dir);
  ASSERT_EQ(written.exit_code, 0) << written.output;
  const fs::path table = dir / "a/s1002_uic60_contact_s1002_uic60_contact_table.csv";
  ASSERT_TRUE(fs::exists(table)) << written.output;
  EXPECT_NE(written.output.find("wrote " + std::string("a/s1002_uic60_contact_s1002_uic60_contact_table.csv")),
            std::string::npos)
      << written.output;
  std::ofstream(dir / "table_contact.toml")
      << "[contacts.s1002_table]\ngeometry = \"table\"\ncontact_table = \"" << table.string()
      << "\"\nnominal_rolling_radius_m = 0.46\nnormal = \"hertz\"\ntangential = \"kalker_hertz\"\n";
  const auto back =
      run_railstab({"contact-geometry", "table_contact.toml", "--out", "b"}, dir);
  ASSERT_EQ(back.exit_code, 0) << back.output;
  auto conicity = [](const std::string& line) { return std::stod(line.substr(line.find(':') + 1)); };
  ASSERT_FALSE(conicity_line(back.output).empty()) << back.output;
  EXPECT_NEAR(conicity(conicity_line(back.output)), conicity(conicity_line(written.output)),
              0.01 * conicity(conicity_line(written.output)))
      << back.output;
  EXPECT_TRUE(fs::exists(dir / "b/table_contact_s1002_table_characteristic.csv"));
  EXPECT_TRUE(fs::exists(dir / "b/table_contact_s1002_table.json"));
  EXPECT_FALSE(fs::exists(dir / "b/table_contact_s1002_table_contact_table.csv"));

  std::ofstream(dir / "missing.toml")
      << "[contacts.s1002_table]\ngeometry = \"table\"\ncontact_table = \"nowhere.csv\"\n"
         "nominal_rolling_radius_m = 0.46\nnormal = \"hertz\"\ntangential = \"kalker_hertz\"\n";
  const auto missing = run_railstab({"contact-geometry", "missing.toml", "--out", "c"}, dir);
  EXPECT_NE(missing.exit_code, 0);
  EXPECT_NE(missing.output.find("missing.toml: contacts.s1002_table.contact_table: "),
            std::string::npos)
      << missing.output;
  EXPECT_NE(missing.output.find("nowhere.csv: contact table file not found"), std::string::npos)
      << missing.output;
  EXPECT_FALSE(fs::exists(dir / "c"));
  fs::remove_all(dir);
}
