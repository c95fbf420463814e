// The stability report's files as a set (issue 10): a speed grid of one
// point (a sweep whose steady state is lost after its first speed) used to
// make gnuplot fail on autoscaling ("x range is invalid") and lose every
// output; with explicit plot ranges the whole set is written, plots
// included, and a hostile scene name still gives valid JSON and CSV.
#include <gtest/gtest.h>

#include <railstab/setup/prepare_scene.hpp>
#include "io/format_checks.hpp"
#include <railstab/io/gnuplot.hpp>
#include <railstab/io/output_set.hpp>
#include <railstab/report/stability_report.hpp>
#include <railstab/stability/speed_analysis.hpp>

#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace railstab;
namespace fs = std::filesystem;

TEST(StabilityReportOutputs, OneSpeedGridStillWritesEveryFileAndPlot) {
  if (find_gnuplot().empty()) GTEST_SKIP() << "gnuplot not installed";
  PreparedScene s = prepare_scene(std::string(RAILSTAB_CASES_DIR) + "/textbook_wheelset.toml", {});
  s.model.name = "one|point \"grid\",\t../x";
  SpeedStability stability(s.model, s.equilibrium.state, s.speed_m_per_s);
  CriticalSpeedResult r;
  r.grid.push_back(stability.at(30.0));
  r.mode_tracks = track_modes(r.grid);  // as find_critical_speed fills it
  r.from_m_per_s = r.to_m_per_s = 30.0;
  r.evaluations = 1;
  const fs::path dir = fs::temp_directory_path() /
                       ("railstab_report_onepoint_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const std::string stem = "one_point";
  std::vector<std::string> written;
  {
    OutputSet outputs(dir);
    write_stability_results(s.model, r, outputs, stem, "dense", true);
    written = outputs.commit();
  }
  EXPECT_EQ(written.size(), stability_file_names(stem).size());
  for (const std::string& name : stability_file_names(stem)) {
    ASSERT_TRUE(fs::exists(dir / name)) << name;
    EXPECT_GT(fs::file_size(dir / name), 0u) << name;
  }
  std::ifstream json(dir / (stem + "_critical_speed.json"));
  const std::string text((std::istreambuf_iterator<char>(json)), {});
  std::vector<std::string> strings;
  EXPECT_TRUE(test::is_valid_json(text, &strings));
  EXPECT_NE(std::find(strings.begin(), strings.end(), s.model.name), strings.end());
  std::ifstream csv_in(dir / (stem + "_eigenvalues.csv"));
  const std::string csv((std::istreambuf_iterator<char>(csv_in)), {});
  const auto rows = test::parse_csv(csv);
  ASSERT_TRUE(rows.has_value());
  for (const auto& row : *rows) EXPECT_EQ(row.size(), 9u);
  fs::remove_all(dir);
}
