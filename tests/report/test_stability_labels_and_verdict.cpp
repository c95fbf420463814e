// What a client reads (issue 12): the JSON and the Markdown state the same
// verdict (the JSON used to say stable_in_range false where the Markdown said
// "stable over the whole range"); every plotted mode is labelled with its
// name in the legend of every plot, with one colour per mode across the
// plots, the critical mode marked, as PNG and SVG; the critical-speed JSON
// carries the mode shape with energy shares.
#include <gtest/gtest.h>

#include "io/format_checks.hpp"
#include <railstab/io/gnuplot.hpp>
#include <railstab/io/output_set.hpp>
#include <railstab/report/stability_report.hpp>
#include <railstab/setup/prepare_scene.hpp>
#include <railstab/stability/speed_analysis.hpp>

#include <array>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <algorithm>
#include <unistd.h>

using namespace railstab;
namespace fs = std::filesystem;

namespace {

std::string read(const fs::path& p) {
  std::ifstream in(p);
  return std::string((std::istreambuf_iterator<char>(in)), {});
}

struct Written {
  std::string json, markdown, script, tracks, svg_damping;
};

Written write_all(const Model& model, const CriticalSpeedResult& r, const std::string& tag,
                  bool plots) {
  const fs::path dir =
      fs::temp_directory_path() / ("railstab_labels_" + tag + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  {
    OutputSet outputs(dir);
    write_stability_results(model, r, outputs, "run", "dense", plots);
    outputs.commit();
  }
  Written w{read(dir / "run_critical_speed.json"), read(dir / "run_critical_speed.md"), "", "", ""};
  if (plots) {
    w.script = read(dir / "run_stability_plots.gp");
    w.tracks = read(dir / "run_tracks.dat");
    w.svg_damping = read(dir / "run_damping_vs_speed.svg");
    for (const char* f : {"run_root_locus.svg", "run_frequency_vs_speed.svg", "run_root_locus.png"})
      EXPECT_GT(fs::file_size(dir / f), 0u) << f;
  }
  fs::remove_all(dir);
  return w;
}

bool json_has(const std::string& json, const std::string& key, const std::string& literal) {
  return std::regex_search(json, std::regex("\"" + key + "\": *" + literal));
}

// The JSON's verdict_text, found in the Markdown; the boolean flags agree with
// the verdict.
void expect_agreement(const Written& w, const CriticalSpeedResult& r) {
  std::vector<std::string> strings;
  ASSERT_TRUE(test::is_valid_json(w.json, &strings));
  const std::string sentence = verdict_sentence(r);
  EXPECT_NE(std::find(strings.begin(), strings.end(), sentence), strings.end()) << sentence;
  EXPECT_NE(w.markdown.find(sentence), std::string::npos) << sentence;
  const StabilityVerdict v = stability_verdict(r);
  EXPECT_TRUE(json_has(w.json, "verdict", "\"" + verdict_key(v) + "\""));
  EXPECT_TRUE(json_has(w.json, "stable_in_range",
                       v == StabilityVerdict::stable_in_range ? "true" : "false"));
  const bool says_whole_range = w.markdown.find("stable over the whole range") != std::string::npos;
  EXPECT_EQ(says_whole_range, v == StabilityVerdict::stable_in_range);
}

// The thesis bogie's search over 20-50 m/s in 5 m/s steps (critical speed
// 36.90 m/s), shared by the plot tests.
struct BogieSearch {
  PreparedScene scene;
  CriticalSpeedResult result;
};

const BogieSearch& bogie_search() {
  static const BogieSearch b = [] {
    BogieSearch out{prepare_scene(std::string(RAILSTAB_CASES_DIR) + "/thesis_bogie_tangent.toml", {}), {}};
    CriticalSpeedOptions opt;
    opt.from_m_per_s = 20.0;
    opt.to_m_per_s = 50.0;
    opt.grid_step_m_per_s = 5.0;
    out.result = find_critical_speed(out.scene.model, out.scene.equilibrium.state,
                                     out.scene.speed_m_per_s, opt);
    return out;
  }();
  return b;
}

}  // namespace

TEST(StabilityVerdict, JsonAndMarkdownAgreeInEveryOutcome) {
  const PreparedScene s =
      prepare_scene(std::string(RAILSTAB_CASES_DIR) + "/textbook_wheelset.toml", {});
  SpeedStability stability(s.model, s.equilibrium.state, s.speed_m_per_s);
  const StabilityPoint p = stability.at(10.0);
  // Stable over the whole (one-point) range.
  CriticalSpeedResult stable;
  stable.grid = {p};
  stable.mode_tracks = track_modes(stable.grid);  // as find_critical_speed fills it
  stable.from_m_per_s = stable.to_m_per_s = 10.0;
  expect_agreement(write_all(s.model, stable, "stable", false), stable);
  // No crossing, but the steady state lost below the top: not "stable over
  // the whole range" (the contradiction of issue 12).
  CriticalSpeedResult lost = stable;
  lost.to_m_per_s = 50.0;
  lost.stable_in_range = false;
  lost.equilibrium_lost_at_m_per_s = 12.5;
  lost.equilibrium_error = "no steady state";
  lost.partial = true;
  lost.partial_reason = "the speed grid stopped";
  expect_agreement(write_all(s.model, lost, "lost", false), lost);
  EXPECT_EQ(stability_verdict(lost), StabilityVerdict::stable_below_equilibrium_loss);
  // A critical speed.
  CriticalSpeedOptions opt;
  opt.from_m_per_s = 5.0;
  opt.to_m_per_s = 80.0;
  opt.grid_step_m_per_s = 5.0;
  const CriticalSpeedResult crit =
      find_critical_speed(s.model, s.equilibrium.state, s.speed_m_per_s, opt);
  ASSERT_TRUE(crit.critical_speed_found);
  const Written w = write_all(s.model, crit, "crit", false);
  expect_agreement(w, crit);
  // The critical mode's shape with both energy shares in the JSON and the Markdown.
  EXPECT_TRUE(json_has(w.json, "normalised_to", "\"wheelset[^\"]* lateral\""));
  EXPECT_TRUE(json_has(w.json, "potential_energy_share", "[-0-9]"));
  EXPECT_TRUE(json_has(w.json, "modes_at_critical_speed", "\\[\\s*\\{"));
  EXPECT_NE(w.markdown.find("| body | coordinate | amplitude | phase [deg] | kinetic share | "
                            "potential share |"),
            std::string::npos);
}

TEST(StabilityPlots, EveryCurveNamedOneColourPerModeCriticalMarkedPngAndSvg) {
  if (find_gnuplot().empty()) GTEST_SKIP() << "gnuplot not installed";
  const BogieSearch& b = bogie_search();
  const PreparedScene& s = b.scene;
  const CriticalSpeedResult& r = b.result;
  ASSERT_TRUE(r.critical_speed_found);
  const Written w = write_all(s.model, r, "plots", true);
  // Track blocks name their mode; every plot clause has a title (no "notitle"
  // curve except the empty-plot placeholder) and the colour of block k is the
  // same in the three plots.
  const std::regex block("# track [0-9]+: '([^']*)'");
  std::vector<std::string> names;
  for (auto it = std::sregex_iterator(w.tracks.begin(), w.tracks.end(), block);
       it != std::sregex_iterator(); ++it)
    names.push_back((*it)[1]);
  ASSERT_GE(names.size(), 3u);
  const std::regex clause("index ([0-9]+) using [^\\n]* lc rgb '(#[0-9a-f]{6})'[^\\n]* title '([^']*)'");
  std::map<int, std::set<std::string>> colours;
  std::map<int, int> clauses;
  int critical_tags = 0;
  for (auto it = std::sregex_iterator(w.script.begin(), w.script.end(), clause);
       it != std::sregex_iterator(); ++it) {
    const int k = std::stoi((*it)[1]);
    ASSERT_LT(size_t(k), names.size());
    colours[k].insert((*it)[2]);
    ++clauses[k];
    const std::string title = (*it)[3];
    EXPECT_EQ(title.rfind(names[size_t(k)], 0), 0u) << title;
    if (title.find("[critical mode]") != std::string::npos) ++critical_tags;
  }
  // At most six named (the critical mode and the least damped others), each
  // in its own colour; the rest grey without a name.
  const size_t named = std::min<size_t>(names.size(), 6);
  EXPECT_EQ(clauses.size(), named);
  std::set<std::string> distinct;
  for (const auto& [k, c] : colours) {
    EXPECT_EQ(c.size(), 1u) << "mode " << names[size_t(k)] << " changes colour";
    EXPECT_EQ(clauses[k], 3) << names[size_t(k)];
    distinct.insert(*c.begin());
  }
  EXPECT_EQ(distinct.size(), colours.size()) << "two named modes share a colour";
  EXPECT_EQ(critical_tags, 3);  // the hunting mode, tagged in each plot
  const std::regex grey("index [0-9]+ using [^\\n]* lc rgb '#c8c8c8' lw 1 notitle");
  EXPECT_EQ(size_t(std::distance(std::sregex_iterator(w.script.begin(), w.script.end(), grey),
                                 std::sregex_iterator())),
            3 * (names.size() - named));
  // Units on every axis, the critical speed marked, the scene in the title.
  for (const char* label : {"set xlabel 'real part of the eigenvalue [1/s]'",
                            "set ylabel 'frequency [Hz]'", "set xlabel 'speed [m/s]'",
                            "set ylabel 'damping ratio [-]'", "V_crit = "})
    EXPECT_NE(w.script.find(label), std::string::npos) << label;
  EXPECT_NE(w.script.find("set title '" + s.model.name + ": "), std::string::npos);
  // The legend is drawn: every named mode's name is in the SVG's text.
  for (const auto& [k, c] : colours)
    EXPECT_NE(w.svg_damping.find(names[size_t(k)]), std::string::npos) << names[size_t(k)];
}

// The root locus a client reads (issue 24 item 5): speed marks along the
// named branches, numbered on the critical one, at the eigenvalues the tracks
// file holds for those speeds; a frame that holds every plotted point and the
// imaginary axis; the V_crit label left of the axis, inside the frame.
TEST(StabilityPlots, RootLocusSpeedMarksAndFrame) {
  if (find_gnuplot().empty()) GTEST_SKIP() << "gnuplot not installed";
  const BogieSearch& b = bogie_search();
  const PreparedScene& s = b.scene;
  const CriticalSpeedResult& r = b.result;
  ASSERT_TRUE(r.critical_speed_found);
  const Written w = write_all(s.model, r, "locus", true);
  // Tracks file: per block its name and (speed, re, f).
  std::map<std::string, std::vector<std::array<double, 3>>> points;
  {
    std::istringstream in(w.tracks);
    std::string line, current;
    while (std::getline(in, line)) {
      std::smatch m;
      if (std::regex_match(line, m, std::regex("# track [0-9]+: '([^']*)'"))) {
        current = m[1];
      } else if (!line.empty() && line[0] != '#' && !current.empty()) {
        std::istringstream cols(line);
        double v, re, f;
        cols >> v >> re >> f;
        points[current].push_back({v, re, f});
      }
    }
  }
  // The critical mode's name, from its legend tag.
  std::smatch tag;
  ASSERT_TRUE(std::regex_search(w.script, tag, std::regex("title '([^']*)  \\[critical mode\\]'")));
  const auto& critical = points.at(tag[1]);
  // Marks every 5 m/s (30 m/s range: 6 steps), numbered on the critical branch
  // at its eigenvalue at that speed (a grid speed: the tracks file's value).
  EXPECT_NE(w.script.find("title 'speed marks every 5 m/s'"), std::string::npos);
  int numbered = 0;
  for (const auto& p : critical) {
    std::ostringstream v;
    v << p[0];
    std::smatch m;
    if (!std::regex_search(w.script, m,
                           std::regex("set label [0-9]+ '" + v.str() + "' at ([-0-9.e+]+), ([-0-9.e+]+) left")))
      continue;
    ++numbered;
    EXPECT_NEAR(std::stod(m[1]), p[1], 1e-6 * (1.0 + std::abs(p[1]))) << v.str();
    EXPECT_NEAR(std::stod(m[2]), p[2], 1e-6 * (1.0 + p[2])) << v.str();
  }
  EXPECT_EQ(numbered, 7);  // 20, 25, ..., 50 m/s
  // The marks' data block: one row per named branch and round speed.
  const size_t begin = w.script.find("$speed_marks << EOD\n");
  ASSERT_NE(begin, std::string::npos);
  const size_t end = w.script.find("EOD\n", begin + 20);
  const std::string block = w.script.substr(begin + 19, end - begin - 19);
  EXPECT_GE(std::count(block.begin(), block.end(), '\n'), 7);
  // The frame holds every plotted point and the imaginary axis.
  std::smatch xr, yr;
  ASSERT_TRUE(std::regex_search(w.script, xr, std::regex("set xrange \\[([-0-9.e+]+):([-0-9.e+]+)\\]")));
  ASSERT_TRUE(std::regex_search(w.script, yr, std::regex("set yrange \\[0:([-0-9.e+]+)\\]")));
  const double x0 = std::stod(xr[1]), x1 = std::stod(xr[2]), y1 = std::stod(yr[1]);
  EXPECT_LT(x0, 0.0);
  EXPECT_GT(x1, 0.0);
  EXPECT_GE(x0, -20.0);
  for (const auto& [name, ps] : points)
    for (const auto& p : ps)
      if (p[1] >= -20.0 && p[2] <= 20.0) {
        EXPECT_GE(p[1], x0) << name;
        EXPECT_LE(p[1], x1) << name;
        EXPECT_LE(p[2], y1) << name;
      }
  EXPECT_NE(w.script.find(" m/s' at 0, "), std::string::npos);
  EXPECT_NE(w.script.find("lc 'red' right offset -1,1"), std::string::npos);
}

// A train has many more tracked modes than a legend can hold (the 4-car
// train: ~60 below 20 Hz): the critical mode and the least damped others
// are named, at most 6 per plot, in colour; the rest are drawn thin grey
// without a name and counted in one legend entry, so the plot keeps its width.
TEST(StabilityPlots, ATrainNamesTheCriticalAndTheLeastDampedModesOnly) {
  if (find_gnuplot().empty()) GTEST_SKIP() << "gnuplot not installed";
  const PreparedScene s =
      prepare_scene(std::string(RAILSTAB_CASES_DIR) + "/thesis_train_4.toml", {});
  CriticalSpeedOptions opt;
  opt.from_m_per_s = 105.0;
  opt.to_m_per_s = 115.0;
  opt.grid_step_m_per_s = 5.0;
  opt.tolerance_m_per_s = 0.5;
  const CriticalSpeedResult r = find_critical_speed(s.model, s.equilibrium.state, s.speed_m_per_s, opt);
  ASSERT_TRUE(r.critical_speed_found);
  const Written w = write_all(s.model, r, "train", true);
  const std::regex block("# track [0-9]+: '([^']*)'");
  const size_t tracks = size_t(std::distance(
      std::sregex_iterator(w.tracks.begin(), w.tracks.end(), block), std::sregex_iterator()));
  ASSERT_GT(tracks, 6u);
  const std::regex named("index [0-9]+ using [^\\n]* title '([^']*)'");
  const std::regex unnamed("index [0-9]+ using [^\\n]* lc rgb '#c8c8c8' lw 1 notitle");
  const auto count = [&](const std::regex& re) {
    return size_t(std::distance(std::sregex_iterator(w.script.begin(), w.script.end(), re),
                                std::sregex_iterator()));
  };
  EXPECT_EQ(count(named), 3 * 6u);  // three plots
  EXPECT_EQ(count(unnamed), 3 * (tracks - 6));
  EXPECT_NE(w.script.find("title '" + std::to_string(tracks - 6) + " better-damped modes, unnamed'"),
            std::string::npos);
  // The critical mode is among the named, in each plot.
  size_t critical = 0;
  for (size_t at = w.script.find("[critical mode]"); at != std::string::npos;
       at = w.script.find("[critical mode]", at + 1))
    ++critical;
  EXPECT_EQ(critical, 3u);
  // The root locus says the sparse solver computed only its box.
  EXPECT_NE(w.script.find("sparse solver: Re near 0 only"),
            std::string::npos);
  // Lateral-plane modes are named before vertical and longitudinal ones;
  // within a plane every named mode's minimum damping ratio over the speeds
  // is at most every unnamed one's (the critical mode is named regardless).
  std::map<std::string, double> min_damping;
  std::map<std::string, bool> lateral;
  std::istringstream in(w.tracks);
  std::string line, current;
  while (std::getline(in, line)) {
    std::smatch m;
    if (std::regex_match(line, m, std::regex("# track [0-9]+: '([^']*)'"))) {
      current = m[1];
      min_damping[current] = 1e9;
    } else if (line.rfind("# plane: ", 0) == 0 && !current.empty()) {
      lateral[current] = line == "# plane: lateral";
    } else if (!line.empty() && line[0] != '#' && !current.empty()) {
      std::istringstream cols(line);
      double v, re, f, zeta;
      cols >> v >> re >> f >> zeta;
      min_damping[current] = std::min(min_damping[current], zeta);
    }
  }
  std::set<std::string> named_names;
  for (auto it = std::sregex_iterator(w.script.begin(), w.script.end(), named);
       it != std::sregex_iterator(); ++it) {
    std::string n = (*it)[1];
    const size_t tag = n.find("  [critical mode]");
    if (tag != std::string::npos) n = n.substr(0, tag);
    named_names.insert(n);
  }
  std::smatch critical_tag;
  ASSERT_TRUE(std::regex_search(w.script, critical_tag, std::regex("title '([^']*)  \\[critical mode\\]'")));
  const std::string critical_name = critical_tag[1];
  bool unnamed_lateral = false, named_other = false;
  for (const auto& [name, zeta] : min_damping) {
    if (named_names.count(name)) named_other |= !lateral[name];
    else unnamed_lateral |= lateral[name];
  }
  EXPECT_FALSE(unnamed_lateral && named_other) << "a vertical mode named before a lateral one";
  for (const bool plane : {true, false}) {
    double worst_named = -1e9, best_unnamed = 1e9;
    for (const auto& [name, zeta] : min_damping) {
      if (lateral[name] != plane || name == critical_name) continue;
      if (named_names.count(name))
        worst_named = std::max(worst_named, zeta);
      else
        best_unnamed = std::min(best_unnamed, zeta);
    }
    EXPECT_LE(worst_named, best_unnamed) << (plane ? "lateral" : "other");
  }
}
