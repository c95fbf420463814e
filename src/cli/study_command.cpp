#include "cli/study_command.hpp"

#include "cli/numeric_flags.hpp"
#include "cli/set_flag.hpp"
#include <railstab/io/file_names.hpp>
#include <railstab/io/gnuplot.hpp>
#include <railstab/io/output_set.hpp>
#include <railstab/setup/prepare_scene.hpp>
#include <railstab/report/study_report.hpp>
#include <railstab/stability/speed_analysis.hpp>
#include <railstab/study/study_record.hpp>

#include <filesystem>
#include <iostream>
#include <memory>
#include <thread>

namespace railstab {

namespace {

struct StudyArgs {
  std::string scene;
  std::vector<SceneValueSetting> fixed;
  std::vector<VariedKey> varied;
  StudyAnalysis analysis;
  unsigned jobs = std::max(1u, std::thread::hardware_concurrency());
  StudyShard shard;
  std::string out_dir = "out";
  bool plots = true;
};

// A validator from a parser that throws std::invalid_argument.
// (No description: the option's type name already shows the form.)
template <class Parse> CLI::Validator parsed_by(Parse parse) {
  return CLI::Validator(
      [parse](std::string& text) -> std::string {
        try {
          parse(text);
          return {};
        } catch (const std::invalid_argument& e) {
          return e.what();
        }
      },
      "");
}

void run_study_command(const StudyArgs& a) {
  StudyDefinition d;
  d.scene_path = a.scene;
  d.fixed = a.fixed;
  d.varied = a.varied;
  d.analysis = a.analysis;
  check_study_definition(d);
  check_speed_grid(d.analysis.from_m_per_s, d.analysis.to_m_per_s, d.analysis.grid_step_m_per_s);
  const bool plots = a.plots && !a.shard.sharded();
  if (plots) require_gnuplot();  // before the study, not after it
  complete_study_definition(d);  // the scene's name and hash; every key checked
  std::size_t todo = 0;
  for (std::size_t i = 0; i < d.combinations(); ++i) todo += a.shard.holds(i);
  std::cerr << "study of " << d.scene_name << ": " << d.combinations() << " combinations"
            << (a.shard.sharded() ? ", shard " + std::to_string(a.shard.index) + "/" +
                                        std::to_string(a.shard.count) + " computes " + std::to_string(todo)
                                  : std::string())
            << ", " << a.jobs << (a.jobs == 1 ? " thread" : " threads") << "\n";
  StudyRunOptions options;
  options.jobs = a.jobs;
  options.shard = a.shard;
  options.progress = [](const std::string& line) { std::cerr << line << "\n"; };
  const auto start = std::chrono::steady_clock::now();
  const std::vector<StudyPoint> points = run_study(d, options);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  OutputSet outputs(a.out_dir);
  write_study_results(d, a.shard, points, outputs, scene_file_stem(d.scene_path), plots);
  const std::vector<std::string> written = outputs.commit();
  print_study_summary(std::cout, d, points);
  std::cout << points.size() << " critical-speed searches in " << seconds << " s wall\n";
  for (const std::string& f : written) std::cout << "wrote " << f << "\n";
}

struct MergeArgs {
  std::string out_dir;
  std::vector<std::string> shard_dirs;
  bool plots = true;
};

// The one *_study_record.toml a shard's output folder holds.
std::string record_in(const std::string& dir) {
  namespace fs = std::filesystem;
  std::vector<std::string> found;
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw std::runtime_error("merge: " + dir + ": expected a shard's output folder, got no folder");
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    const std::string tail = "_study_record.toml";
    if (name.size() > tail.size() && name.compare(name.size() - tail.size(), tail.size(), tail) == 0)
      found.push_back(e.path().string());
  }
  if (found.size() != 1)
    throw std::runtime_error("merge: " + dir + ": expected one *_study_record.toml (the output of "
                             "`railstab study ... --shard I/N --out " + dir + "`), found " +
                             std::to_string(found.size()));
  return found.front();
}

void run_merge_command(const MergeArgs& a) {
  if (a.plots) require_gnuplot();
  std::vector<StudyRecord> records;
  for (const std::string& dir : a.shard_dirs) records.push_back(read_study_record(record_in(dir)));
  const std::vector<StudyPoint> points = merge_study_records(records);
  const StudyDefinition& d = records.front().definition;
  OutputSet outputs(a.out_dir);
  write_study_results(d, StudyShard{}, points, outputs, scene_file_stem(d.scene_path), a.plots);
  const std::vector<std::string> written = outputs.commit();
  std::cout << "merged " << records.size() << " shard" << (records.size() == 1 ? "" : "s") << "\n";
  print_study_summary(std::cout, d, points);
  for (const std::string& f : written) std::cout << "wrote " << f << "\n";
}

}  // namespace

void register_study_commands(CLI::App& app) {
  {
    auto a = std::make_shared<StudyArgs>();
    CLI::App* cmd = app.add_subcommand(
        "study",
        "parameter study: the critical speed for every combination of scene values "
        "(--vary KEY=FROM:TO:STEP ...), in parallel; CSV, JSON, plots (a stability map for two keys)");
    cmd->add_option("scene", a->scene, "scene file (TOML)")->required()->check(CLI::ExistingFile);
    add_set_flag(cmd, a->fixed);
    cmd->add_option_function<std::vector<std::string>>(
           "--vary",
           [a](const std::vector<std::string>& texts) {
             a->varied.clear();
             for (const std::string& t : texts) a->varied.push_back(parse_varied_key(t));
           },
           "a scene key and its values, e.g. --vary elements.yaw_damper.damping_N_s_per_m[0]="
           "1e5:5e5:1e5 (repeatable: every combination is computed; the first key outermost); "
           "keys joined by commas take one value together, e.g. --vary 'K1,K2=1e5:5e5:1e5'")
        ->type_name("KEY=FROM:TO:STEP")
        ->required()
        ->expected(1)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
        ->check(parsed_by([](const std::string& t) { parse_varied_key(t); }));
    cmd->add_option("--from", a->analysis.from_m_per_s, "lowest speed (m/s)")
        ->capture_default_str()
        ->check(finite_in(flag_ranges::speed_m_per_s));
    cmd->add_option("--to", a->analysis.to_m_per_s, "highest speed (m/s)")
        ->capture_default_str()
        ->check(finite_in(flag_ranges::speed_m_per_s));
    cmd->add_option("--step", a->analysis.grid_step_m_per_s, "speed grid step (m/s)")
        ->capture_default_str()
        ->check(finite_in(flag_ranges::speed_step_m_per_s));
    cmd->add_option("--solver", a->analysis.solver,
                    "eigen-solver: auto, dense, sparse or arpack (as critical-speed --solver)")
        ->check(CLI::IsMember(eigen_solver_names()))
        ->capture_default_str();
    cmd->add_option("--hunting-band", a->analysis.hunting_band_hz,
                    "highest mode frequency (Hz) that decides stability")
        ->capture_default_str()
        ->check(finite_in(flag_ranges::frequency_hz));
    cmd->add_option("--jobs", a->jobs, "threads (default: the machine's cores)")
        ->capture_default_str()
        ->check(CLI::Range(1u, 1024u));
    cmd->add_option_function<std::string>(
           "--shard", [a](const std::string& t) { a->shard = parse_study_shard(t); },
           "compute only the combinations with index % N == I - 1 (join the shards' --out folders "
           "with `railstab merge`; no plots)")
        ->type_name("I/N")
        ->check(parsed_by([](const std::string& t) { parse_study_shard(t); }));
    cmd->add_option("--out", a->out_dir, "output directory")->capture_default_str();
    cmd->add_flag("!--no-plots", a->plots, "do not run gnuplot (CSV, JSON and record only)");
    cmd->callback([a] { run_study_command(*a); });
  }
  {
    auto a = std::make_shared<MergeArgs>();
    CLI::App* cmd = app.add_subcommand(
        "merge", "join the output folders of `railstab study --shard I/N` runs into the files of the "
                 "whole study (the same as one unsharded run)");
    cmd->add_option("out", a->out_dir, "output directory of the merged study")->required();
    cmd->add_option("shards", a->shard_dirs, "the shards' output folders (each with its "
                                             "*_study_record.toml)")
        ->required()
        ->check(CLI::ExistingDirectory);
    cmd->add_flag("!--no-plots", a->plots, "do not run gnuplot");
    cmd->callback([a] { run_merge_command(*a); });
  }
}

}  // namespace railstab
