#include "cli/verify_command.hpp"

#include "cli/scene_command.hpp"
#include <railstab/report/run_conditions.hpp>
#include "cli/numeric_flags.hpp"
#include "cli/set_flag.hpp"
#include "cli/start_flags.hpp"
#include <railstab/setup/prepare_scene.hpp>
#include <railstab/io/file_names.hpp>
#include <railstab/io/gnuplot.hpp>
#include <railstab/io/output_set.hpp>
#include <railstab/report/verify_report.hpp>
#include <railstab/verify/verification.hpp>

#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>

namespace railstab {

namespace {

struct VerifyArgs : SceneCommandArgs {
  VerificationOptions options;
  std::string json;
  bool scene_offsets = false;
  StartFlags start;
};

void run_verify(const VerifyArgs& a) {
  if (!(a.options.settle_periods < a.options.periods)) {
    std::ostringstream msg;
    msg << "--settle-periods " << a.options.settle_periods << " must be below --periods "
        << a.options.periods << " (the fit window lies between them)";
    throw std::invalid_argument(msg.str());
  }
  check_start_flags(a.overrides, a.start);
  if (a.scene_offsets && !a.start.mode.empty())
    throw std::invalid_argument("--scene-offsets and --mode: give one of them");
  if (a.plots) require_gnuplot();
  const PreparedScene s = prepare_command_scene(a);
  std::cerr << "verify " << s.model.name << " at " << s.speed_m_per_s
            << " m/s: eigen-analysis, then two time-domain runs (tolerance and 100x tighter)\n";
  VerificationOptions options = a.options;
  // --offset values are scene offsets given on the command line.
  if (a.scene_offsets || !a.overrides.offsets.empty()) {
    options.initial_state = perturbed_initial_state(s);
    options.initial_state_description = "scene initial offsets";
    for (const OffsetSetting& o : a.overrides.offsets)
      options.initial_state_description += ", --offset " + o.text;
  }
  if (const std::optional<ModeStart> mode = mode_start_from_flags(s, a.start)) {
    options.initial_state = mode->state;
    options.initial_state_description = mode_start_description(*mode);
  }
  const VerificationResult r = verify_least_stable_mode(s.model, s.speed_m_per_s, s.equilibrium.state, options);
  const std::string stem =
      steady_state_file_stem(a.scene, s.model) + "_verify_" + speed_file_tag(r.speed_m_per_s);
  OutputSet outputs(a.out_dir);
  for (const std::string& name : verification_plot_file_names(stem)) outputs.replaces(name);
  auto json_writer = [&](std::ostream& out) { write_verification_json(out, s.model, r); };
  outputs.replaces(stem + ".json");  // with --json elsewhere, an earlier default goes
  if (a.json.empty()) outputs.write(stem + ".json", json_writer);
  else outputs.write_at(a.json, json_writer);
  if (a.plots) write_verification_plot(r, outputs, stem, s.model);
  const std::vector<std::string> written = outputs.commit();
  print_verification_summary(std::cout, s.model, r);
  list_written(written, std::cout);
}

}  // namespace

void register_verify_command(CLI::App& app) {
  auto a = std::make_shared<VerifyArgs>();
  CLI::App* cmd = app.add_subcommand(
      "verify", "time-domain check of the least stable mode: fitted rate and frequency against "
                "the eigenvalue");
  SceneFlags flags;
  flags.speed = flags.arc_length = flags.plots = true;
  flags.speed_help = "speed V in m/s";
  flags.arc_length_help = "arc length (m) of the reference point at t = 0";
  flags.plots_help = "do not run gnuplot (JSON only)";
  add_scene_flags(cmd, *a, flags);
  cmd->add_option("--amplitude", a->options.amplitude_m,
                  "initial lateral amplitude (m) of the body that moves most laterally (with "
                  "--any-mode: of the fitted coordinate, in its unit)")
      ->capture_default_str()
      ->check(finite_in(flag_ranges::amplitude_m));
  cmd->add_option("--periods", a->options.periods,
                  "simulated length in periods of the mode (cut where the uniform track ends)")
      ->capture_default_str()
      ->check(finite_in(flag_ranges::periods));
  cmd->add_option("--settle-periods", a->options.settle_periods,
                  "periods skipped before the fit window")
      ->capture_default_str()
      ->check(finite_in(flag_ranges::settle_periods));
  cmd->add_flag("!--any-mode", a->options.lateral_modes_only,
                "fit the least stable oscillatory mode of any kind (e.g. a wheelset spin mode "
                "in a curve), on the coordinate with the largest share of its kinetic energy");
  add_start_flags(cmd, a->overrides, a->start);
  cmd->add_flag("--scene-offsets", a->scene_offsets,
                "start from the scene's initial offsets and rates instead of the mode "
                "perturbation (e.g. the thesis cases' 1 mm offset of wheelset1)");
  cmd->add_option("--json", a->json, "JSON output (default OUT/<scene>_verify_<V>mps.json)");
  cmd->callback([a] { run_verify(*a); });
}

}  // namespace railstab
