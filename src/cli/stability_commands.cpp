#include "cli/stability_commands.hpp"

#include "cli/model_warnings.hpp"
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
#include <railstab/report/quasi_linear_report.hpp>
#include <railstab/stability/quasi_linear_critical_speed.hpp>
#include <railstab/stability/speed_analysis.hpp>

#include <cmath>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

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

// Output names start with the scene file's stem made safe
// (io/file_names.hpp), so two copies of a scene keep their own outputs, and
// a run in a curve carries its arc length (report/run_conditions.hpp): it
// never overwrites the tangent run's files.
std::string stem_for(const CommonArgs& a, const Model& m) { return steady_state_file_stem(a.scene, m); }

// --- equilibrium ---------------------------------------------------------------
void run_equilibrium(const CommonArgs& a) {
  const PreparedScene s = prepare_command_scene(a);
  OutputSet outputs(a.out_dir);
  const std::string summary = write_equilibrium_results(s, outputs, stem_for(a, s.model));
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
  write_eigen_json(s.model, p, full_mode_shapes(s.model, p), outputs, stem_for(a, s.model));
  list_written(outputs.commit(), std::cout);
}

// --- quasi-linear critical speed by amplitude -------------------------------------------
// critical-speed --amplitude A / --amplitudes FROM:TO:STEP (metres; TO may be
// "flange": the flange-contact shift of the scene's profiles).
struct QuasiLinearArgs {
  std::optional<double> amplitude_m;
  std::string amplitudes;
};

inline constexpr int kMaxAmplitudes = 1000;

// FROM:TO:STEP in metres, each finite and positive (TO also "flange"); the
// amplitudes FROM, FROM + STEP, ... up to TO (within STEP / 1000).
std::vector<double> parse_amplitudes(const std::string& text, double flange_m) {
  auto fail = [&](const std::string& why) {
    throw std::invalid_argument("--amplitudes: expected FROM:TO:STEP in metres (0 < FROM <= TO, "
                                "STEP > 0, TO a number or 'flange'), got '" + text + "': " + why);
  };
  const std::vector<std::string> parts = colon_fields(text);
  if (parts.size() != 3) fail("not three fields");
  auto number = [&](const std::string& p, const char* what) {
    double v = 0;
    if (read_field_number(p, v) != FieldNumber::ok || !std::isfinite(v) || !(v > 0))
      fail(std::string(what) + " is not a finite positive number");
    return v;
  };
  const double from = number(parts[0], "FROM"), step = number(parts[2], "STEP");
  double to = 0;
  if (parts[1] == "flange") {
    if (!(flange_m > 0)) fail("the scene's profiles have no flange contact (or no profile contact)");
    to = flange_m;
  } else {
    to = number(parts[1], "TO");
  }
  if (!(from <= to)) fail("FROM above TO");
  if ((to - from) / step + 1 > kMaxAmplitudes) fail("more than " + std::to_string(kMaxAmplitudes) + " amplitudes");
  std::vector<double> a;
  for (int i = 0;; ++i) {
    const double v = from + i * step;
    if (v > to + 1e-3 * step) break;
    a.push_back(v);
  }
  return a;
}

// The builder's range error under the flag's name.
template <class F> auto with_flag(const char* flag, F&& f) {
  try {
    return f();
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string(flag) + ": " + e.what());
  }
}

void run_quasi_linear_amplitude(const CommonArgs& a, const CriticalSpeedOptions& opt,
                                const PreparedScene& s, double amplitude_m) {
  std::cerr << "quasi-linear critical speed of " << s.model.name << " at amplitude "
            << amplitude_m * 1e3 << " mm between " << opt.from_m_per_s << " and "
            << opt.to_m_per_s << " m/s\n";
  const QuasiLinearModelBuilder builder(s.model, s.equilibrium.state);
  const QuasiLinearModel q = with_flag("--amplitude", [&] { return builder.at(amplitude_m); });
  QuasiLinearCriticalSpeed r;
  r.amplitude_m = amplitude_m;
  r.wheelsets = q.wheelsets;
  r.has_profile_contact = q.has_profile_contact;
  r.result = find_critical_speed(q.model, s.equilibrium.state, s.speed_m_per_s, opt);
  const std::string solver =
      r.result.grid.empty() ? a.solver : eigen_solver_name(r.result.grid.front().solver_used);
  OutputSet outputs(a.out_dir);
  write_stability_results(s.model, r.result, outputs, stem_for(a, s.model) + "_quasi_linear", solver,
                          a.plots, opt.stability.max_frequency_hz, nullptr, &r);
  const std::vector<std::string> written = outputs.commit();
  std::cout << "quasi-linear contact at amplitude " << amplitude_m * 1e3 << " mm";
  if (!r.wheelsets.empty())
    std::cout << " (equivalent conicity of " << r.wheelsets.front().body << ": "
              << r.wheelsets.front().equivalent_conicity << ")";
  else
    std::cout << " (no profile contact: the plain model)";
  std::cout << "\n";
  print_critical_speed_summary(std::cout, s.model, r.result, opt.stability.max_frequency_hz);
  list_written(written, std::cout);
}

void run_quasi_linear_curve(const CommonArgs& a, const CriticalSpeedOptions& opt,
                            const PreparedScene& s, const std::string& amplitudes_text) {
  const QuasiLinearModelBuilder builder(s.model, s.equilibrium.state);
  const std::vector<double> amplitudes =
      parse_amplitudes(amplitudes_text, builder.flange_contact_amplitude_m());
  if (builder.has_profile_contact() && amplitudes.back() > builder.max_amplitude_m()) {
    std::ostringstream msg;
    msg << "--amplitudes: the largest amplitude " << amplitudes.back() * 1e3 << " mm exceeds "
        << builder.max_amplitude_m() * 1e3
        << " mm (the contact table's lateral range less 1 mm, less the steady shift)";
    throw std::invalid_argument(msg.str());
  }
  std::cerr << "quasi-linear critical speed of " << s.model.name << " at " << amplitudes.size()
            << " amplitudes " << amplitudes.front() * 1e3 << " .. " << amplitudes.back() * 1e3
            << " mm, between " << opt.from_m_per_s << " and " << opt.to_m_per_s << " m/s\n";
  CriticalSpeedOptions plain_opt = opt;
  plain_opt.progress = nullptr;
  plain_opt.mode_shapes_at_critical = false;
  const CriticalSpeedResult plain =
      find_critical_speed(s.model, s.equilibrium.state, s.speed_m_per_s, plain_opt);
  const QuasiLinearCurve curve = quasi_linear_critical_speed_curve(
      builder, s.equilibrium.state, s.speed_m_per_s, amplitudes, opt,
      [](int i, int n, double A) {
        std::cerr << "  amplitude " << i << "/" << n << ": " << A * 1e3 << " mm done\n";
      });
  OutputSet outputs(a.out_dir);
  write_quasi_linear_curve(s.model, curve, plain.critical_speed_found ? plain.critical_speed_m_per_s : 0.0,
                           opt.from_m_per_s, opt.to_m_per_s, outputs, stem_for(a, s.model), a.plots);
  const std::vector<std::string> written = outputs.commit();
  std::cout << s.model.name << ": quasi-linear critical speed by amplitude (linear: ";
  if (plain.critical_speed_found) std::cout << plain.critical_speed_m_per_s << " m/s)\n";
  else std::cout << "none in the range)\n";
  for (const QuasiLinearCurvePoint& p : curve.points) {
    std::cout << "  A = " << p.amplitude_m * 1e3 << " mm, conicity " << p.equivalent_conicity << ": ";
    if (p.critical_speed_found) std::cout << p.critical_speed_m_per_s << " m/s, " << p.frequency_Hz << " Hz\n";
    else std::cout << p.note << "\n";
  }
  std::cout << "CPU " << curve.cpu_seconds << " s for the curve\n";
  list_written(written, std::cout);
}

// --- critical speed / sweep -----------------------------------------------------------
void run_critical_speed(const CommonArgs& a, CriticalSpeedOptions opt, const QuasiLinearArgs& ql = {}) {
  check_speed_grid(opt.from_m_per_s, opt.to_m_per_s, opt.grid_step_m_per_s);
  if (ql.amplitude_m && !ql.amplitudes.empty())
    throw std::invalid_argument("--amplitude and --amplitudes: give one of them");
  if (a.plots) require_gnuplot();  // before the sweep, not after it
  const PreparedScene s = prepare_command_scene(a);
  if (ql.amplitude_m || !ql.amplitudes.empty()) {
    opt.stability = stability_options(a);
    opt.progress = [](const std::string& line) { std::cerr << line << "\n"; };
    if (ql.amplitude_m) run_quasi_linear_amplitude(a, opt, s, *ql.amplitude_m);
    else run_quasi_linear_curve(a, opt, s, ql.amplitudes);
    return;
  }
  opt.stability = stability_options(a);
  opt.progress = [](const std::string& line) { std::cerr << line << "\n"; };
  std::cerr << "critical speed of " << s.model.name << " between " << opt.from_m_per_s
            << " and " << opt.to_m_per_s << " m/s (grid " << opt.grid_step_m_per_s << " m/s)\n";
  const CriticalSpeedResult r = find_critical_speed(s.model, s.equilibrium.state, s.speed_m_per_s, opt);
  print_speed_range_warnings_to_stderr(s, r, opt.to_m_per_s);
  const std::string solver =
      r.grid.empty() ? a.solver : eigen_solver_name(r.grid.front().solver_used);
  // The Hopf point's criticality (first Lyapunov coefficient, kind), or why
  // it is not computed (profile contact, no oscillatory crossing).
  const HopfAssessment hopf = assess_hopf(s.model, r);
  OutputSet outputs(a.out_dir);
  write_stability_results(s.model, r, outputs, stem_for(a, s.model), solver, a.plots,
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
    auto ql = std::make_shared<QuasiLinearArgs>();
    if (!is_sweep) {
      cmd->add_option("--amplitude", ql->amplitude_m,
                      "quasi-linear critical speed: the profile contacts replaced by their "
                      "harmonic linearisation at this wheelset lateral amplitude (m, e.g. 0.003); "
                      "outputs <scene>_quasi_linear_*")
          ->check(finite_in(flag_ranges::wheelset_amplitude_m));
      cmd->add_option("--amplitudes", ql->amplitudes,
                      "the quasi-linear critical speed over amplitudes FROM:TO:STEP (m; TO may be "
                      "'flange', the flange-contact shift), e.g. 0.0001:flange:0.0001: curve "
                      "V_c(A) as CSV, JSON and plot");
    }
    cmd->callback([a, opt, ql] { run_critical_speed(*a, *opt, *ql); });
  }
}

}  // namespace railstab
