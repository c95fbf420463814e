#include <railstab/report/bifurcation_report.hpp>

#include <railstab/io/csv.hpp>
#include <railstab/io/gnuplot.hpp>
#include <railstab/io/json_writer.hpp>
#include <railstab/report/markdown_text.hpp>
#include <railstab/report/run_conditions.hpp>

#include <algorithm>
#include <cmath>
#include <complex>
#include <iomanip>
#include <limits>
#include <sstream>

namespace railstab {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The shooting's method and tolerances, as the JSON and the Markdown state them.
const char* kMethod =
    "single shooting: Newton on (start, period, speed) with the exact monodromy matrix from "
    "CVODES forward sensitivities (BDF, AD Jacobian); pseudo-arclength continuation in the "
    "(speed, excursion) plane; Floquet multipliers = eigenvalues of the monodromy matrix";

double amplitude_of(const PeriodicOrbit& o, int state) {
  return state >= 0 ? o.amplitude(state) : kNaN;
}

bool has_linear_critical(const BifurcationResult& r) { return r.linear.critical_speed_found; }

// "supercritical (first Lyapunov coefficient)", "subcritical (side of the
// first orbits; profile contact)": where the kind comes from.
std::string hopf_kind_source(const BifurcationResult& r) {
  if (r.hopf_kind.empty()) return "";
  return r.hopf_computed ? "first_lyapunov_coefficient" : "first_orbits_side";
}

void write_json_number_or_null(JsonWriter& j, const std::string& key, double v) {
  if (std::isfinite(v))
    j.field(key, v);
  else
    j.key(key).null();
}

void write_orbit_json(JsonWriter& j, const PeriodicOrbit& o, const BifurcationResult& r) {
  const std::complex<double> mu = o.critical_multiplier;
  j.begin_object()
      .field("speed_m_per_s", o.speed_m_per_s)
      .field("period_s", o.period_s)
      .field("frequency_Hz", 1.0 / o.period_s)
      .field("excursion_m", o.start(r.coords.amplitude_state))
      .field("amplitude_m", o.amplitude(r.coords.amplitude_state))
      .field("stable", o.stable)
      .field("largest_multiplier_modulus", std::abs(mu))
      .field("largest_multiplier_real", mu.real())
      .field("largest_multiplier_imag", mu.imag())
      .field("trivial_multiplier_error", o.trivial_multiplier_error)
      .field("periodicity_residual", o.periodicity_residual)
      .field("newton_iterations", o.newton_iterations)
      .field("integration_steps", double(o.integration_steps))
      .field("jacobian_evaluations", double(o.jacobian_evaluations))
      .field("cpu_s", o.cpu_seconds);
  j.key("wheelsets").begin_array();
  for (const WheelsetOrbitStates& w : r.wheelsets) {
    j.begin_object().field("name", w.name);
    write_json_number_or_null(j, "lateral_amplitude_m", amplitude_of(o, w.lateral_state));
    write_json_number_or_null(j, "yaw_amplitude_rad", amplitude_of(o, w.yaw_state));
    j.end_object();
  }
  j.end_array().end_object();
}

void write_branch_json(JsonWriter& j, const BranchResult& b, const BifurcationResult& r) {
  j.begin_object().field("origin", b.origin).field("started", b.error.empty());
  if (b.error.empty())
    j.key("not_started_reason").null().field("stop_reason", b.branch.stop_reason);
  else
    j.field("not_started_reason", b.error).key("stop_reason").null();
  j.field("orbit_count", int(b.branch.orbits.size()))
      .field("failed_correctors", b.branch.failed_correctors)
      .field("cpu_s", b.branch.cpu_seconds);
  j.key("orbits").begin_array();
  for (const PeriodicOrbit& o : b.branch.orbits) write_orbit_json(j, o, r);
  j.end_array();
  j.key("bifurcations").begin_array();
  for (const OrbitBifurcation& f : b.branch.bifurcations)
    j.begin_object()
        .field("kind", orbit_bifurcation_name(f.kind))
        .field("speed_m_per_s", f.speed_m_per_s)
        .field("amplitude_m", f.amplitude)
        .field("after_orbit", f.after_orbit)
        .field("multiplier_real", f.multiplier.real())
        .field("multiplier_imag", f.multiplier.imag())
        .end_object();
  j.end_array().end_object();
}

void write_json(std::ostream& out, const Model& model, const BifurcationResult& r,
                const BifurcationRunInfo& info, const RunConditions& conditions) {
  JsonWriter j(out);
  j.begin_object().field("scene", model.name).field("scene_file", model.source_path);
  std::vector<double> speeds;
  if (has_linear_critical(r)) speeds.push_back(r.linear.critical_speed_m_per_s);
  write_conditions_json(j, conditions, speeds);
  j.field("from_m_per_s", r.from_m_per_s)
      .field("to_m_per_s", r.to_m_per_s)
      .field("max_amplitude_m", r.max_amplitude_m)
      .field("eigen_solver", info.eigen_solver)
      .field("hunting_band_Hz", info.hunting_band_hz);
  if (r.cycle_speed_m_per_s > 0.0)
    j.field("cycle_speed_m_per_s", r.cycle_speed_m_per_s);
  else
    j.key("cycle_speed_m_per_s").null();
  j.field("cycle_speed_default", r.cycle_speed_default);
  j.key("cycle_speeds_not_periodic_m_per_s").begin_array();
  for (double v : r.cycle_speeds_not_periodic_m_per_s) j.value(v);
  j.end_array();
  j.field("cycle_direction", std::string(r.cycle_branch_upwards ? "up" : "down"));
  if (r.no_default_cycle_reason.empty())
    j.key("no_cycle_branch_reason").null();
  else
    j.field("no_cycle_branch_reason", r.no_default_cycle_reason);
  // The headline: both critical speeds and their ratio.
  if (has_linear_critical(r))
    j.field("linear_critical_speed_m_per_s", r.linear.critical_speed_m_per_s)
        .field("linear_critical_speed_tolerance_m_per_s", r.linear.speed_tolerance_m_per_s);
  else
    j.key("linear_critical_speed_m_per_s").null().key("linear_critical_speed_tolerance_m_per_s").null();
  j.field("linear_verdict", r.linear.critical_speed_found
                                ? std::string("critical_speed_found")
                                : r.linear.unstable_at_start ? std::string("unstable_at_start")
                                                             : std::string("no_critical_speed_in_range"));
  write_json_number_or_null(j, "nonlinear_critical_speed_m_per_s",
                            r.nonlinear.found ? r.nonlinear.speed_m_per_s : kNaN);
  write_json_number_or_null(j, "nonlinear_to_linear_critical_speed_ratio", nonlinear_to_linear_ratio(r));
  j.field("nonlinear_critical_speed_bound", stable_bound_name(r.nonlinear.bound));
  write_json_number_or_null(j, "lowest_stable_orbit_speed_m_per_s",
                            r.nonlinear.bound != StableBound::none ? r.nonlinear.lowest_stable_speed_m_per_s
                                                                   : kNaN);
  j.field("nonlinear_critical_speed_note", r.nonlinear.explanation);
  if (r.hopf_kind.empty())
    j.key("hopf_kind").null().key("hopf_kind_source").null();
  else
    j.field("hopf_kind", r.hopf_kind).field("hopf_kind_source", hopf_kind_source(r));
  if (r.hopf_assessment.computed)
    j.field("first_lyapunov_coefficient", r.hopf_assessment.result.first_lyapunov_coefficient);
  else
    j.key("first_lyapunov_coefficient").null();
  j.key("hopf").begin_object().field("computed", r.hopf_assessment.computed);
  if (r.hopf_assessment.computed)
    j.key("not_computed_reason").null();
  else
    j.field("not_computed_reason", r.hopf_assessment.not_computed_reason);
  j.field("description", describe_hopf(r.hopf_assessment)).end_object();
  j.field("profile_contact", r.profile_contact)
      .field("amplitude_state", r.amplitude_state_name)
      .field("method", std::string(kMethod))
      .field("states", int(r.state_names.size()));
  j.key("branches").begin_array();
  for (const BranchResult& b : r.branches) write_branch_json(j, b, r);
  j.end_array();
  j.field("cpu_s", r.cpu_seconds).end_object();
}

void write_csv(std::ostream& out, const BifurcationResult& r) {
  out << "branch,origin,orbit,speed_m_per_s,period_s,frequency_Hz,stable,largest_multiplier_modulus";
  for (const WheelsetOrbitStates& w : r.wheelsets)
    out << "," << csv_field(w.name + ".y_amplitude_m") << "," << csv_field(w.name + ".yaw_amplitude_rad");
  out << "\n" << std::setprecision(12);
  for (size_t b = 0; b < r.branches.size(); ++b)
    for (size_t k = 0; k < r.branches[b].branch.orbits.size(); ++k) {
      const PeriodicOrbit& o = r.branches[b].branch.orbits[k];
      auto put = [&](double v, const char* column) {
        out << ',';
        put_csv_number(out, v, [&] {
          std::ostringstream what;
          what << "bifurcation CSV column " << column << " of orbit " << k + 1 << " of branch "
               << b + 1;
          return what.str();
        });
      };
      out << b + 1 << ',' << csv_field(r.branches[b].origin) << ',' << k + 1;
      put(o.speed_m_per_s, "speed_m_per_s");
      put(o.period_s, "period_s");
      put(1.0 / o.period_s, "frequency_Hz");
      out << ',' << (o.stable ? 1 : 0);
      put(std::abs(o.critical_multiplier), "largest_multiplier_modulus");
      // A coordinate that is not free has no amplitude: an empty field.
      for (const WheelsetOrbitStates& w : r.wheelsets) {
        for (int s : {w.lateral_state, w.yaw_state}) {
          if (s >= 0)
            put(o.amplitude(s), "amplitude");
          else
            out << ',';
        }
      }
      out << "\n";
    }
}

// The speed range the diagram shows: the orbits and the linear critical
// speed with a margin (a branch may span a hundredth of the search range),
// inside the searched range.
void diagram_range(const BifurcationResult& r, double& lo, double& hi) {
  lo = std::numeric_limits<double>::infinity(), hi = -lo;
  auto take = [&](double v) { lo = std::min(lo, v), hi = std::max(hi, v); };
  if (has_linear_critical(r)) take(r.linear.critical_speed_m_per_s);
  if (r.nonlinear.bound != StableBound::none) take(r.nonlinear.lowest_stable_speed_m_per_s);
  for (const BranchResult& b : r.branches)
    for (const PeriodicOrbit& o : b.branch.orbits) take(o.speed_m_per_s);
  if (!(lo <= hi)) lo = r.from_m_per_s, hi = r.to_m_per_s;
  const double pad = std::max(0.15 * (hi - lo), 0.002 * std::max(std::abs(hi), 1.0));
  lo = std::max(r.from_m_per_s, lo - pad), hi = std::min(r.to_m_per_s, hi + pad);
  if (!(hi > lo)) hi = lo + 1.0;
}

struct DiagramBlock {
  std::string title;  // "" : no key entry
  bool stable = true;
  int colour = 0;     // 0: the steady state (black), else the branch number
};

// One data block per run of equally stable orbits of a branch (sharing the
// end point with the next, so the curve is continuous), and the steady state
// on the axis (stable below V_c, unstable above). Amplitudes in mm.
std::vector<DiagramBlock> write_diagram_data(std::ostream& out, const BifurcationResult& r,
                                             double lo, double hi) {
  std::vector<DiagramBlock> blocks;
  out << std::setprecision(12);
  auto steady = [&](double a, double b, bool stable) {
    out << "# steady state, " << (stable ? "stable" : "unstable") << "\n"
        << a << " 0\n" << b << " 0\n\n\n";
    blocks.push_back({stable ? "steady state, stable" : "steady state, unstable", stable, 0});
  };
  if (has_linear_critical(r)) {
    const double vc = std::clamp(r.linear.critical_speed_m_per_s, lo, hi);
    steady(lo, vc, true);
    steady(vc, hi, false);
  } else if (r.linear.stable_in_range) {
    steady(lo, hi, true);
  } else if (r.linear.unstable_at_start) {
    steady(lo, hi, false);
  }
  const int ia = r.coords.amplitude_state;
  for (size_t b = 0; b < r.branches.size(); ++b) {
    const std::vector<PeriodicOrbit>& o = r.branches[b].branch.orbits;
    bool titled[2] = {false, false};
    size_t k = 0;
    while (k < o.size()) {
      const bool stable = o[k].stable;
      size_t end = k;
      while (end + 1 < o.size() && o[end + 1].stable == stable) ++end;
      out << "# branch " << b + 1 << " (" << r.branches[b].origin << "), "
          << (stable ? "stable" : "unstable") << " orbits " << k + 1 << " to " << end + 1 << "\n";
      for (size_t i = k; i <= std::min(end + 1, o.size() - 1); ++i)
        out << o[i].speed_m_per_s << ' ' << 1e3 * o[i].amplitude(ia) << "\n";
      out << "\n\n";
      std::string title;
      if (!titled[stable]) {
        title = "branch from the " +
                std::string(r.branches[b].origin == "hopf" ? "Hopf point" : "time-domain cycle") +
                (stable ? ", stable orbits" : ", unstable orbits");
        titled[stable] = true;
      }
      blocks.push_back({title, stable, int(b) + 1});
      k = end + 1;
    }
  }
  return blocks;
}

std::vector<std::string> plot_diagram(OutputSet& outputs, const std::string& stem,
                                      const BifurcationResult& r, const std::string& title) {
  double lo = 0.0, hi = 0.0;
  diagram_range(r, lo, hi);
  const std::string data = stem + "_bifurcation_diagram.dat";
  std::vector<DiagramBlock> blocks;
  outputs.write(data, [&](std::ostream& out) { blocks = write_diagram_data(out, r, lo, hi); });
  double max_mm = 0.0;
  for (const BranchResult& b : r.branches)
    for (const PeriodicOrbit& o : b.branch.orbits)
      max_mm = std::max(max_mm, 1e3 * o.amplitude(r.coords.amplitude_state));
  if (!(max_mm > 0.0)) max_mm = 1.0;
  const std::string script = stem + "_bifurcation_diagram.gp";
  const std::string png = stem + "_bifurcation_diagram.png", svg = stem + "_bifurcation_diagram.svg";
  const std::string png_terminal = "set terminal pngcairo size 1200,700 font 'Sans,10' noenhanced\n";
  const std::string svg_terminal = "set terminal svg size 1200,700 dynamic font 'Sans,10' noenhanced\n";
  static const char* colours[] = {"#0060ad", "#dd181f", "#009e73", "#e69f00"};
  outputs.write(script, [&](std::ostream& gp) {
    gp << "# Run from the output folder: gnuplot " << script << "\n"
       << "# Bifurcation diagram: the half peak-to-peak amplitude of " << r.amplitude_state_name
       << " on each periodic orbit against speed;\n# stable orbits solid, unstable dashed; the "
          "steady state on the axis.\n"
       << std::setprecision(10) << png_terminal << "set output " << gnuplot_text(png) << "\n"
       << "set grid\nset key inside left top box opaque noenhanced font ',9'\n"
       << "set title " << gnuplot_text(title + ": bifurcation diagram (periodic orbits by shooting)")
       << "\nset xlabel 'speed [m/s]'\nset ylabel "
       << gnuplot_text(r.amplitude_state_name + " amplitude, half peak-to-peak [mm]") << "\n"
       << "set xrange [" << lo << ":" << hi << "]\nset yrange [" << -0.04 * max_mm << ":"
       << 1.25 * max_mm << "]\n";
    // Both critical speeds: a vertical line each, labelled inside the frame.
    if (has_linear_critical(r)) {
      const double vc = r.linear.critical_speed_m_per_s;
      gp << "set arrow 1 from " << vc << ", graph 0 to " << vc
         << ", graph 1 nohead dt 3 lw 1.5 lc 'black'\n"
         << "set label 1 " << gnuplot_text([&] {
              std::ostringstream s;
              s << "linear critical speed " << std::fixed << std::setprecision(2) << vc << " m/s";
              return s.str();
            }()) << " at " << vc
         // Beside the line on the side with room: left of it in the right
         // half of the frame, else right of it (a line near the left edge
         // would push its label out of the frame).
         << ((vc - lo) > 0.5 * (hi - lo) ? ", graph 0.62 right offset -0.5,0 front\n"
                                          : ", graph 0.62 left offset 0.5,0 front\n");
    }
    if (r.nonlinear.found) {
      const double vn = r.nonlinear.speed_m_per_s;
      gp << "set arrow 2 from " << vn << ", graph 0 to " << vn
         << ", graph 1 nohead dt 4 lw 1.5 lc 'dark-green'\n"
         << "set label 2 " << gnuplot_text([&] {
              std::ostringstream s;
              s << "nonlinear critical speed " << std::fixed << std::setprecision(2) << vn
                << " m/s (" << stable_bound_name(r.nonlinear.bound) << ")";
              return s.str();
            }()) << " at " << vn << ", graph 0.54 left offset 0.5,0 tc 'dark-green' front\n";
    } else {
      gp << "set label 2 'nonlinear critical speed: not found (see the report)' at graph 0.98, "
            "graph 0.54 right tc 'dark-green' front\n";
    }
    gp << "plot ";
    for (size_t k = 0; k < blocks.size(); ++k) {
      const DiagramBlock& b = blocks[k];
      const std::string colour = b.colour == 0 ? "black" : colours[size_t(b.colour - 1) % 4];
      gp << (k ? ", \\\n     " : "") << gnuplot_path(data) << " index " << k
         << " using 1:2 with linespoints pt 7 ps " << (b.colour == 0 ? "0" : "0.5") << " lw "
         << (b.colour == 0 ? 3 : 2) << " dt " << (b.stable ? 1 : 2) << " lc rgb '" << colour
         << "' " << (b.title.empty() ? std::string("notitle") : "title " + gnuplot_text(b.title));
    }
    if (blocks.empty()) gp << "NaN notitle";
    gp << "\n" << svg_terminal << "set output " << gnuplot_text(svg) << "\nreplot\nunset output\n";
  });
  outputs.add(png);
  outputs.add(svg);
  run_gnuplot(script, outputs.staging_dir(), {png, svg});
  return {png};
}

std::string speed_text(double v) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(2) << v << " m/s";
  return s.str();
}

void write_markdown(std::ostream& md, const Model& model, const BifurcationResult& r,
                    const BifurcationRunInfo& info, const RunConditions& conditions,
                    const BifurcationFiles& files) {
  md << std::setprecision(6);
  md << "# Bifurcation analysis: " << md_text(model.name) << "\n\n"
     << "Scene `" << md_text(model.source_path) << "`, speeds " << r.from_m_per_s << " to "
     << r.to_m_per_s << " m/s, orbit amplitude limit " << 1e3 * r.max_amplitude_m << " mm of `"
     << md_text(r.amplitude_state_name) << "`, " << r.state_names.size()
     << " states in the orbits (the model's state without the wheelsets' spin angles).\n\n"
     << conditions_markdown(conditions) << "\n";
  md << "| result | value |\n|---|---|\n";
  md << "| linear critical speed | "
     << (has_linear_critical(r) ? "**" + speed_text(r.linear.critical_speed_m_per_s) + "**" +
                                      " (bracketed to " + [&] {
                                        std::ostringstream s;
                                        s << r.linear.speed_tolerance_m_per_s;
                                        return s.str();
                                      }() + " m/s)"
                                : std::string(r.linear.unstable_at_start
                                                  ? "none: unstable at the start of the range"
                                                  : "none in the range"))
     << " |\n";
  // From l1 the description says it all; with profile contact the kind
  // comes from the first orbits and the description says why l1 is not.
  md << "| Hopf bifurcation | ";
  if (r.hopf_computed)
    md << md_text(describe_hopf(r.hopf_assessment));
  else
    md << (r.hopf_kind.empty() ? std::string("kind not known")
                               : r.hopf_kind + " (from the side of the critical speed where the "
                                               "first orbit lies)")
       << "; first Lyapunov coefficient " << md_text(describe_hopf(r.hopf_assessment));
  md << " |\n";
  // The explanation opens with "<speed> m/s, " or with "not found: ": the
  // table puts that part in bold.
  const std::string& e = r.nonlinear.explanation;
  const size_t head = r.nonlinear.found ? e.find(", ") : e.rfind("not found: ", 0) == 0 ? 9 : std::string::npos;
  md << "| nonlinear critical speed | "
     << (head == std::string::npos ? md_text(e)
                                   : "**" + md_text(e.substr(0, head)) + "**" + md_text(e.substr(head)))
     << " |\n";
  const double ratio = nonlinear_to_linear_ratio(r);
  if (std::isfinite(ratio)) md << "| nonlinear / linear | " << std::setprecision(5) << ratio << " |\n";
  md << std::setprecision(6) << "\n";

  md << "## What was computed\n\n"
     << "Periodic (hunting) orbits of the nonlinear model by " << kMethod << ". An orbit is "
     << "stable when every Floquet multiplier but the trivial one (1, along the flow) has modulus "
     << "below 1. The nonlinear critical speed is the lowest speed at which a stable hunting "
     << "orbit exists on the computed branches: a vehicle above it can hunt on that orbit after "
     << "a large enough disturbance, even below the linear critical speed. It says nothing about "
     << "branches not computed (other starts, amplitudes above the limit, speeds outside the "
     << "range), and the orbits are those of the model: knife-edge or linear contact has no "
     << "flange.\n\n";
  if (!r.no_default_cycle_reason.empty()) md << md_text(r.no_default_cycle_reason) << ".\n\n";
  for (const BranchResult& b : r.branches) {
    md << "### Branch from the " << (b.origin == "hopf" ? "Hopf point" : "time-domain cycle");
    if (b.origin == "time_domain") {
      md << " at " << speed_text(r.cycle_speed_m_per_s);
      if (r.cycle_speed_default) {
        md << " (the default start on profile contact: " << kDefaultCycleSpeedRatio
           << " x the linear critical speed";
        const std::vector<double>& left = r.cycle_speeds_not_periodic_m_per_s;
        if (!left.empty()) {
          md << ", times " << kDefaultStartLowering << " each time the settled run was not periodic to "
             << 100.0 * kSettledCycleSpreadLimit << " %: at";
          for (size_t k = 0; k < left.size(); ++k) md << (k ? "," : "") << " " << speed_text(left[k]);
        }
        md << ")";
      }
      md << ", followed " << (r.cycle_branch_upwards ? "upwards" : "downwards") << " in speed first";
    }
    md << "\n\n";
    if (!b.error.empty()) {
      md << "Not started: " << md_text(b.error) << "\n\n";
      continue;
    }
    const std::vector<PeriodicOrbit>& o = b.branch.orbits;
    md << o.size() << " orbits, " << b.branch.failed_correctors << " failed correctors (step halved), "
       << b.branch.cpu_seconds << " s CPU; stopped: " << md_text(b.branch.stop_reason) << ".\n\n";
    for (const OrbitBifurcation& f : b.branch.bifurcations)
      md << "- " << orbit_bifurcation_name(f.kind) << " at " << speed_text(f.speed_m_per_s) << ", amplitude "
         << 1e3 * f.amplitude << " mm (between orbits " << f.after_orbit + 1 << " and " << f.after_orbit + 2
         << ")\n";
    if (b.branch.bifurcations.empty()) md << "- no fold, period doubling or torus point detected\n";
    md << "\n| orbit | speed [m/s] | period [s] | frequency [Hz] | " << md_text(r.amplitude_state_name)
       << " amplitude [mm] | largest multiplier | stable |\n|---|---|---|---|---|---|---|\n";
    for (size_t k = 0; k < o.size(); ++k)
      md << "| " << k + 1 << " | " << std::setprecision(8) << o[k].speed_m_per_s << " | "
         << std::setprecision(6) << o[k].period_s << " | " << 1.0 / o[k].period_s << " | "
         << 1e3 * o[k].amplitude(r.coords.amplitude_state) << " | " << std::setprecision(9)
         << std::abs(o[k].critical_multiplier) << std::setprecision(6) << " | " << (o[k].stable ? "yes" : "no") << " |\n";
    md << "\n";
  }
  for (const std::string& png : files.plots) md << "![bifurcation diagram](" << png << ")\n\n";
  md << "Data: `" << files.json << "` (every orbit with the amplitudes of every wheelset's lateral "
     << "displacement and yaw), `" << files.csv << "`. CPU time " << r.cpu_seconds << " s.\n";
}

}  // namespace

double nonlinear_to_linear_ratio(const BifurcationResult& r) {
  if (!r.nonlinear.found || !has_linear_critical(r) || !(r.linear.critical_speed_m_per_s > 0.0))
    return kNaN;
  return r.nonlinear.speed_m_per_s / r.linear.critical_speed_m_per_s;
}

std::vector<std::string> bifurcation_file_names(const std::string& stem) {
  return {stem + "_bifurcation.json",         stem + "_bifurcation_branches.csv",
          stem + "_bifurcation.md",           stem + "_bifurcation_diagram.dat",
          stem + "_bifurcation_diagram.gp",   stem + "_bifurcation_diagram.png",
          stem + "_bifurcation_diagram.svg"};
}

BifurcationFiles write_bifurcation_results(const Model& model, const BifurcationResult& result,
                                           const BifurcationRunInfo& info, OutputSet& outputs,
                                           const std::string& stem, bool plots) {
  for (const std::string& name : bifurcation_file_names(stem)) outputs.replaces(name);
  const RunConditions conditions = run_conditions(model);
  BifurcationFiles files;
  files.json = stem + "_bifurcation.json";
  outputs.write(files.json, [&](std::ostream& out) { write_json(out, model, result, info, conditions); });
  files.csv = stem + "_bifurcation_branches.csv";
  outputs.write(files.csv, [&](std::ostream& out) { write_csv(out, result); });
  if (plots) files.plots = plot_diagram(outputs, stem, result, model.name);
  files.markdown = stem + "_bifurcation.md";
  outputs.write(files.markdown,
                [&](std::ostream& out) { write_markdown(out, model, result, info, conditions, files); });
  return files;
}

void print_bifurcation_summary(std::ostream& out, const Model& model, const BifurcationResult& r) {
  out << model.name << ": linear critical speed "
      << (has_linear_critical(r) ? speed_text(r.linear.critical_speed_m_per_s) : std::string("none in the range"))
      << ", Hopf " << (r.hopf_kind.empty() ? std::string("kind not known") : r.hopf_kind) << "\n"
      << "nonlinear critical speed " << r.nonlinear.explanation;
  const double ratio = nonlinear_to_linear_ratio(r);
  if (std::isfinite(ratio)) out << ", ratio to the linear " << std::setprecision(5) << ratio;
  out << "\n";
  for (const BranchResult& b : r.branches) {
    out << "  " << b.origin << " branch: ";
    if (!b.error.empty()) {
      out << "not started: " << b.error << "\n";
      continue;
    }
    out << b.branch.orbits.size() << " orbits";
    for (const OrbitBifurcation& f : b.branch.bifurcations)
      out << ", " << orbit_bifurcation_name(f.kind) << " at " << speed_text(f.speed_m_per_s);
    out << "; stopped: " << b.branch.stop_reason << "\n";
  }
  out << std::setprecision(4) << "CPU " << r.cpu_seconds << " s\n";
}

}  // namespace railstab
