#include "cli/work_precision_command.hpp"

#include "cli/scene_command.hpp"
#include "cli/numeric_flags.hpp"
#include "cli/set_flag.hpp"
#include <railstab/setup/prepare_scene.hpp>
#include <railstab/integrate/work_precision.hpp>
#include <railstab/io/file_names.hpp>
#include <railstab/io/gnuplot.hpp>
#include <railstab/io/output_set.hpp>
#include <railstab/report/work_precision_report.hpp>

#include <iostream>
#include <memory>

namespace railstab {

namespace {

struct WorkPrecisionArgs : SceneCommandArgs {
  double budget_s = 5.0;
  std::vector<std::string> integrators;  // labels; empty: all
  std::vector<double> rtols;             // empty: the default ladder
};

std::vector<IntegratorVariant> selected_variants(const std::vector<std::string>& labels) {
  if (labels.empty()) return default_variants();
  std::vector<IntegratorVariant> chosen;
  for (const std::string& l : labels) chosen.push_back(parse_integrator_variant(l));
  return chosen;
}

void run_work_precision_command(const WorkPrecisionArgs& args) {
  if (args.plots) require_gnuplot();
  const PreparedScene scene = prepare_command_scene(args);
  const Model& model = scene.model;
  const double speed_m_per_s = scene.speed_m_per_s;
  WorkPrecisionSettings s;
  s.t_end_s = scene.spec.simulation.t_end_s;
  s.output_interval_s = scene.spec.simulation.output_interval_s;
  s.cpu_budget_per_run_s = args.budget_s;
  s.variants = selected_variants(args.integrators);
  if (!args.rtols.empty()) s.relative_tolerances = args.rtols;
  std::cerr << "work-precision: " << model.name << ", " << model.state_size() << " states, "
            << speed_m_per_s << " m/s, " << s.t_end_s << " s\n";
  const WorkPrecisionResult r = run_work_precision(
      model, speed_m_per_s, perturbed_initial_state(scene), s, [](const std::string& line) {
        std::cerr << "  " << line << "\n";
      });

  const std::string stem = scene_file_stem(args.scene) + "_" + speed_file_tag(speed_m_per_s);
  OutputSet outputs(args.out_dir);
  for (const std::string& name : work_precision_plot_file_names(stem)) outputs.replaces(name);
  outputs.write(stem + "_work_precision.csv",
                [&](std::ostream& out) { write_work_precision_csv(out, r); });
  outputs.write(stem + "_work_precision.md", [&](std::ostream& out) {
    write_work_precision_markdown(out, model, speed_m_per_s, s, r);
  });
  if (args.plots) write_work_precision_plot(outputs, stem, model, speed_m_per_s, s.t_end_s, r);
  list_written(outputs.commit(), std::cout);
}

}  // namespace

void register_work_precision_command(CLI::App& app) {
  auto args = std::make_shared<WorkPrecisionArgs>();
  CLI::App* cmd = app.add_subcommand(
      "work-precision", "compare the integrators: error against CPU time over a range of tolerances");
  SceneFlags flags;
  flags.speed = flags.plots = true;
  add_scene_flags(cmd, *args, flags);
  cmd->add_option("--t-end", args->overrides.t_end_s,
                  "end time in s (overrides the scene; 5 s keeps the study near a minute)")
      ->check(finite_in(flag_ranges::t_end_s));
  cmd->add_option("--budget", args->budget_s, "CPU seconds per run before giving up")
      ->capture_default_str()
      ->check(finite_in(flag_ranges::cpu_budget_s));
  cmd->add_option("--integrators", args->integrators,
                  "integrators to compare (default: cvode_bdf, cvode_bdf_q2, cvode_adams, "
                  "arkode_erk, arkode_dirk, arkode_imex); _qN caps or sets the order, e.g. "
                  "arkode_dirk_q3")
      ->delimiter(',');
  cmd->add_option("--rtols", args->rtols,
                  "relative tolerances, loose to tight (default 1e-3,...,1e-8; atol = 1e-3 rtol)")
      ->delimiter(',')
      ->check(finite_in(flag_ranges::relative_tolerance));
  cmd->callback([args] { run_work_precision_command(*args); });
}

}  // namespace railstab
