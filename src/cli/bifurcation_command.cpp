#include "cli/bifurcation_command.hpp"

#include "cli/numeric_flags.hpp"
#include "cli/scene_command.hpp"
#include <railstab/io/gnuplot.hpp>
#include <railstab/io/output_set.hpp>
#include <railstab/nonlinear/bifurcation_analysis.hpp>
#include <railstab/report/bifurcation_report.hpp>
#include <railstab/report/run_conditions.hpp>

#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>

namespace railstab {

namespace {

struct BifurcationArgs : SceneCommandArgs {
  BifurcationOptions options;
  std::string solver = "auto";
  std::string cycle_direction = "down";
  double hunting_band_hz = 20.0;
  int max_orbits = 200;
};

void run_bifurcation(const BifurcationArgs& a) {
  BifurcationOptions o = a.options;
  check_speed_grid(o.linear.from_m_per_s, o.linear.to_m_per_s, o.linear.grid_step_m_per_s);
  if (o.cycle_speed_m_per_s > 0.0 &&
      !(o.cycle_speed_m_per_s >= o.linear.from_m_per_s && o.cycle_speed_m_per_s <= o.linear.to_m_per_s)) {
    std::ostringstream msg;
    msg << "--cycle-speed " << o.cycle_speed_m_per_s << " m/s must lie between --from "
        << o.linear.from_m_per_s << " and --to " << o.linear.to_m_per_s << " m/s";
    throw std::invalid_argument(msg.str());
  }
  if (!o.from_hopf && !(o.cycle_speed_m_per_s > 0.0) && !o.default_cycle_start)
    throw std::invalid_argument(
        "--no-hopf-branch with --no-cycle-branch leaves no branch to compute");
  if (a.plots) require_gnuplot();  // before the orbits, not after them
  const PreparedScene s = prepare_command_scene(a);
  // Without a cycle speed only profile contact starts a time-domain branch
  // by default (analyse_bifurcation).
  if (!starts_a_branch(s.model, o))
    throw std::invalid_argument(
        "--no-hopf-branch leaves no branch to compute: give --cycle-speed V as well (the "
        "default time-domain start is for profile contact, and " + a.scene +
        " has none)");
  o.linear.stability.solver = eigen_solver_from_name(a.solver);
  o.linear.stability.max_frequency_hz = a.hunting_band_hz;
  o.continuation.max_orbits = a.max_orbits;
  o.cycle_speed_step_m_per_s = cycle_speed_step_for(a.cycle_direction, "--cycle-direction");
  o.progress = [](const std::string& line) { std::cerr << line << "\n"; };
  std::cerr << "bifurcation analysis of " << s.model.name << " between " << o.linear.from_m_per_s
            << " and " << o.linear.to_m_per_s << " m/s, orbit amplitudes up to "
            << 1e3 * o.max_amplitude_m << " mm\n";
  const BifurcationResult r = analyse_bifurcation(s.model, s.equilibrium.state, s.speed_m_per_s, o);
  BifurcationRunInfo info;
  info.eigen_solver = a.solver;
  info.hunting_band_hz = a.hunting_band_hz;
  OutputSet outputs(a.out_dir);
  write_bifurcation_results(s.model, r, info, outputs, steady_state_file_stem(a.scene, s.model), a.plots);
  const std::vector<std::string> written = outputs.commit();
  print_bifurcation_summary(std::cout, s.model, r);
  list_written(written, std::cout);
}

}  // namespace

void register_bifurcation_command(CLI::App& app) {
  auto a = std::make_shared<BifurcationArgs>();
  a->options.linear.from_m_per_s = 5.0;
  a->options.linear.to_m_per_s = 150.0;
  a->options.linear.grid_step_m_per_s = 2.5;
  a->options.max_amplitude_m = 0.01;
  CLI::App* cmd = app.add_subcommand(
      "bifurcation",
      "nonlinear critical speed: periodic hunting orbits by shooting from the Hopf point (and "
      "from a time-domain cycle), continued in speed with their Floquet stability; JSON, CSV, "
      "Markdown report and the bifurcation diagram");
  SceneFlags flags;
  flags.arc_length = flags.plots = true;
  flags.arc_length_help =
      "arc length (m) of the reference point: tangent track or a constant curve (the orbits "
      "need an autonomous model)";
  flags.plots_help = "do not run gnuplot (data, JSON and report only)";
  add_scene_flags(cmd, *a, flags);
  cmd->add_option("--from", a->options.linear.from_m_per_s,
                  "lowest speed (m/s) of the linear search and of the branches")
      ->capture_default_str()
      ->check(finite_in(flag_ranges::speed_m_per_s));
  cmd->add_option("--to", a->options.linear.to_m_per_s,
                  "highest speed (m/s) of the linear search and of the branches")
      ->capture_default_str()
      ->check(finite_in(flag_ranges::speed_m_per_s));
  cmd->add_option("--step", a->options.linear.grid_step_m_per_s,
                  "grid step (m/s) of the linear critical-speed search")
      ->capture_default_str()
      ->check(finite_in(flag_ranges::speed_step_m_per_s));
  cmd->add_option("--cycle-speed", a->options.cycle_speed_m_per_s,
                  "also start a branch from the cycle a time-domain run settles on at this speed "
                  "(m/s; from the steady state with the leading wheelset displaced 5 mm, 6 s); "
                  "on profile contact the default is 1.03 x the linear critical speed")
      ->check(finite_in(flag_ranges::speed_m_per_s));
  cmd->add_option("--cycle-direction", a->cycle_direction,
                  "the time-domain branch is followed from its cycle down in speed (towards the "
                  "fold below a flange-hunting cycle) or up (to higher speeds); its second orbit "
                  "lies 0.5 m/s that way")
      ->check(CLI::IsMember({"down", "up"}))
      ->capture_default_str();
  cmd->add_flag("--no-cycle-branch", [a](std::int64_t) { a->options.default_cycle_start = false; },
               "on profile contact without --cycle-speed, do not start the default time-domain "
               "branch (from the cycle a run at 1.03 x the linear critical speed settles on)");
  cmd->add_flag("--no-hopf-branch", [a](std::int64_t) { a->options.from_hopf = false; },
               "do not start a branch at the Hopf point (only the time-domain branch): on a "
               "profile contact the orbits near the Hopf point are micrometres in size and "
               "costly; the hunting that matters starts from a cycle");
  cmd->add_option("--max-amplitude", a->options.max_amplitude_m,
                  "stop a branch where the leading wheelset's lateral amplitude exceeds this (m)")
      ->capture_default_str()
      ->check(finite_in(flag_ranges::orbit_amplitude_m));
  cmd->add_flag("--stop-at-fold",
               [a](std::int64_t) { a->options.continuation.stop_at_first_fold = true; },
               "stop each branch two orbits past its first fold (the nonlinear critical speed "
               "where its stable orbits end there) instead of following it on");
  cmd->add_option("--max-orbits", a->max_orbits, "stop a branch after this many orbits")
      ->capture_default_str()
      ->check(CLI::Range(2, 10000));
  cmd->add_option("--solver", a->solver, "eigen-solver of the linear search (as critical-speed)")
      ->check(CLI::IsMember(eigen_solver_names()))
      ->capture_default_str();
  cmd->add_option("--hunting-band", a->hunting_band_hz,
                  "highest mode frequency (Hz) that decides the linear stability")
      ->capture_default_str()
      ->check(finite_in(flag_ranges::frequency_hz));
  cmd->callback([a] { run_bifurcation(*a); });
}

}  // namespace railstab
