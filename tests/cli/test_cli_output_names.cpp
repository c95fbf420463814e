// Every key of every JSON output, every CSV column and every key of the
// study record follows the naming convention of docs/outputs.md ("Naming
// convention"): snake_case, a unit at the end spelled as in the scene keys,
// `scene` the scene's name and `scene_file` its path, and none of the names
// renamed away (CHANGELOG) is written anywhere.
#include <gtest/gtest.h>

#include "cli/run_cli.hpp"

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

const std::string kCases = RAILSTAB_CASES_DIR;
const std::string kWheelset = kCases + "/textbook_wheelset.toml";

std::string file_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// The names of the old outputs (CHANGELOG, "one naming convention").
const std::set<std::string> kOldNames = {
    "speed_m_s", "critical_speed_m_s", "critical_speed_tolerance_m_s",
    "speed_tolerance_requested_m_s", "speed_range_m_s", "equilibrium_lost_at_m_s",
    "stable_side_m_s", "unstable_side_m_s", "modes_at_critical_speed_m_s", "speed_tolerance_m_s",
    "natural_frequency_speed_m_s", "frequency_hz", "hunting_band_hz", "eigen_frequency_hz",
    "fitted_frequency_hz", "wall_seconds", "cpu_seconds", "reference_wall_seconds",
    "integration_wall_seconds", "x_m_offset", "y_m_offset", "z_m_offset", "roll_rad_offset",
    "pitch_rad_offset", "yaw_rad_offset", "spin_rate_rad_s", "total_force_on_wheelset_I_N_x",
    "total_force_on_wheelset_I_N_y", "total_force_on_wheelset_I_N_z", "fit_window_s_from",
    "fit_window_s_to", "equilibrium_acceleration_tolerance_m_s2", "cant_deficiency_m_by_speed",
    "eigenvalue_imag_rad_per_s", "dVc_dp_m_per_s_per_unit", "dVc_dp", "dRe_lambda_dp",
    "dIm_lambda_dp", "dRe_lambda_dV_per_m", "equivalent_conicity_at_3mm", "real_per_s",
    "imag_per_s", "eigen_real_per_s", "Y_N", "Q_N", "Y_over_Q", "scene_name", "source", "rtol",
    "atol", "jacobians", "error", "error_coordinate"};

// Lower-case words joined by '_'; capitals only in a unit at the end (_Hz,
// _N, _N_m); no unit followed by another word (x_m_offset), no unit spelled
// otherwise than in the scene keys (_m_s, _hz, _seconds, _rad_s).
std::string convention_broken(const std::string& name) {
  static const std::regex snake("[a-z][a-z0-9]*(_[a-z0-9]+)*(_Hz|_N|_N_m)?");
  static const std::regex unit_inside("_(m|rad|s|N|Hz|kg)_(?!per_|m$|m_per_)[a-z]");
  static const std::regex misspelt("(_m_s|_m_s2|_rad_s|_hz|_seconds)$");
  if (kOldNames.count(name)) return "an old name";
  if (!std::regex_match(name, snake)) return "not snake_case";
  if (std::regex_search(name, unit_inside)) return "a unit inside the name";
  if (std::regex_search(name, misspelt)) return "a unit not spelled as in the scene keys";
  return "";
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t from = 0;
  while (from < text.size()) {
    const std::size_t end = text.find('\n', from);
    lines.push_back(text.substr(from, end == std::string::npos ? std::string::npos : end - from));
    if (end == std::string::npos) break;
    from = end + 1;
  }
  return lines;
}

// Keys at the start of a JSON line (the writer puts every key on its own
// line); keys naming a scene key or a body coordinate (holding '.') are the
// scene's own names.
std::vector<std::string> json_keys(const std::string& text) {
  static const std::regex key("^\\s*\"((?:[^\"\\\\]|\\\\.)*)\":");
  std::vector<std::string> keys;
  std::smatch m;
  for (const std::string& line : lines_of(text))
    if (std::regex_search(line, m, key)) keys.push_back(m[1]);
  return keys;
}

std::vector<std::string> csv_columns(const std::string& text) {
  std::vector<std::string> columns;
  const std::string header = text.substr(0, text.find('\n'));
  std::size_t from = 0;
  for (;;) {
    const std::size_t comma = header.find(',', from);
    std::string c = header.substr(from, comma == std::string::npos ? std::string::npos : comma - from);
    // <body>.y_m: the coordinate's name after the body's; a study's
    // column for a varied scene key: its last part.
    if (const std::size_t dot = c.rfind('.'); dot != std::string::npos && c.find('=') == std::string::npos)
      c = c.substr(dot + 1);
    columns.push_back(c);
    if (comma == std::string::npos) break;
    from = comma + 1;
  }
  return columns;
}

// key = value at the start of a line (tables' keys, indented in arrays of
// tables) or inside an inline table.
std::vector<std::string> toml_keys(const std::string& text) {
  static const std::regex key("(?:^\\s*|[{,]\\s*)([A-Za-z_][A-Za-z0-9_]*) = ");
  std::vector<std::string> keys;
  for (const std::string& line : lines_of(text))
    for (auto it = std::sregex_iterator(line.begin(), line.end(), key); it != std::sregex_iterator(); ++it)
      keys.push_back((*it)[1]);
  return keys;
}

struct Command {
  std::vector<std::string> args;
  bool plots_flag = true;  // takes --no-plots
};

}  // namespace

TEST(CliOutputNames, EveryKeyAndColumnFollowsTheNamingConvention) {
  const fs::path dir = fs::temp_directory_path() / ("railstab_cli_names_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::vector<Command> commands = {
      {{"critical-speed", kWheelset, "--from", "5", "--to", "120", "--step", "5",
        "--min-damping-ratio", "0.05"}},
      {{"eigen", kWheelset, "--speed", "30"}, false},
      {{"equilibrium", kWheelset, "--speed", "30"}, false},
      {{"simulate", kWheelset, "--speed", "30", "--t-end", "0.2"}},
      {{"simulate", kWheelset, "--speed", "30", "--t-end", "0.2", "--mode", "hunting",
        "--mode-amplitude", "1e-4"}},
      {{"simulate", kWheelset, "--speed", "30", "--ramp-rate", "5", "--ramp-rate", "10",
        "--ramp-to", "26"}},
      {{"verify", kWheelset}},
      {{"check", kWheelset}, false},
      {{"sensitivity", kWheelset, "--key", "contacts.textbook_linear.conicity"}},
      {{"study", kWheelset, "--vary", "contacts.textbook_linear.conicity=0.1:0.2:0.1", "--from",
        "5", "--to", "120", "--step", "5"}},
      {{"work-precision", kWheelset, "--t-end", "0.2", "--integrators", "cvode_bdf", "--rtols",
        "1e-3"}},
      {{"contact-geometry", kCases + "/s1002_uic60_contact.toml"}},
      // The quasi-linear critical speed at one amplitude and over amplitudes.
      {{"critical-speed", kWheelset, "--from", "5", "--to", "120", "--step", "5", "--amplitude",
        "0.003"}},
      {{"critical-speed", kWheelset, "--from", "5", "--to", "120", "--step", "5", "--amplitudes",
        "0.001:0.003:0.001"}},
      {{"bifurcation", kWheelset, "--from", "50", "--to", "100", "--max-amplitude", "0.002"}},
  };
  std::size_t names = 0;
  for (std::size_t i = 0; i < commands.size(); ++i) {
    const Command& c = commands[i];
    const std::string out = "out" + std::to_string(i);
    std::vector<std::string> args = c.args;
    if (c.plots_flag) args.push_back("--no-plots");
    args.insert(args.end(), {"--out", out});
    const auto run = railstab::test::run_railstab(args, dir, "", 300);
    ASSERT_EQ(run.exit_code, 0) << c.args[0] << ": " << run.output;
    std::size_t files = 0;
    for (const auto& entry : fs::directory_iterator(dir / out)) {
      const fs::path& p = entry.path();
      const std::string ext = p.extension().string(), text = file_text(p);
      std::vector<std::string> found;
      if (ext == ".json") found = json_keys(text);
      else if (ext == ".csv") found = csv_columns(text);
      else if (ext == ".toml") found = toml_keys(text);
      else continue;
      ++files;
      EXPECT_FALSE(found.empty()) << p;
      for (const std::string& name : found) {
        if (ext != ".csv" && name.find('.') != std::string::npos) continue;  // a scene key
        ++names;
        const std::string broken = convention_broken(name);
        EXPECT_EQ(broken, "") << p.filename() << ": " << name;
      }
      // `scene` is the scene's name, `scene_file` its path, in every output.
      if (ext == ".json") {
        static const std::regex scene("^\\s*\"scene\": \"([^\"]*)\""),
            scene_file("^\\s*\"scene_file\": \"([^\"]*)\"");
        std::smatch m;
        for (const std::string& line : lines_of(text)) {
          if (std::regex_search(line, m, scene)) {
            EXPECT_EQ(m[1].str(), "textbook_wheelset") << p.filename() << ": " << line;
          }
          if (std::regex_search(line, m, scene_file)) {
            EXPECT_NE(m[1].str().find(".toml"), std::string::npos) << p.filename() << ": " << line;
          }
        }
      }
    }
    EXPECT_GT(files, 0u) << c.args[0];
  }
  EXPECT_GT(names, 300u);
  fs::remove_all(dir);
}

// equilibrium's file carries the speed as eigen's does (docs/outputs.md,
// "File names"): runs at two speeds into one folder keep both results.
TEST(CliOutputNames, EquilibriumAtTwoSpeedsKeepsBoth) {
  const fs::path dir = fs::temp_directory_path() / ("railstab_cli_eq_names_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  for (const std::string speed : {"30", "36.9"}) {
    const auto run = railstab::test::run_railstab({"equilibrium", kWheelset, "--speed", speed, "--out", "out"}, dir);
    ASSERT_EQ(run.exit_code, 0) << run.output;
  }
  EXPECT_TRUE(fs::is_regular_file(dir / "out" / "textbook_wheelset_equilibrium_30mps.json"));
  EXPECT_TRUE(fs::is_regular_file(dir / "out" / "textbook_wheelset_equilibrium_36.9mps.json"));
  EXPECT_FALSE(fs::exists(dir / "out" / "textbook_wheelset_equilibrium.json"));
  fs::remove_all(dir);
}

// Every command names its files after the scene file, not the scene's
// `name` (issue 24, item 4): two copies of one scene (same `name`, one
// value changed) run into one folder keep their own outputs, and a command
// run at one speed carries it (docs/outputs.md, "File names").
TEST(CliOutputNames, EveryCommandNamesItsFilesAfterTheSceneFileAndItsSpeed) {
  const fs::path dir = fs::temp_directory_path() / ("railstab_cli_stem_names_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string text = file_text(kWheelset);
  ASSERT_NE(text.find("name = \"textbook_wheelset\""), std::string::npos);
  std::ofstream(dir / "copy_a.toml") << text;
  std::ofstream(dir / "copy_b.toml") << text;
  struct Run {
    std::vector<std::string> args;  // after the scene
    std::vector<std::string> files;  // after the stem
  };
  const std::vector<Run> runs = {
      {{"equilibrium", "--speed", "30"}, {"_equilibrium_30mps.json"}},
      {{"eigen", "--speed", "30"}, {"_eigen_30mps.json"}},
      {{"critical-speed", "--from", "5", "--to", "60", "--step", "5", "--no-plots"},
       {"_critical_speed.json", "_eigenvalues.csv"}},
      {{"check", "--speed", "30", "--no-frequencies"}, {"_check_30mps.json", "_check_30mps.md"}},
      {{"simulate", "--speed", "30", "--t-end", "0.05", "--no-plots"}, {"_30mps.csv", "_30mps_run.json"}},
      {{"verify", "--speed", "30", "--no-plots"}, {"_verify_30mps.json"}},
      {{"work-precision", "--speed", "30", "--t-end", "0.05", "--integrators", "cvode_bdf",
        "--rtols", "1e-3", "--no-plots"},
       {"_30mps_work_precision.csv", "_30mps_work_precision.md"}},
      {{"sensitivity", "--key", "contacts.textbook_linear.conicity", "--from", "5", "--to", "120",
        "--step", "5", "--no-plots"},
       {"_sensitivity.json"}},
      {{"study", "--vary", "contacts.textbook_linear.conicity=0.1:0.2:0.1", "--from", "5", "--to",
        "60", "--step", "5", "--no-plots"},
       {"_study.csv", "_study.json"}},
  };
  for (const Run& r : runs) {
    for (const std::string stem : {"copy_a", "copy_b"}) {
      std::vector<std::string> args = {r.args[0], stem + ".toml"};
      args.insert(args.end(), r.args.begin() + 1, r.args.end());
      args.insert(args.end(), {"--out", "out"});
      const auto run = railstab::test::run_railstab(args, dir, "", 300);
      ASSERT_EQ(run.exit_code, 0) << r.args[0] << ": " << run.output;
      for (const std::string& suffix : r.files)
        EXPECT_TRUE(fs::is_regular_file(dir / "out" / (stem + suffix))) << r.args[0] << ": " << stem + suffix;
    }
  }
  // Nothing is named after the scene's `name` any more.
  for (const auto& entry : fs::directory_iterator(dir / "out"))
    EXPECT_EQ(entry.path().filename().string().rfind("textbook_wheelset", 0), std::string::npos)
        << entry.path();
  fs::remove_all(dir);
}
