#include "cli/modes_command.hpp"

#include "cli/scene_command.hpp"
#include <railstab/report/run_conditions.hpp>
#include "cli/numeric_flags.hpp"
#include "cli/set_flag.hpp"
#include <railstab/io/file_names.hpp>
#include <railstab/io/gnuplot.hpp>
#include <railstab/io/output_set.hpp>
#include <railstab/report/mode_plot.hpp>
#include <railstab/setup/prepare_scene.hpp>
#include <railstab/stability/point_mode_shapes.hpp>
#include <railstab/stability/speed_analysis.hpp>

#include <algorithm>
#include <iostream>
#include <memory>
#include <stdexcept>

namespace railstab {

namespace {

struct ModesArgs : SceneCommandArgs {
  double max_frequency_hz = 20.0;
  int count = 6;
  std::vector<std::string> names;  // substrings of mode names to draw
};

void run_modes(const ModesArgs& a) {
  require_gnuplot();
  const PreparedScene s = prepare_command_scene(a);
  StabilityOptions opt;
  opt.max_frequency_hz = a.max_frequency_hz;
  SpeedStability stability(s.model, s.equilibrium.state, s.speed_m_per_s, opt);
  const StabilityPoint p = stability.at(s.speed_m_per_s);
  // Oscillatory modes in the band, least damped first.
  std::vector<int> chosen;
  for (int i = 0; i < int(p.modes.size()); ++i) {
    const ModeReport& m = p.modes[size_t(i)];
    if (m.neutral || m.eigenvalue.imag() <= 0.0 || m.frequency_hz > a.max_frequency_hz) continue;
    // Default: the lateral-plane modes (what a plan view shows); --mode
    // picks any mode by name.
    bool wanted = a.names.empty() && m.lateral_share >= 0.5;
    for (const std::string& n : a.names) wanted = wanted || m.name.find(n) != std::string::npos;
    if (wanted) chosen.push_back(i);
  }
  std::stable_sort(chosen.begin(), chosen.end(), [&](int x, int y) {
    return p.modes[size_t(x)].damping_ratio < p.modes[size_t(y)].damping_ratio;
  });
  if (chosen.empty())
    throw std::invalid_argument(
        "modes: no oscillatory mode up to --max-frequency " + std::to_string(a.max_frequency_hz) +
        " Hz" + (a.names.empty() ? std::string(" in the lateral plane")
                                 : std::string(" whose name contains a --mode text")));
  if (int(chosen.size()) > a.count) chosen.resize(size_t(a.count));
  OutputSet outputs(a.out_dir);
  write_mode_plots(s.model, p, full_mode_shapes(s.model, p), chosen, outputs,
                   steady_state_file_stem(a.scene, s.model));
  std::cout << s.model.name << " at " << p.speed_m_per_s << " m/s, modes drawn:\n";
  for (int i : chosen) {
    const ModeReport& m = p.modes[size_t(i)];
    std::cout << "  " << m.frequency_hz << " Hz, damping ratio " << m.damping_ratio << ": "
              << m.name << "\n";
  }
  list_written(outputs.commit(), std::cout);
}

}  // namespace

void register_modes_command(CLI::App& app) {
  auto a = std::make_shared<ModesArgs>();
  CLI::App* cmd = app.add_subcommand(
      "modes", "plan-view plots (PNG, SVG, animated GIF) of the mode shapes at one speed: "
               "lateral and yaw of every body at four phases; by default the lateral-plane modes, "
               "least damped first");
  SceneFlags flags;
  flags.speed = flags.arc_length = true;
  flags.speed_help = "speed V in m/s";
  flags.arc_length_help = "arc length (m) of the scene's reference point";
  add_scene_flags(cmd, *a, flags);
  cmd->add_option("--max-frequency", a->max_frequency_hz, "draw modes up to this frequency (Hz)")
      ->capture_default_str()
      ->check(finite_in(flag_ranges::frequency_hz));
  cmd->add_option("--count", a->count, "draw at most this many modes, least damped first")
      ->capture_default_str()
      ->check(CLI::Range(1, 100));
  cmd->add_option("--mode", a->names,
                  "draw only modes whose name contains this text (repeatable), e.g. hunting");
  cmd->callback([a] { run_modes(*a); });
}

}  // namespace railstab
