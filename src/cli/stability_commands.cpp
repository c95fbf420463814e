#include "cli/stability_commands.hpp"

#include "cli/scene_command.hpp"
#include <railstab/report/run_conditions.hpp>
#include "cli/numeric_flags.hpp"
#include "cli/set_flag.hpp"
#include <railstab/setup/prepare_scene.hpp>
#include <railstab/io/file_names.hpp>
#include <railstab/io/gnuplot.hpp>
#include <railstab/io/output_set.hpp>
#include <railstab/report/eigen_report.hpp>
#include <railstab/stability/point_mode_shapes.hpp>
#include <railstab/report/equilibrium_report.hpp>
#include <railstab/nonlinear/hopf_assessment.hpp>
#include <railstab/report/stability_report.hpp>
#include <railstab/stability/speed_analysis.hpp>

#include <iostream>
#include <memory>

namespace railstab {

namespace {

struct CommonArgs : SceneCommandArgs {
  std::string solver = "auto";
  double hunting_band_hz = 20.0;
};

// equilibrium and eigen: at one speed, anywhere on the track.
SceneFlags speed_and_arc_length() {
  SceneFlags flags;
  flags.speed = flags.arc_length = true;
  flags.speed_help = "speed V in m/s";
  return flags;
}

void add_solver(CLI::App* cmd, CommonArgs& a) {
  cmd->add_option("--solver", a.solver,
                  "eigen-solver: dense (all modes), sparse (every mode in the hunting band, "
                  "shift-invert on a sparse LU at several shifts), arpack (the 16 modes nearest "
                  "one shift) or auto (dense below " +
                      std::to_string(kSparseFromStates) + " states, sparse from there)")
      ->check(CLI::IsMember(eigen_solver_names()))
      ->capture_default_str();
  cmd->add_option("--hunting-band", a.hunting_band_hz,
                  "highest mode frequency (Hz) that decides stability; faster unstable modes "
                  "are reported as warnings")
      ->capture_default_str()
      ->check(finite_in(flag_ranges::frequency_hz));
}

StabilityOptions stability_options(const CommonArgs& a) {
  StabilityOptions o;
  o.solver = eigen_solver_from_name(a.solver);
  o.max_frequency_hz = a.hunting_band_hz;
  return o;
}

// Output names start with the scene name made safe (io/file_names.hpp), so
// a scene called "../evil" still writes inside --out, and a run in a curve
// carries its arc length (report/run_conditions.hpp): it never overwrites
// the tangent run's files.
std::string stem_for(const Model& m) { return steady_state_file_stem(m); }

// --- equilibrium ---------------------------------------------------------------
void run_equilibrium(const CommonArgs& a) {
  const PreparedScene s = prepare_command_scene(a);
  OutputSet outputs(a.out_dir);
  const std::string summary = write_equilibrium_results(s, outputs, stem_for(s.model));
  std::cout << summary;
  list_written(outputs.commit(), std::cout);
}

// --- eigen ---------------------------------------------------------------------
void run_eigen(const CommonArgs& a, double max_hz) {
  const PreparedScene s = prepare_command_scene(a);
  SpeedStability stability(s.model, s.equilibrium.state, s.speed_m_per_s, stability_options(a));
  const StabilityPoint p = stability.at(s.speed_m_per_s);
  print_eigen_summary(std::cout, s.model, p, max_hz);
  OutputSet outputs(a.out_dir);
  write_eigen_json(s.model, p, full_mode_shapes(s.model, p), outputs, stem_for(s.model));
  list_written(outputs.commit(), std::cout);
}

// --- critical speed / sweep -----------------------------------------------------------
void run_critical_speed(const CommonArgs& a, CriticalSpeedOptions opt) {
  check_speed_grid(opt.from_m_per_s, opt.to_m_per_s, opt.grid_step_m_per_s);
  if (a.plots) require_gnuplot();  // before the sweep, not after it
  const PreparedScene s = prepare_command_scene(a);
  opt.stability = stability_options(a);
  opt.progress = [](const std::string& line) { std::cerr << line << "\n"; };
  std::cerr << "critical speed of " << s.model.name << " between " << opt.from_m_per_s
            << " and " << opt.to_m_per_s << " m/s (grid " << opt.grid_step_m_per_s << " m/s)\n";
  const CriticalSpeedResult r = find_critical_speed(s.model, s.equilibrium.state, s.speed_m_per_s, opt);
  const std::string solver =
      r.grid.empty() ? a.solver : eigen_solver_name(r.grid.front().solver_used);
  // The Hopf point's criticality (first Lyapunov coefficient, kind), or why
  // it is not computed (profile contact, no oscillatory crossing).
  const HopfAssessment hopf = assess_hopf(s.model, r);
  OutputSet outputs(a.out_dir);
  write_stability_results(s.model, r, outputs, stem_for(s.model), solver, a.plots,
                          opt.stability.max_frequency_hz, &hopf);
  const std::vector<std::string> written = outputs.commit();
  print_critical_speed_summary(std::cout, s.model, r, opt.stability.max_frequency_hz, &hopf);
  list_written(written, std::cout);
}

}  // namespace

void register_stability_commands(CLI::App& app) {
  {
    auto a = std::make_shared<CommonArgs>();
    CLI::App* cmd = app.add_subcommand(
        "equilibrium", "steady rolling / curving equilibrium: offsets, wheel loads, creepages");
    add_scene_flags(cmd, *a, speed_and_arc_length());
    cmd->callback([a] { run_equilibrium(*a); });
  }
  {
    auto a = std::make_shared<CommonArgs>();
    auto max_hz = std::make_shared<double>(30.0);
    CLI::App* cmd = app.add_subcommand("eigen", "eigenvalues and modes at one speed");
    add_scene_flags(cmd, *a, speed_and_arc_length());
    add_solver(cmd, *a);
    cmd->add_option("--max-frequency", *max_hz, "list modes up to this frequency (Hz)")
        ->capture_default_str()
        ->check(finite_in(flag_ranges::list_frequency_hz));
    cmd->callback([a, max_hz] { run_eigen(*a, *max_hz); });
  }
  for (const bool is_sweep : {false, true}) {
    auto a = std::make_shared<CommonArgs>();
    auto opt = std::make_shared<CriticalSpeedOptions>();
    opt->from_m_per_s = 5.0;
    opt->to_m_per_s = 150.0;
    opt->grid_step_m_per_s = is_sweep ? 1.0 : 2.5;
    CLI::App* cmd = app.add_subcommand(
        is_sweep ? "sweep" : "critical-speed",
        is_sweep ? "eigenvalues over a speed grid: CSV, root locus, damping and frequency plots, "
                   "report"
                 : "critical (hunting) speed: speed grid, then bisection to 0.01 m/s; JSON, "
                   "Markdown report and plots");
    SceneFlags flags;
    flags.arc_length = flags.plots = true;
    flags.plots_help = "do not run gnuplot (data, JSON and report only)";
    add_scene_flags(cmd, *a, flags);
    add_solver(cmd, *a);
    cmd->add_option("--from", opt->from_m_per_s, "lowest speed (m/s)")
        ->capture_default_str()
        ->check(finite_in(flag_ranges::speed_m_per_s));
    cmd->add_option("--to", opt->to_m_per_s, "highest speed (m/s)")
        ->capture_default_str()
        ->check(finite_in(flag_ranges::speed_m_per_s));
    cmd->add_option("--step", opt->grid_step_m_per_s, "grid step (m/s)")
        ->capture_default_str()
        ->check(finite_in(flag_ranges::speed_step_m_per_s));
    cmd->add_option("--min-damping-ratio", opt->min_damping_ratio,
                    "also report the lowest speed where a mode in the hunting band has a damping "
                    "ratio below this (e.g. 0.05), bisected like the critical speed")
        ->check(finite_in(flag_ranges::damping_ratio));
    cmd->callback([a, opt] { run_critical_speed(*a, *opt); });
  }
}

}  // namespace railstab
