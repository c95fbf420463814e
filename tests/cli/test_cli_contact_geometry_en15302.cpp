// railstab contact-geometry and EN 15302 (docs/en15302.md), as a user runs it:
// - a contact-only file without `normal`/`tangential` (it never uses them);
// - an asymmetric wheelset (right_nominal_rolling_radius_m and a right
//   wheel file): the equilibrium is reported off the centre, no contact
//   table file is written (its format holds one wheel);
// - the grids from the flags (the conicity CSV has their amplitudes) and a
//   bad grid refused naming the flag, nothing written;
// - shifts without rigid contact and an amplitude whose motion leaves the
//   delta r function are reported on stderr and in the JSON's not_computed,
//   and every file is still written;
// - a scene building a vehicle model still needs `normal`.
#include "cli/run_cli.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "support/test_files.hpp"

namespace fs = std::filesystem;
using railstab::test::run_railstab;

namespace {

// A contact file of the benchmark pair with `extra` keys, in `dir`.
fs::path contact_file(const fs::path& dir, const std::string& extra) {
  const std::string profiles = std::string(RAILSTAB_CASES_DIR) + "/profiles/";
  const fs::path p = dir / "pair.toml";
  std::ofstream(p) << "[contacts.pair]\ngeometry = \"profiles\"\nwheel_profile = \"" << profiles
                   << "MBench_S1002_v3.prw\"\nrail_profile = \"" << profiles
                   << "MBench_UIC60_v3.prr\"\nnominal_rolling_radius_m = 0.46\n"
                   << extra;
  return p;
}

size_t csv_rows(const fs::path& p) {
  std::ifstream in(p);
  std::string line;
  size_t n = 0;
  while (std::getline(in, line)) ++n;
  return n == 0 ? 0 : n - 1;
}

}  // namespace

TEST(CliContactGeometryEn15302, ContactFileWithoutForceModelsAndAsymmetricWheelset) {
  const fs::path dir = railstab::test::fresh_dir("cg15302", "asym");
  const fs::path plain = contact_file(dir, "");
  const auto run = run_railstab({"contact-geometry", plain.string(), "--out", "a", "--no-plots"}, dir);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_TRUE(fs::exists(dir / "a/pair_pair_contact_table.csv"));

  const std::string profiles = std::string(RAILSTAB_CASES_DIR) + "/profiles/";
  const fs::path asym = contact_file(dir, "right_nominal_rolling_radius_m = 0.459\n"
                                          "right_wheel_profile = \"" + profiles +
                                              "MBench_S1002_v3.prw\"\n");
  const auto a = run_railstab({"contact-geometry", asym.string(), "--out", "b", "--no-plots"}, dir);
  ASSERT_EQ(a.exit_code, 0) << a.output;
  EXPECT_NE(a.output.find("equilibrium (delta r = 0) at a lateral shift of -"), std::string::npos)
      << a.output;
  EXPECT_FALSE(fs::exists(dir / "b/pair_pair_contact_table.csv"));
  const std::string json = railstab::test::read_text(dir / "b/pair_pair.json");
  EXPECT_NE(json.find("\"asymmetric_wheelset\": true"), std::string::npos) << json;
  EXPECT_NE(json.find("\"right_nominal_rolling_radius_m\": 0.459"), std::string::npos) << json;
  EXPECT_NE(json.find("\"equilibrium_lateral_m\": -"), std::string::npos) << json;
}

TEST(CliContactGeometryEn15302, GridsFromFlagsAndPointsNotComputedAreReported) {
  const fs::path dir = railstab::test::fresh_dir("cg15302", "grid");
  const fs::path file = contact_file(dir, "");
  const auto run = run_railstab({"contact-geometry", file.string(), "--out", "a", "--no-plots",
                                 "--delta-r-half-range-m", "0.005", "--delta-r-step-m", "0.0005",
                                 "--amplitude-min-m", "0.001", "--amplitude-max-m", "0.004",
                                 "--amplitude-step-m", "0.001"},
                                dir);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_EQ(csv_rows(dir / "a/pair_pair_characteristic.csv"), 21u);
  EXPECT_EQ(csv_rows(dir / "a/pair_pair_conicity.csv"), 4u);

  const auto bad = run_railstab({"contact-geometry", file.string(), "--out", "b", "--no-plots",
                                 "--amplitude-min-m", "0.005", "--amplitude-max-m", "0.004"},
                                dir);
  EXPECT_NE(bad.exit_code, 0);
  EXPECT_NE(bad.output.find("--amplitude-min-m: expected a positive amplitude not above the largest"), std::string::npos) << bad.output;
  EXPECT_FALSE(fs::exists(dir / "b"));

  // A cone wheel only 16 mm wide (u from -23 to -7 mm, about its contact
  // at -15 mm) on a circular rail head: the rigid contact runs off the
  // wheel beyond a lateral shift of about 7 mm. Those shifts
  // and the 8 mm amplitude are reported (stderr and the JSON's
  // not_computed, empty CSV fields); the 2 mm amplitude and every file are
  // still written, exit 0.
  {
    std::ofstream wheel(dir / "narrow_cone.txt"), rail(dir / "circle.txt");
    for (int i = -230; i <= -70; ++i) wheel << i * 0.1 << " " << 0.05 * i * 0.1 << "\n";
    for (int i = -400; i <= 400; ++i) {
      const double y = i * 0.1;
      rail << y << " " << std::sqrt(300.0 * 300.0 - y * y) - 300.0 << "\n";
    }
  }
  std::ofstream(dir / "narrow.toml")
      << "[contacts.narrow]\ngeometry = \"profiles\"\nwheel_profile_mm = \"narrow_cone.txt\"\n"
         "rail_profile_mm = \"circle.txt\"\nnominal_rolling_radius_m = 0.46\n"
         "gauge_measuring_height_m = 0.002\ntrack_gauge_m = 1.430834\n";
  const auto narrow = run_railstab({"contact-geometry", "narrow.toml", "--out", "c", "--no-plots",
                                    "--amplitude-min-m", "0.002", "--amplitude-max-m", "0.008",
                                    "--amplitude-step-m", "0.006"},
                                   dir);
  ASSERT_EQ(narrow.exit_code, 0) << narrow.output;
  EXPECT_NE(narrow.output.find("warning: equivalent conicity not computed at 8 mm"),
            std::string::npos)
      << narrow.output;
  EXPECT_NE(narrow.output.find("warning: characteristic functions not computed at 10 mm"),
            std::string::npos)
      << narrow.output;
  const std::string json = railstab::test::read_text(dir / "c/narrow_narrow.json");
  EXPECT_NE(json.find("\"not_computed\": ["), std::string::npos) << json;
  EXPECT_NE(json.find("\"equivalent_conicity_at_reference_amplitude\": 0.05"),
            std::string::npos)
      << json;
  EXPECT_EQ(csv_rows(dir / "c/narrow_narrow_conicity.csv"), 2u);
  EXPECT_EQ(csv_rows(dir / "c/narrow_narrow_characteristic.csv"), 201u);
}
