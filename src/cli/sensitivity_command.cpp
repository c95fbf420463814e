#include "cli/sensitivity_command.hpp"

#include "cli/model_warnings.hpp"
#include "cli/scene_command.hpp"
#include "cli/numeric_flags.hpp"
#include "cli/set_flag.hpp"
#include <railstab/io/file_names.hpp>
#include <railstab/io/gnuplot.hpp>
#include <railstab/io/output_set.hpp>
#include <railstab/report/sensitivity_report.hpp>
#include <railstab/sensitivity/sensitivity_run.hpp>
#include <railstab/setup/prepare_scene.hpp>

#include <iostream>
#include <memory>

namespace railstab {

namespace {

struct SensitivityArgs : SceneCommandArgs {
  std::vector<std::string> keys;
  double from_m_per_s = 5.0, to_m_per_s = 150.0, step_m_per_s = 2.5;
  double hunting_band_hz = 20.0;
  std::size_t top = 20;
};

void run_sensitivity_command(const SensitivityArgs& a) {
  check_speed_grid(a.from_m_per_s, a.to_m_per_s, a.step_m_per_s);
  if (a.plots) require_gnuplot();
  const PreparedScene s = prepare_command_scene(a);
  SensitivityRunOptions o;
  o.keys = a.keys;
  o.from_m_per_s = a.from_m_per_s;
  o.to_m_per_s = a.to_m_per_s;
  o.grid_step_m_per_s = a.step_m_per_s;
  o.hunting_band_hz = a.hunting_band_hz;
  const SensitivityRun run = run_sensitivity(s, o);
  print_speed_range_warnings_to_stderr(s, run.search, o.to_m_per_s);
  const CriticalSpeedSensitivities& sens = run.sensitivities;
  const ModeReport& mode = run.mode;
  std::cerr << "critical speed " << run.search.critical_speed_m_per_s << " m/s; derivatives of "
            << sens.parameters.size() << " parameters\n";
  SensitivityReportContext c{s.spec.name, a.scene, mode.name, mode.frequency_hz, a.top};
  OutputSet outputs(a.out_dir);
  write_sensitivity_results(sens, c, outputs, scene_file_stem(a.scene), a.plots);
  const std::vector<std::string> written = outputs.commit();
  print_sensitivity_summary(std::cout, sens, c, 10);
  list_written(written, std::cout);
}

}  // namespace

void register_sensitivity_command(CLI::App& app) {
  auto a = std::make_shared<SensitivityArgs>();
  CLI::App* cmd = app.add_subcommand(
      "sensitivity",
      "d(critical speed)/dp for every named suspension, body and contact parameter, from the exact "
      "eigenvalue derivative and the implicit function theorem; ranked CSV, JSON, Markdown and a "
      "tornado plot");
  SceneFlags flags;
  flags.plots = true;
  add_scene_flags(cmd, *a, flags);
  cmd->add_option("--key", a->keys, "only these parameters (repeatable; default: all)")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  cmd->add_option("--from", a->from_m_per_s, "lowest speed (m/s)")
      ->capture_default_str()
      ->check(finite_in(flag_ranges::speed_m_per_s));
  cmd->add_option("--to", a->to_m_per_s, "highest speed (m/s)")
      ->capture_default_str()
      ->check(finite_in(flag_ranges::speed_m_per_s));
  cmd->add_option("--step", a->step_m_per_s, "speed grid step (m/s)")
      ->capture_default_str()
      ->check(finite_in(flag_ranges::speed_step_m_per_s));
  cmd->add_option("--hunting-band", a->hunting_band_hz, "highest mode frequency (Hz) that decides stability")
      ->capture_default_str()
      ->check(finite_in(flag_ranges::frequency_hz));
  cmd->add_option("--top", a->top, "bars in the tornado plot")->capture_default_str()->check(CLI::Range(1, 200));
  cmd->callback([a] { run_sensitivity_command(*a); });
}

}  // namespace railstab
