// `railstab bifurcation` on the textbook wheelset (linear contact, 4 free
// states: 0.1-0.3 s CPU for a branch to 3 mm): the branch from the Hopf
// point starts at the linear critical speed (0.01 m/s) with the period
// 2 pi / Im(lambda) of the linear model there (1e-6 relative); the JSON's
// numbers are the library's (same options, 12 printed digits); its
// hopf_kind is the critical-speed command's; every file exists and parses,
// no output holds a NaN; bad flags give a message naming the flag and write
// nothing.
#include <gtest/gtest.h>

#include "cli/run_cli.hpp"
#include "io/format_checks.hpp"
#include "support/test_files.hpp"

#include <railstab/nonlinear/bifurcation_analysis.hpp>
#include <railstab/setup/prepare_scene.hpp>
#include <railstab/stability/speed_analysis.hpp>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <regex>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace railstab;

namespace {

const std::string kScene = test::case_path("textbook_wheelset");
const std::string kStem = "textbook_wheelset";

// Every value of "key": in order of appearance (the text up to the next
// comma or newline).
std::vector<std::string> json_values(const std::string& json, const std::string& key) {
  const std::regex re("\"" + key + "\": ([^,\\n]*)");
  std::vector<std::string> values;
  for (auto it = std::sregex_iterator(json.begin(), json.end(), re); it != std::sregex_iterator(); ++it)
    values.push_back((*it)[1].str());
  return values;
}

std::string json_value(const std::string& json, const std::string& key) {
  const std::vector<std::string> v = json_values(json, key);
  return v.empty() ? "<missing>" : v.front();
}

// The command's flags, and the library's options that they stand for.
const std::vector<std::string> kFlags = {"--from", "50", "--to", "100", "--max-amplitude", "0.003"};

BifurcationOptions library_options() {
  BifurcationOptions o;
  o.linear.from_m_per_s = 50.0;
  o.linear.to_m_per_s = 100.0;
  o.linear.grid_step_m_per_s = 2.5;
  o.max_amplitude_m = 0.003;
  return o;
}

}  // namespace

TEST(CliBifurcation, OutputsAreTheLibrarysAndTheBranchStartsAtTheHopfPoint) {
  const fs::path dir = test::fresh_dir("cli_bifurcation", "wheelset");
  std::vector<std::string> args = {"bifurcation", kScene};
  args.insert(args.end(), kFlags.begin(), kFlags.end());
  args.insert(args.end(), {"--out", "out"});
  const test::CliRun run = test::run_railstab(args, dir);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  // Progress: one line per orbit on stderr (here merged with stdout).
  EXPECT_NE(run.output.find("hopf branch, orbit 1: "), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("largest multiplier |mu| "), std::string::npos) << run.output;

  // Every file exists, is not empty and parses; no NaN anywhere.
  const fs::path out = dir / "out";
  for (const std::string suffix :
       {"_bifurcation.json", "_bifurcation_branches.csv", "_bifurcation.md",
        "_bifurcation_diagram.dat", "_bifurcation_diagram.gp", "_bifurcation_diagram.png",
        "_bifurcation_diagram.svg"}) {
    const fs::path f = out / (kStem + suffix);
    ASSERT_TRUE(fs::exists(f)) << f;
    EXPECT_GT(fs::file_size(f), 100u) << f;
    if (suffix.ends_with(".png")) continue;
    EXPECT_FALSE(std::regex_search(test::read_text(f), std::regex("\\bnan\\b", std::regex::icase)))
        << f;
  }
  const std::string json = test::read_text(out / (kStem + "_bifurcation.json"));
  ASSERT_TRUE(test::is_valid_json(json));
  const auto csv = test::parse_csv(test::read_text(out / (kStem + "_bifurcation_branches.csv")));
  ASSERT_TRUE(csv.has_value());
  const std::string svg = test::read_text(out / (kStem + "_bifurcation_diagram.svg"));
  EXPECT_NE(svg.find("</svg>"), std::string::npos);

  // The library with the same options.
  const PreparedScene s = prepare_scene(kScene, {});
  const BifurcationResult r = analyse_bifurcation(s.model, s.equilibrium.state, s.speed_m_per_s,
                                                  library_options());
  ASSERT_TRUE(r.linear.critical_speed_found);
  ASSERT_EQ(r.branches.size(), 1u);
  const OrbitBranch& b = r.branches[0].branch;
  ASSERT_TRUE(r.branches[0].error.empty()) << r.branches[0].error;
  ASSERT_GE(b.orbits.size(), 3u);
  auto number = [](const std::string& text) { return std::stod(text); };
  const double Vc = r.linear.critical_speed_m_per_s;
  EXPECT_NEAR(number(json_value(json, "linear_critical_speed_m_per_s")), Vc, 1e-10 * Vc);
  const std::vector<std::string> speeds = json_values(json, "speed_m_per_s");
  const std::vector<std::string> periods = json_values(json, "period_s");
  const std::vector<std::string> amplitudes = json_values(json, "lateral_amplitude_m");
  const std::vector<std::string> stable = json_values(json, "stable");
  // The conditions' cant deficiency carries one speed_m_per_s (V_c) first.
  ASSERT_EQ(speeds.size(), b.orbits.size() + 1 + b.bifurcations.size());
  ASSERT_EQ(periods.size(), b.orbits.size());
  ASSERT_EQ(csv->size(), b.orbits.size() + 1);  // header + one row per orbit
  for (size_t k = 0; k < b.orbits.size(); ++k) {
    const PeriodicOrbit& o = b.orbits[k];
    EXPECT_NEAR(number(speeds[k + 1]), o.speed_m_per_s, 1e-10 * o.speed_m_per_s) << "orbit " << k + 1;
    EXPECT_NEAR(number(periods[k]), o.period_s, 1e-10 * o.period_s) << "orbit " << k + 1;
    const double a = o.amplitude(r.wheelsets[0].lateral_state);
    EXPECT_NEAR(number(amplitudes[k]), a, 1e-10 * a) << "orbit " << k + 1;
    EXPECT_EQ(stable[k], o.stable ? "true" : "false");
    EXPECT_NEAR(number((*csv)[k + 1][3]), o.speed_m_per_s, 1e-9 * o.speed_m_per_s);
  }
  EXPECT_EQ(json_value(json, "stop_reason"), "\"" + b.stop_reason + "\"");
  EXPECT_EQ(json_value(json, "nonlinear_critical_speed_bound"),
            "\"" + stable_bound_name(r.nonlinear.bound) + "\"");

  // The branch starts at the Hopf point: its first orbits (excursions 0.05
  // and 0.1 mm, V(a) = V0 + k a^2, T(a) = T0 + O(a^2)) extrapolate to
  // V0 = V_c within the search's 0.01 m/s and to the period of the linear
  // model's critical pair at V0 within 1e-6.
  const PeriodicOrbit &o1 = b.orbits[0], &o2 = b.orbits[1];
  EXPECT_NEAR(o1.start(r.coords.amplitude_state) - s.equilibrium.state(r.reduced_states[size_t(r.coords.amplitude_state)]),
              5e-5, 1e-12);
  const double V0 = (4.0 * o1.speed_m_per_s - o2.speed_m_per_s) / 3.0;
  const double T0 = (4.0 * o1.period_s - o2.period_s) / 3.0;
  EXPECT_NEAR(V0, Vc, 0.01);
  StabilityOptions so;
  SpeedStability linear(s.model, s.equilibrium.state, s.speed_m_per_s, so);
  const StabilityPoint p = linear.at(V0);
  ASSERT_GE(p.least_stable, 0);
  const double w = std::abs(p.modes[size_t(p.least_stable)].eigenvalue.imag());
  EXPECT_NEAR(T0, 2.0 * std::numbers::pi / w, 1e-6 * T0);
  EXPECT_LT(std::abs(p.modes[size_t(p.least_stable)].eigenvalue.real()), 1e-3);

  // The kind is the critical-speed command's.
  std::vector<std::string> cs = {"critical-speed", kScene, "--from", "50", "--to", "100",
                                 "--no-plots", "--out", "cs"};
  const test::CliRun crit = test::run_railstab(cs, dir);
  ASSERT_EQ(crit.exit_code, 0) << crit.output;
  const std::string cs_json = test::read_text(dir / "cs" / (kStem + "_critical_speed.json"));
  ASSERT_NE(json_value(cs_json, "hopf_kind"), "null");
  EXPECT_EQ(json_value(json, "hopf_kind"), json_value(cs_json, "hopf_kind"));
  EXPECT_EQ(json_value(json, "hopf_kind"), "\"" + r.hopf_kind + "\"");
  EXPECT_NEAR(number(json_value(cs_json, "critical_speed_m_per_s")), Vc, 1e-10 * Vc);

  // Subcritical here, no stable orbit up to 3 mm: "not found", with why.
  ASSERT_FALSE(r.nonlinear.found);
  EXPECT_EQ(json_value(json, "nonlinear_critical_speed_m_per_s"), "null");
  EXPECT_EQ(json_value(json, "nonlinear_to_linear_critical_speed_ratio"), "null");
  EXPECT_NE(json_value(json, "nonlinear_critical_speed_note").find("not found"), std::string::npos);
  const std::string md = test::read_text(out / (kStem + "_bifurcation.md"));
  EXPECT_NE(md.find("| nonlinear critical speed | **not found**"), std::string::npos) << md;
  EXPECT_NE(md.find("- track: "), std::string::npos);  // the run conditions
  EXPECT_NE(md.find("](" + kStem + "_bifurcation_diagram.png)"), std::string::npos);
}

TEST(CliBifurcation, BadFlagsNameTheFlagAndWriteNothing) {
  const fs::path dir = test::fresh_dir("cli_bifurcation", "bad_flags");
  struct Case {
    std::vector<std::string> flags;
    std::string message;
  };
  const std::vector<Case> cases = {
      {{"--from", "100", "--to", "50"}, "--from 100 m/s must be below --to 50 m/s"},
      {{"--max-amplitude", "-0.001"}, "--max-amplitude: expected a finite number in (0, 0.05] m"},
      {{"--max-amplitude", "0"}, "--max-amplitude: expected a finite number in (0, 0.05] m"},
      {{"--max-amplitude", "abc"}, "--max-amplitude"},
      {{"--from", "fast"}, "--from"},
      {{"--to", "nan"}, "--to"},
      {{"--cycle-speed", "inf"}, "--cycle-speed"},
      {{"--cycle-speed", "120", "--to", "100"}, "--cycle-speed 120 m/s must lie between --from"},
      {{"--max-orbits", "1"}, "--max-orbits"},
      {{"--cycle-direction", "sideways"}, "--cycle-direction"},
      {{"--no-hopf-branch"}, "--no-hopf-branch leaves no branch to compute: give --cycle-speed V"},
  };
  for (const Case& c : cases) {
    std::vector<std::string> args = {"bifurcation", kScene};
    args.insert(args.end(), c.flags.begin(), c.flags.end());
    args.insert(args.end(), {"--no-plots", "--out", "out"});
    const test::CliRun run = test::run_railstab(args, dir);
    EXPECT_NE(run.exit_code, 0) << c.flags[0] << ": " << run.output;
    EXPECT_NE(run.output.find(c.message), std::string::npos) << run.output;
    EXPECT_FALSE(fs::exists(dir / "out")) << c.flags[0];
  }
}

// --no-hopf-branch computes the --cycle-speed branch alone: the JSON holds
// one branch, of time-domain origin (on the textbook wheelset above its
// critical speed the run grows to the flange clearance, so that branch is
// not started, and says why).
TEST(CliBifurcation, NoHopfBranchLeavesOnlyTheCycleBranch) {
  const fs::path dir = test::fresh_dir("cli_bifurcation", "no_hopf_branch");
  std::vector<std::string> args = {"bifurcation", kScene};
  args.insert(args.end(), kFlags.begin(), kFlags.end());
  args.insert(args.end(), {"--cycle-speed", "80", "--no-hopf-branch", "--no-plots", "--out", "out"});
  const test::CliRun run = test::run_railstab(args, dir);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const std::string json = test::read_text(dir / "out" / (kStem + "_bifurcation.json"));
  const std::vector<std::string> origins = json_values(json, "origin");
  ASSERT_EQ(origins.size(), 1u) << json;
  EXPECT_EQ(origins[0], "\"time_domain\"");
}
