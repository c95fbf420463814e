#include "cli/stability_commands.hpp"

#include "cli/numeric_flags.hpp"
#include "setup/prepare_scene.hpp"
#include "io/file_names.hpp"
#include "io/gnuplot.hpp"
#include "io/json_writer.hpp"
#include "io/output_set.hpp"
#include "model/equations_of_motion.hpp"
#include "report/stability_report.hpp"
#include "stability/speed_analysis.hpp"

#include <cmath>
#include <sstream>
#include <iomanip>
#include <iostream>
#include <memory>

namespace railstab {

namespace {

struct CommonArgs {
  std::string scene;
  SceneOverrides overrides;
  std::string out_dir = "out";
  std::string solver = "auto";
  double hunting_band_hz = 20.0;
  bool plots = true;
};

void add_common(CLI::App* cmd, CommonArgs& a) {
  cmd->add_option("scene", a.scene, "scene file (TOML)")->required()->check(CLI::ExistingFile);
  cmd->add_option("--arc-length", a.overrides.reference_arc_length_m,
                  "arc length (m) of the scene's reference point, e.g. inside an arc for "
                  "steady curving")
      ->check(finite_in(flag_ranges::arc_length_m));
  cmd->add_option("--out", a.out_dir, "output directory")->capture_default_str();
}

void add_solver(CLI::App* cmd, CommonArgs& a) {
  cmd->add_option("--solver", a.solver,
                  "eigen-solver: dense (all modes), arpack (shift-invert near the hunting "
                  "band) or auto (dense below 150 states, ARPACK from there)")
      ->check(CLI::IsMember({"auto", "dense", "arpack"}))
      ->capture_default_str();
  cmd->add_option("--hunting-band", a.hunting_band_hz,
                  "highest mode frequency (Hz) that decides stability; faster unstable modes "
                  "are reported as warnings")
      ->capture_default_str()
      ->check(finite_in(flag_ranges::frequency_hz));
}

StabilityOptions stability_options(const CommonArgs& a) {
  StabilityOptions o;
  o.solver = a.solver == "arpack"  ? EigenSolverKind::arpack
             : a.solver == "dense" ? EigenSolverKind::dense
                                   : EigenSolverKind::automatic;
  o.max_frequency_hz = a.hunting_band_hz;
  return o;
}

// Output names start with the scene name made safe (io/file_names.hpp), so
// a scene called "../evil" still writes inside --out.
std::string stem_for(const Model& m) { return file_stem(m.name); }

// Every coordinate of the steady state must be finite before anything is
// printed or written (an equilibrium printed as "inf mm" was exit 0).
void check_finite_state(const Model& model, double speed_m_per_s, const Eigen::MatrixXd& q6,
                        const Eigen::MatrixXd& qd6) {
  for (Eigen::Index b = 0; b < q6.cols(); ++b)
    for (int c = 0; c < 6; ++c)
      if (!std::isfinite(q6(c, b)) || !std::isfinite(qd6(c, b))) {
        std::ostringstream msg;
        msg << "equilibrium of " << model.name << " at " << speed_m_per_s
            << " m/s: " << model.bodies[size_t(b)].name << '.' << kCoordinateNames[c]
            << " is not finite (position " << q6(c, b) << ", rate " << qd6(c, b)
            << "); no output written";
        throw std::runtime_error(msg.str());
      }
}

// --- equilibrium ---------------------------------------------------------------
void run_equilibrium(const CommonArgs& a) {
  const PreparedScene s = prepare_scene(a.scene, a.overrides);
  const Model& model = s.model;
  EvaluationDetails details;
  rhs(model, s.speed_m_per_s, 0.0, s.equilibrium.state, &details);
  Eigen::MatrixXd q6, qd6;
  model.full_coordinates(0.0, s.speed_m_per_s, s.equilibrium.state, q6, qd6);
  check_finite_state(model, s.speed_m_per_s, q6, qd6);
  OutputSet outputs(a.out_dir);
  // The text for the terminal is collected while the JSON is rendered and
  // shown only once the JSON holds no non-finite value.
  std::ostringstream shown;
  shown << std::setprecision(6) << "equilibrium of " << model.name << " at "
        << s.speed_m_per_s << " m/s: " << s.equilibrium.iterations
        << " Newton iterations, max acceleration residual " << s.equilibrium.max_acceleration
        << "\n";
  outputs.write(stem_for(model) + "_equilibrium.json", [&](std::ostream& out) {
    JsonWriter j(out);
    j.begin_object().field("scene", model.name).field("speed_m_s", s.speed_m_per_s);
    j.field("newton_iterations", s.equilibrium.iterations)
        .field("max_acceleration_residual", s.equilibrium.max_acceleration);
    j.key("bodies").begin_array();
    for (size_t b = 0; b < model.bodies.size(); ++b) {
      j.begin_object().field("name", model.bodies[b].name);
      for (int c = 0; c < 6; ++c) {
        const double offset = q6(c, b) - model.bodies[b].nominal_q(c);
        if (c == int(CoordinateIndex::pitch) && model.bodies[b].wheelset()) {
          j.field("spin_rate_rad_s", qd6(c, b));
          continue;
        }
        j.field(kCoordinateNames[c] + "_offset", offset);
      }
      shown << "  " << std::left << std::setw(10) << model.bodies[b].name << std::right
                << " lateral " << std::setw(12) << q6(1, b) * 1e3 << " mm  yaw " << std::setw(12)
                << q6(5, b) * 1e3 << " mrad  roll " << std::setw(12) << q6(3, b) * 1e3
                << " mrad  vertical offset " << std::setw(12)
                << (q6(2, b) - model.bodies[b].nominal_q(2)) * 1e3 << " mm\n";
      j.key("wheels").begin_array();
      for (const ContactSnapshot& c : details.contacts) {
        if (c.body != int(b)) continue;
        const WheelContact<double>& w = c.wheel;
        j.begin_object()
            .field("side", w.side > 0 ? "left" : "right")
            .field("normal_force_N", w.normal_force_N)
            .field("penetration_m", w.penetration_m)
            .field("rolling_radius_m", w.rolling_radius_m)
            .field("creepage_longitudinal", w.creep_x)
            .field("creepage_lateral", w.creep_y)
            .field("creepage_spin_per_m", w.creep_spin_per_m)
            .field("creep_force_longitudinal_N", w.creep_force_x_N)
            .field("creep_force_lateral_N", w.creep_force_y_N)
            .field("spin_creep_moment_N_m", w.spin_moment_N_m)
            .field("total_force_on_wheelset_I_N_x", w.force_I.x())
            .field("total_force_on_wheelset_I_N_y", w.force_I.y())
            .field("total_force_on_wheelset_I_N_z", w.force_I.z())
            .end_object();
        shown << "      " << (w.side > 0 ? "left " : "right") << " wheel load "
                  << w.normal_force_N << " N, creepages (" << w.creep_x << ", " << w.creep_y
                  << ", " << w.creep_spin_per_m << " 1/m), creep forces (" << w.creep_force_x_N
                  << ", " << w.creep_force_y_N << " N, " << w.spin_moment_N_m << " N m)\n";
      }
      j.end_array().end_object();
    }
    j.end_array().end_object();
  });
  std::cout << shown.str();
  for (const std::string& f : outputs.commit()) std::cout << "wrote " << f << "\n";
}

// --- eigen ---------------------------------------------------------------------
void run_eigen(const CommonArgs& a, double max_hz) {
  const PreparedScene s = prepare_scene(a.scene, a.overrides);
  SpeedStability stability(s.model, s.equilibrium.state, s.speed_m_per_s, stability_options(a));
  const StabilityPoint p = stability.at(s.speed_m_per_s);
  std::cout << s.model.name << " at " << p.speed_m_per_s << " m/s: " << p.linear.A.rows()
            << " states";
  if (!p.linear.removed_states.empty()) {
    std::cout << " (removed cyclic:";
    for (const std::string& r : p.linear.removed_states) std::cout << ' ' << r;
    std::cout << ")";
  }
  std::cout << ", " << p.modes.size() << " eigenvalues (" << eigen_solver_name(p.solver_used)
            << ") in " << p.seconds
            << " s\n";
  std::cout << "  real [1/s]     freq [Hz]   damping    residual   mode\n";
  for (const ModeReport& m : p.modes) {
    if (m.eigenvalue.imag() < 0.0 || m.frequency_hz > max_hz) continue;
    std::cout << "  " << std::setw(12) << m.eigenvalue.real() << std::setw(12) << m.frequency_hz
              << std::setw(11) << m.damping_ratio << std::setw(12) << m.residual << "   "
              << m.name << "\n";
  }
  OutputSet outputs(a.out_dir);
  outputs.write(stem_for(s.model) + "_eigen_" + speed_file_tag(p.speed_m_per_s) + ".json",
                [&](std::ostream& out) {
    JsonWriter j(out);
    j.begin_object().field("scene", s.model.name).field("speed_m_s", p.speed_m_per_s);
    j.field("eigen_solver", eigen_solver_name(p.solver_used)).field("states", int(p.linear.A.rows()));
    j.key("removed_cyclic_states").begin_array();
    for (const std::string& r : p.linear.removed_states) j.value(r);
    j.end_array().key("modes").begin_array();
    for (const ModeReport& m : p.modes)
      j.begin_object()
          .field("real_per_s", m.eigenvalue.real())
          .field("imag_per_s", m.eigenvalue.imag())
          .field("frequency_hz", m.frequency_hz)
          .field("damping_ratio", m.damping_ratio)
          .field("neutral", m.neutral)
          .field("residual", m.residual)
          .field("name", m.name)
          .end_object();
    j.end_array().end_object();
  });
  for (const std::string& f : outputs.commit()) std::cout << "wrote " << f << "\n";
}

// --- critical speed / sweep -----------------------------------------------------------
void run_critical_speed(const CommonArgs& a, CriticalSpeedOptions opt) {
  check_speed_grid(opt.from_m_per_s, opt.to_m_per_s, opt.grid_step_m_per_s);
  if (a.plots) require_gnuplot();  // before the sweep, not after it
  const PreparedScene s = prepare_scene(a.scene, a.overrides);
  opt.stability = stability_options(a);
  opt.progress = [](const std::string& line) { std::cerr << line << "\n"; };
  std::cerr << "critical speed of " << s.model.name << " between " << opt.from_m_per_s
            << " and " << opt.to_m_per_s << " m/s (grid " << opt.grid_step_m_per_s << " m/s)\n";
  const CriticalSpeedResult r = find_critical_speed(s.model, s.equilibrium.state, s.speed_m_per_s, opt);
  const std::string solver =
      r.grid.empty() ? a.solver : eigen_solver_name(r.grid.front().solver_used);
  OutputSet outputs(a.out_dir);
  write_stability_results(s.model, r, outputs, stem_for(s.model), solver, a.plots);
  const std::vector<std::string> written = outputs.commit();
  std::cout << std::setprecision(6);
  if (r.unstable_at_start) {
    std::cout << s.model.name << ": already unstable at " << r.from_m_per_s << " m/s\n";
  } else if (!r.critical_speed_found) {
    const double top = r.grid.back().speed_m_per_s;
    std::cout << s.model.name << ": stable over the whole range analysed " << r.from_m_per_s
              << " - " << top << " m/s\n";
  } else {
    const ModeReport& m = r.at_critical.modes[r.at_critical.least_stable];
    std::cout << s.model.name << ": critical speed " << std::fixed << std::setprecision(2)
              << r.critical_speed_m_per_s << " m/s (" << r.critical_speed_m_per_s * 3.6
              << " km/h)" << std::defaultfloat << std::setprecision(5) << ", frequency "
              << m.frequency_hz << " Hz, mode " << m.name << "\n";
  }
  if (r.partial) std::cout << "partial result: " << r.partial_reason << "\n";
  else if (r.equilibrium_lost_at_m_per_s > 0.0)
    std::cout << "no steady state from " << r.equilibrium_lost_at_m_per_s
              << " m/s: " << r.equilibrium_error << "\n";
  for (const StabilityPoint& p : r.grid)
    if (!p.validity_warning.empty()) {
      std::cout << "warning from " << p.speed_m_per_s << " m/s: " << p.validity_warning << "\n";
      break;
    }
  for (const StabilityPoint& p : r.grid)
    if (!p.unstable_above_band.empty()) {
      const ModeReport& m = p.modes[p.unstable_above_band.front()];
      std::cout << "warning from " << p.speed_m_per_s << " m/s: mode above the hunting band ("
                << opt.stability.max_frequency_hz << " Hz) unstable: " << m.name << " at "
                << m.frequency_hz << " Hz, real part " << m.eigenvalue.real() << " 1/s\n";
      break;
    }
  std::cout << r.evaluations << " speed evaluations in " << r.seconds << " s\n";
  for (const std::string& f : written) std::cout << "wrote " << f << "\n";
}

}  // namespace

void register_stability_commands(CLI::App& app) {
  {
    auto a = std::make_shared<CommonArgs>();
    CLI::App* cmd = app.add_subcommand(
        "equilibrium", "steady rolling / curving equilibrium: offsets, wheel loads, creepages");
    add_common(cmd, *a);
    cmd->add_option("--speed", a->overrides.speed_m_per_s, "speed V in m/s")
        ->check(finite_in(flag_ranges::speed_m_per_s));
    cmd->callback([a] { run_equilibrium(*a); });
  }
  {
    auto a = std::make_shared<CommonArgs>();
    auto max_hz = std::make_shared<double>(30.0);
    CLI::App* cmd = app.add_subcommand("eigen", "eigenvalues and modes at one speed");
    add_common(cmd, *a);
    add_solver(cmd, *a);
    cmd->add_option("--speed", a->overrides.speed_m_per_s, "speed V in m/s")
        ->check(finite_in(flag_ranges::speed_m_per_s));
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
    add_common(cmd, *a);
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
    cmd->add_flag("!--no-plots", a->plots, "do not run gnuplot (data, JSON and report only)");
    cmd->callback([a, opt] { run_critical_speed(*a, *opt); });
  }
}

}  // namespace railstab
