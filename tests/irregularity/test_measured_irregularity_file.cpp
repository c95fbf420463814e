// Reading measured track-geometry records
// (irregularity/measured_irregularity_file.hpp): units from the header,
// missing channels, separators, and an error naming the file, the line and
// what was expected for every way a record can be wrong.
#include <gtest/gtest.h>

#include "support/test_files.hpp"

#include <railstab/irregularity/measured_irregularity_file.hpp>
#include <railstab/irregularity/track_irregularities.hpp>

#include <filesystem>
#include <fstream>
#include <numbers>

namespace fs = std::filesystem;

namespace railstab {
namespace {

std::string write_record(const fs::path& dir, const std::string& name, const std::string& text) {
  const fs::path p = dir / name;
  std::ofstream(p) << text;
  return p.string();
}

TEST(MeasuredIrregularityFile, ReadsUnitsFromTheHeaderAndLeavesMissingChannelsAtZero) {
  const fs::path dir = test::fresh_dir("irregularity", "measured_read");
  const std::string path = write_record(dir, "track.csv",
                                        "# recorded 2026-11-30, 0.25 m\n"
                                        "arc_length_m;level_mm;alignment_m\n"
                                        "0.0;1.5;0.001\n"
                                        "0.25;-2.0;0.002\n"
                                        "\n"
                                        "0.5;0.25;-0.0005\n"
                                        "0.75;0.0;0.0\n");
  const MeasuredIrregularities m = read_measured_irregularities(path);
  ASSERT_EQ(m.arc_length_m.size(), 4u);
  EXPECT_DOUBLE_EQ(m.arc_length_m[2], 0.5);
  const auto channel = [&](IrregularityChannel c) { return m.channels_m[size_t(c)]; };
  EXPECT_DOUBLE_EQ(channel(IrregularityChannel::level)[1], -2.0e-3);
  EXPECT_DOUBLE_EQ(channel(IrregularityChannel::alignment)[2], -0.0005);
  EXPECT_TRUE(m.in_file[size_t(IrregularityChannel::level)]);
  EXPECT_FALSE(m.in_file[size_t(IrregularityChannel::gauge)]);
  ASSERT_EQ(channel(IrregularityChannel::gauge).size(), 4u);
  EXPECT_EQ(channel(IrregularityChannel::gauge)[3], 0.0);
  fs::remove_all(dir);
}

// The spline goes through the rows (no fades): at a row the value is the
// row's, and a quadratic sampled finely is interpolated to its own accuracy.
TEST(MeasuredIrregularityFile, TheChannelIsTheSplineThroughTheRows) {
  IrregularitySpec spec;
  MeasuredIrregularities m;
  for (int i = 0; i <= 400; ++i) m.arc_length_m.push_back(-50.0 + 0.25 * i);
  for (double s : m.arc_length_m) {
    m.channels_m[0].push_back(1e-3 * std::sin(2 * std::numbers::pi * s / 20.0));
    for (int c = 1; c < 4; ++c) m.channels_m[size_t(c)].push_back(0.0);
  }
  spec.measured = m;
  spec.fade_in_m = spec.fade_out_m = 0.0;
  spec.amplitude_scale = 2.0;
  const TrackIrregularities irr(spec);
  EXPECT_DOUBLE_EQ(irr.first_m(), -50.0);
  EXPECT_DOUBLE_EQ(irr.last_m(), 50.0);
  EXPECT_NEAR(irr.at(IrregularityChannel::alignment, 2.5).f, 2e-3 * std::sin(2 * std::numbers::pi * 2.5 / 20.0), 1e-15);
  // Between rows: the spline of a 20 m wave at 0.25 m rows, error ~ (pi/40)^4 / 384 relative.
  EXPECT_NEAR(irr.at(IrregularityChannel::alignment, 3.1).f, 2e-3 * std::sin(2 * std::numbers::pi * 3.1 / 20.0), 1e-9);
  EXPECT_EQ(irr.at(IrregularityChannel::alignment, 50.5).f, 0.0);   // beyond the record
  EXPECT_EQ(irr.at(IrregularityChannel::alignment, -50.5).f, 0.0);
  EXPECT_EQ(irr.synthesised_variance_m2(IrregularityChannel::alignment), 0.0);
}

TEST(MeasuredIrregularityFile, EveryBadRecordNamesTheFileLineAndWhatWasExpected) {
  const fs::path dir = test::fresh_dir("irregularity", "measured_errors");
  const std::string rows = "0,0\n1,0\n2,0\n3,0\n";
  struct Case {
    std::string text, expected;
  };
  const std::vector<Case> cases = {
      {"arc_length_m,twist_mm\n" + rows, ":1: column 'twist_mm': expected arc_length_m"},
      {"arc_length_m,level\n" + rows, "column 'level': expected"},  // no unit
      {"0.0,1.0\n" + rows, ":1: column '0.0'"},                    // no header
      {"level_mm,gauge_mm\n" + rows, ":1: expected an arc_length_m (or s_m) column"},
      {"s_m\n0\n1\n2\n3\n", "expected at least one channel column"},
      {"s_m,level_mm,level_m\n" + rows, "'level_m' appears twice"},
      {"s_m,level_mm\n0,0\n1,0\n1,0\n3,0\n", ":4: arc length 1 m: expected arc lengths strictly increasing"},
      {"s_m,level_mm\n0,0\n1,x\n2,0\n3,0\n", ":3: column 2: expected a finite number, got 'x'"},
      {"s_m,level_mm\n0,0\n1,nan\n2,0\n3,0\n", ":3: column 2: expected a finite number"},
      {"s_m,level_mm\n0,0\n1\n2,0\n3,0\n", ":3: expected 2 values"},
      {"s_m,level_mm\n0,0\n1,0\n2,0\n", "expected at least 4 rows"},
      {"s_m,level_m\n0,0\n1,0.5\n2,0\n3,0\n", ":3: column 2: expected |value| <= 100 mm"},
      {"# only a comment\n", "expected a header line"},
  };
  for (size_t i = 0; i < cases.size(); ++i) {
    const std::string path = write_record(dir, "bad" + std::to_string(i) + ".csv", cases[i].text);
    try {
      read_measured_irregularities(path);
      ADD_FAILURE() << "case " << i << " was accepted";
    } catch (const IrregularityFileError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind(path, 0), 0u) << what;  // starts with the file
      EXPECT_NE(what.find(cases[i].expected), std::string::npos) << "case " << i << ": " << what;
    }
  }
  EXPECT_THROW(read_measured_irregularities((dir / "absent.csv").string()), IrregularityFileError);
  EXPECT_THROW(read_measured_irregularities(dir.string()), IrregularityFileError);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace railstab
