// Outputs under hostile names (issue 10): JSON per RFC 8259 and CSV per
// RFC 4180 parse back to the same names; non-finite numbers are refused
// naming the field; file names made from user text stay inside the output
// folder; an output set is all-or-nothing; gnuplot runs without a shell and
// its plots are checked; a scene path that is not a regular file is refused.
#include <gtest/gtest.h>

#include <railstab/io/csv.hpp>
#include <railstab/io/file_names.hpp>
#include <railstab/io/gnuplot.hpp>
#include <railstab/io/json_writer.hpp>
#include <railstab/io/output_files.hpp>
#include <railstab/io/output_set.hpp>
#include <railstab/io/regular_file.hpp>
#include <railstab/scene_reading/load_scene.hpp>
#include <railstab/model/model.hpp>
#include <railstab/setup/build_model.hpp>
#include <railstab/integrate/integrator.hpp>
#include "io/format_checks.hpp"
#include "model/scene_builders.hpp"

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <future>
#include <limits>
#include <map>
#include <sstream>
#include <sys/stat.h>
#include <fcntl.h>
#include <unistd.h>
#include "support/test_files.hpp"

using namespace railstab;
namespace fs = std::filesystem;

namespace {

// Names a hostile scene may hold: separators, quotes, escapes, controls,
// a UTF-8 letter and a byte that is not UTF-8.
const std::vector<std::string> kHostileNames = {
    "a,b",          "quote\"d",      "back\\slash",    "tab\there", "new\nline", "cr\rx",
    "ctl\x01\x1f",  "del\x7f",       "\xc3\xbc" "ber",  "bad\xff",   "'; system('x'); '",
    "..", "../evil", std::string("nul\0byte", 8)};

fs::path fresh_dir(const std::string& name) { return railstab::test::fresh_dir("hostile", name); }

std::map<std::string, std::string> folder_contents(const fs::path& dir) {
  std::map<std::string, std::string> contents;
  if (!fs::exists(dir)) return contents;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    std::string text;
    if (entry.is_regular_file()) {
      std::ifstream in(entry.path(), std::ios::binary);
      text.assign(std::istreambuf_iterator<char>(in), {});
    }
    contents[fs::relative(entry.path(), dir).string()] = text;
  }
  return contents;
}

using railstab::test::read_text;

}  // namespace

// --- JSON -----------------------------------------------------------------------

TEST(HostileJson, EveryNameGivesValidJsonThatDecodesToIt) {
  for (const std::string& name : kHostileNames) {
    std::ostringstream out;
    JsonWriter j(out);
    j.begin_object().field("name", name).key("bodies").begin_array().value(name).end_array();
    j.field(name, 1.5).end_object();
    std::vector<std::string> strings;
    ASSERT_TRUE(test::is_valid_json(out.str(), &strings)) << "name " << name << ":\n" << out.str();
    // Valid UTF-8 comes back unchanged; the one invalid byte as U+FFFD.
    std::string expected = name;
    if (name == "bad\xff") expected = "bad\xef\xbf\xbd";
    ASSERT_EQ(strings.size(), 5u);  // key, value, key, array element, key
    EXPECT_EQ(strings[1], expected);
    EXPECT_EQ(strings[2], "bodies");
    EXPECT_EQ(strings[3], expected);
    EXPECT_EQ(strings[4], expected);
  }
}

TEST(HostileJson, ControlCharactersAreEscapedAsU00XX) {
  std::ostringstream out;
  JsonWriter(out).value(std::string("\x01\x1f\t"));
  EXPECT_EQ(out.str(), "\"\\u0001\\u001f\\t\"");
}

TEST(HostileJson, NonFiniteNumberIsRefusedNamingTheKey) {
  for (double bad : {std::nan(""), std::numeric_limits<double>::infinity(),
                     -std::numeric_limits<double>::infinity()}) {
    std::ostringstream out;
    JsonWriter j(out);
    j.begin_object();
    try {
      j.field("critical_speed_m_per_s", bad);
      FAIL() << "non-finite value written: " << out.str();
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("critical_speed_m_per_s"), std::string::npos) << e.what();
    }
    EXPECT_EQ(out.str().find("nan"), std::string::npos);
    EXPECT_EQ(out.str().find("inf"), std::string::npos);
  }
}

// --- CSV ------------------------------------------------------------------------

TEST(HostileCsv, FieldsRoundTripThroughAnRfc4180Reader) {
  std::string line;
  for (const std::string& name : kHostileNames) line += (line.empty() ? "" : ",") + csv_field(name);
  line += "\n1,2\n";
  const auto rows = test::parse_csv(line);
  ASSERT_TRUE(rows.has_value());
  ASSERT_EQ(rows->size(), 2u);
  ASSERT_EQ((*rows)[0].size(), kHostileNames.size());
  for (size_t i = 0; i < kHostileNames.size(); ++i) EXPECT_EQ((*rows)[0][i], kHostileNames[i]);
  EXPECT_EQ(csv_physical_lines(line), 4);  // one name holds a line feed; plus the data row
}

TEST(HostileCsv, NonFiniteNumberIsRefusedNamingTheField) {
  try {
    csv_number(std::nan(""), "wheelset1.y_m at t = 0.5 s");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("wheelset1.y_m at t = 0.5 s"), std::string::npos);
  }
  EXPECT_EQ(csv_number(0.25, "x"), "0.25");
}

// A model whose body names hold a comma, quotes, a tab and a control
// character: the trajectory CSV keeps one column per value and its header
// names read back unchanged (before: the raw comma split a name in two).
TEST(HostileCsv, TrajectoryCsvWithHostileBodyNamesHasConsistentColumns) {
  SceneSpec spec = test::two_body_oscillator(test::straight_track(), 10.0);
  const std::string a = "a,\"1\"\tx", b = "b\x01;\nz";
  spec.bodies[0].name = a;
  spec.bodies[1].name = b;
  for (ElementSpec& element : spec.elements) {
    ElementEnds& e = ends_of(element);
    if (e.body1_name == "a") e.body1_name = a;
    if (e.body2_name == "a") e.body2_name = a;
    if (e.body1_name == "b") e.body1_name = b;
    if (e.body2_name == "b") e.body2_name = b;
  }
  const Model model = build_model(spec);
  Trajectory traj;
  traj.times_s = {0.0, 0.1};
  traj.states = {Eigen::VectorXd::Zero(model.state_size()),
                 Eigen::VectorXd::Constant(model.state_size(), 1e-3)};
  for (int kind = 0; kind < 2; ++kind) {
    std::ostringstream out;
    if (kind == 0) write_trajectory_csv(out, model, spec.speed_m_per_s, traj);
    else write_absolute_roll_csv(out, model, spec.speed_m_per_s, traj);
    const auto rows = test::parse_csv(out.str());
    ASSERT_TRUE(rows.has_value()) << out.str();
    ASSERT_EQ(rows->size(), 3u);
    const size_t columns = kind == 0 ? 1 + 6 * 2 : 1 + 2;
    for (const auto& row : *rows) EXPECT_EQ(row.size(), columns) << out.str();
    EXPECT_EQ((*rows)[0][1], a + (kind == 0 ? ".x_m" : ".absolute_roll_rad"));
  }
  // A non-finite state is refused naming body and coordinate.
  traj.states[1](0) = std::nan("");
  std::ostringstream out;
  try {
    write_trajectory_csv(out, model, spec.speed_m_per_s, traj);
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("at t = 0.1 s"), std::string::npos) << e.what();
  }
}

// --- file names -----------------------------------------------------------------

TEST(HostileFileNames, StemsAreSingleSafeComponentsOfBoundedLength) {
  for (const std::string& name : kHostileNames) {
    const std::string stem = file_stem(name);
    EXPECT_TRUE(is_safe_file_name(stem)) << stem;
    EXPECT_EQ(stem.find('/'), std::string::npos);
    EXPECT_NE(stem, "..");
    EXPECT_NE(stem.front(), '.');
  }
  EXPECT_EQ(file_stem("../evil"), "_._evil");
  // The outputs' stem: the scene file's name without folder and extension.
  EXPECT_EQ(scene_file_stem("cases/coach_k6.toml"), "coach_k6");
  EXPECT_EQ(scene_file_stem("../up/two.dots.toml"), "two.dots");
  EXPECT_EQ(scene_file_stem("no_extension"), "no_extension");
  EXPECT_EQ(scene_file_stem("dir/.toml"), "_toml");
  EXPECT_EQ(scene_file_stem("dir/"), "unnamed");
  EXPECT_EQ(scene_file_stem("a b;rm -rf.toml"), "a_b_rm_-rf");
  for (const std::string& name : kHostileNames) EXPECT_TRUE(is_safe_file_name(scene_file_stem(name))) << name;
  EXPECT_EQ(file_stem("/etc/passwd"), "_etc_passwd");
  EXPECT_EQ(file_stem(""), "unnamed");
  EXPECT_EQ(file_stem("thesis_bogie-tangent.v2"), "thesis_bogie-tangent.v2");  // unchanged
  EXPECT_EQ(file_stem(std::string(4000, 'x')).size(), kMaxFileStemLength);
  EXPECT_FALSE(is_safe_file_name("../x"));
  EXPECT_FALSE(is_safe_file_name(".hidden"));
  EXPECT_EQ(speed_file_tag(36.9), "36.9mps");
  EXPECT_EQ(speed_file_tag(30.0), "30mps");
  EXPECT_EQ(speed_file_tag(36.904), "36.9mps");
  EXPECT_EQ(speed_file_tag(12.346), "12.35mps");
  EXPECT_EQ(speed_file_tag(0.05), "0.05mps");
  EXPECT_EQ(speed_file_tag(7.0999), "7.1mps");
  EXPECT_THROW(speed_file_tag(std::nan("")), std::invalid_argument);
  EXPECT_THROW(speed_file_tag(1e300), std::invalid_argument);
}

// --- all-or-nothing output sets --------------------------------------------------

TEST(OutputSetTest, CommitReplacesTheOldSetAndRemovesItsOtherNames) {
  const fs::path dir = fresh_dir("commit");
  std::ofstream(dir / "run_a.csv") << "old a";
  std::ofstream(dir / "run_b.png") << "old plot";
  std::ofstream(dir / "other.txt") << "not ours";
  {
    OutputSet set(dir);
    set.replaces("run_b.png");  // this run makes no plot: the old one must go
    set.write("run_a.csv", [](std::ostream& o) { o << "new a"; });
    set.write("run_c.json", [](std::ostream& o) { o << "{}"; });
    // Nothing visible before commit.
    EXPECT_EQ(read_text(dir / "run_a.csv"), "old a");
    EXPECT_FALSE(fs::exists(dir / "run_c.json"));
    const auto written = set.commit();
    EXPECT_EQ(written.size(), 2u);
  }
  const auto contents = folder_contents(dir);
  EXPECT_EQ(contents.size(), 3u);  // no staging folder left
  EXPECT_EQ(contents.at("run_a.csv"), "new a");
  EXPECT_EQ(contents.at("run_c.json"), "{}");
  EXPECT_EQ(contents.at("other.txt"), "not ours");
  fs::remove_all(dir);
}

TEST(OutputSetTest, AFailureHalfWayLeavesTheFolderAsItWas) {
  const fs::path dir = fresh_dir("failure");
  std::ofstream(dir / "run_a.csv") << "old a";
  const auto before = folder_contents(dir);
  try {
    OutputSet set(dir);
    set.write("run_a.csv", [](std::ostream& o) { o << "new a"; });
    set.write("run_b.json", [](std::ostream& o) {
      o << "{";
      throw std::runtime_error("non-finite value half-way");
    });
    set.commit();
    FAIL();
  } catch (const std::runtime_error&) {
  }
  EXPECT_EQ(folder_contents(dir), before);
  // A folder of an output's name in the way: refused before anything moves.
  fs::create_directories(dir / "run_c.png");
  const auto before2 = folder_contents(dir);
  {
    OutputSet set(dir);
    set.write("run_a.csv", [](std::ostream& o) { o << "new a"; });
    set.write("run_c.png", [](std::ostream& o) { o << "png"; });
    EXPECT_THROW(set.commit(), std::runtime_error);
  }
  EXPECT_EQ(folder_contents(dir), before2);
  // An output folder this run created is removed again on failure.
  const fs::path created = dir / "new" / "deeper";
  {
    OutputSet set(created);
    set.write("x.csv", [](std::ostream& o) { o << "x"; });
  }
  EXPECT_FALSE(fs::exists(dir / "new"));
  fs::remove_all(dir);
}

TEST(OutputSetTest, RefusesNamesThatLeaveTheFolder) {
  const fs::path dir = fresh_dir("names");
  OutputSet set(dir);
  for (const char* bad : {"../evil.json", "/tmp/x", "a/b", "..", ".hidden", ""})
    EXPECT_THROW(set.add(bad), std::invalid_argument) << bad;
  fs::remove_all(dir);
}

// --- gnuplot ---------------------------------------------------------------------

TEST(Gnuplot, TextInScriptsCannotBreakOutOfItsString) {
  EXPECT_EQ(gnuplot_text("it's"), "'it''s'");
  EXPECT_EQ(gnuplot_text("a\nb"), "'a b'");
  EXPECT_THROW(gnuplot_path("a\nb.csv"), GnuplotError);
}

// A title holding gnuplot commands and a shell command: with gnuplot on
// PATH, the plot is made and nothing is executed.
TEST(Gnuplot, RunsWithoutAShellAndChecksThePlots) {
  if (find_gnuplot().empty()) GTEST_SKIP() << "gnuplot not installed";
  const fs::path dir = fresh_dir("gnuplot");
  const std::string hostile = "x'; system(\"touch PWNED_GP\"); print '`touch PWNED_BQ`";
  const std::string script = "it's $(touch PWNED_SH).gp";  // a name a shell would run
  {
    std::ofstream gp(dir / script);
    gp << "set terminal pngcairo\nset output " << gnuplot_text("plot.png") << "\n"
       << "set title " << gnuplot_text(hostile) << "\nplot sin(x) title " << gnuplot_text(hostile)
       << "\n";
  }
  EXPECT_NO_THROW(run_gnuplot(script, dir, {"plot.png"}));
  for (const char* marker : {"PWNED_GP", "PWNED_BQ", "PWNED_SH"})
    EXPECT_FALSE(fs::exists(dir / marker)) << marker;
  EXPECT_GT(fs::file_size(dir / "plot.png"), 0u);
  // A promised plot that is not made, and a failing script, are errors.
  EXPECT_THROW(run_gnuplot(script, dir, {"plot.png", "missing.png"}), GnuplotError);
  std::ofstream(dir / "bad.gp") << "this is not gnuplot\n";
  EXPECT_THROW(run_gnuplot("bad.gp", dir, {}), GnuplotError);
  fs::remove_all(dir);
}

TEST(Gnuplot, MissingFromPathIsAClearError) {
  const char* old = std::getenv("PATH");
  const std::string saved = old ? old : "";
  const fs::path empty = fresh_dir("nopath");
  ::setenv("PATH", empty.c_str(), 1);
  EXPECT_TRUE(find_gnuplot().empty());
  try {
    run_gnuplot("x.gp", empty, {});
    ADD_FAILURE() << "no error without gnuplot";
  } catch (const GnuplotError& e) {
    EXPECT_NE(std::string(e.what()).find("not on PATH"), std::string::npos) << e.what();
  }
  EXPECT_THROW(require_gnuplot(), GnuplotError);
  ::setenv("PATH", saved.c_str(), 1);
  fs::remove_all(empty);
}

// --- scene files that are not regular files --------------------------------------

TEST(SceneFileKind, PipesFoldersAndDevicesAreRefusedBeforeReading) {
  const fs::path dir = fresh_dir("kinds");
  const fs::path fifo = dir / "scene.toml";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // Bounded wait: before the fix, opening a FIFO without a writer blocked.
  auto pending = std::async(std::launch::async, [&] {
    try {
      load_scene_file(fifo.string());
      return std::string("accepted");
    } catch (const SceneError& e) {
      return std::string(e.what());
    }
  });
  if (pending.wait_for(std::chrono::seconds(10)) != std::future_status::ready) {
    const int w = ::open(fifo.c_str(), O_WRONLY | O_NONBLOCK);  // unblock the reader
    if (w >= 0) ::close(w);
    pending.wait();
    FAIL() << "reading a named pipe hung";
  }
  const std::string fifo_error = pending.get();
  EXPECT_NE(fifo_error.find("named pipe (not a regular file)"), std::string::npos) << fifo_error;
  EXPECT_NE(fifo_error.find(fifo.string()), std::string::npos) << fifo_error;
  for (const std::string& path : {dir.string(), std::string("/dev/null")}) {
    try {
      load_scene_file(path);
      ADD_FAILURE() << path << " accepted";
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find("not a regular file"), std::string::npos) << e.what();
    }
  }
  std::ofstream(dir / "big.toml") << std::string(2000, '#');
  EXPECT_THROW(read_regular_file((dir / "big.toml").string(), 1000), std::runtime_error);
  fs::remove_all(dir);
}
