#include "cli/sensitivity_command.hpp"

#include "cli/scene_command.hpp"
#include "cli/numeric_flags.hpp"
#include "cli/set_flag.hpp"
#include <railstab/io/file_names.hpp>
#include <railstab/io/gnuplot.hpp>
#include <railstab/io/output_set.hpp>
#include <railstab/report/sensitivity_report.hpp>
#include <railstab/sensitivity/parameter_derivative.hpp>
#include <railstab/setup/prepare_scene.hpp>
#include <railstab/stability/speed_analysis.hpp>

#include <algorithm>
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

void run_sensitivity(const SensitivityArgs& a) {
  check_speed_grid(a.from_m_per_s, a.to_m_per_s, a.step_m_per_s);
  if (a.plots) require_gnuplot();
  const PreparedScene s = prepare_command_scene(a);
  const std::vector<std::string> known = parameter_keys(s.spec);
  for (const std::string& k : a.keys)
    if (std::find(known.begin(), known.end(), k) == known.end())
      throw std::invalid_argument("--key " + k + ": no such parameter of " + s.spec.name +
                                  " (`railstab sensitivity SCENE` without --key lists them all)");
  CriticalSpeedOptions opt;
  opt.from_m_per_s = a.from_m_per_s;
  opt.to_m_per_s = a.to_m_per_s;
  opt.grid_step_m_per_s = a.step_m_per_s;
  // The derivative holds at Re lambda = 0: the speed found to 1e-6 m/s.
  opt.tolerance_m_per_s = 1e-6;
  opt.stability.max_frequency_hz = a.hunting_band_hz;
  const CriticalSpeedResult r = find_critical_speed(s.model, s.equilibrium.state, s.speed_m_per_s, opt);
  if (!r.critical_speed_found || r.at_critical.least_stable < 0)
    throw std::runtime_error(s.spec.source_path + ": no critical speed between " +
                             std::to_string(a.from_m_per_s) + " and " + std::to_string(a.to_m_per_s) +
                             " m/s (--from/--to): there is no stability boundary to differentiate");
  // The implicit function theorem needs an eigenvalue that crosses the
  // imaginary axis continuously (stability/loss_of_stability.hpp).
  if (r.loss.kind != LossOfStabilityKind::oscillatory_crossing)
    throw std::runtime_error(
        s.spec.source_path + ": at " + std::to_string(r.critical_speed_m_per_s) +
        " m/s the stability is lost by " + describe_loss_of_stability(r.loss) +
        "; dVc/dp (implicit function theorem on Re lambda(Vc, p) = 0 for an oscillatory mode) "
        "is only defined for an oscillatory crossing");
  const ModeReport& mode = r.at_critical.modes[size_t(r.at_critical.least_stable)];
  std::cerr << "critical speed " << r.critical_speed_m_per_s << " m/s; derivatives of "
            << (a.keys.empty() ? known.size() : a.keys.size()) << " parameters\n";
  CriticalSpeedSensitivityOptions so;
  so.max_frequency_hz = a.hunting_band_hz;
  const CriticalSpeedSensitivities sens =
      critical_speed_sensitivities(s.spec, r.critical_speed_m_per_s, mode.frequency_hz, a.keys, so);
  SensitivityReportContext c{s.spec.name, a.scene, mode.name, mode.frequency_hz, a.top};
  OutputSet outputs(a.out_dir);
  write_sensitivity_results(sens, c, outputs, file_stem(s.spec.name), a.plots);
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
  cmd->callback([a] { run_sensitivity(*a); });
}

}  // namespace railstab
