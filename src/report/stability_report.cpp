#include "report/stability_report.hpp"

#include "io/csv.hpp"
#include "io/gnuplot.hpp"
#include "io/json_writer.hpp"

#include <array>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <map>
#include <sstream>

namespace railstab {

namespace {

void write_eigenvalue_csv(std::ostream& out, const CriticalSpeedResult& r,
                          const std::vector<std::vector<int>>& ids) {
  out << "speed_m_s,mode_track,real_per_s,imag_per_s,frequency_hz,damping_ratio,neutral,"
         "residual,mode\n"
      << std::setprecision(12);
  for (size_t i = 0; i < r.grid.size(); ++i)
    for (size_t j = 0; j < r.grid[i].modes.size(); ++j) {
      const ModeReport& m = r.grid[i].modes[j];
      const double speed = r.grid[i].speed_m_per_s;
      auto put = [&](double v, const char* column) {
        put_csv_number(out, v, [&] {
          std::ostringstream what;
          what << "eigenvalue CSV column " << column << " of mode " << m.name << " at " << speed
               << " m/s";
          return what.str();
        });
        out << ',';
      };
      put(speed, "speed_m_s");
      out << ids[i][j] << ',';
      put(m.eigenvalue.real(), "real_per_s");
      put(m.eigenvalue.imag(), "imag_per_s");
      put(m.frequency_hz, "frequency_hz");
      put(m.damping_ratio, "damping_ratio");
      out << (m.neutral ? 1 : 0) << ',';
      put(m.residual, "residual");
      out << csv_field(m.name) << '\n';
    }
}

// One gnuplot data block per tracked mode (speed, real, frequency, damping),
// only for modes below the frequency cap.
int write_track_blocks(std::ostream& out, const CriticalSpeedResult& r,
                       const std::vector<std::vector<int>>& ids, double max_hz) {
  std::map<int, std::vector<std::array<double, 4>>> tracks;
  for (size_t i = 0; i < r.grid.size(); ++i)
    for (size_t j = 0; j < r.grid[i].modes.size(); ++j) {
      const ModeReport& m = r.grid[i].modes[j];
      if (ids[i][j] < 0 || m.frequency_hz > max_hz) continue;
      tracks[ids[i][j]].push_back(
          {r.grid[i].speed_m_per_s, m.eigenvalue.real(), m.frequency_hz, m.damping_ratio});
    }
  int blocks = 0;
  out << std::setprecision(10) << "# speed_m_s real_per_s frequency_hz damping_ratio, one block "
                                  "per tracked mode\n";
  for (const auto& track : tracks) {
    // (Not a structured binding: clang 14 cannot capture one in the lambda.)
    const int id = track.first;
    const auto& points = track.second;
    if (points.size() < 2) continue;
    out << "# track " << id << "\n";
    for (const auto& p : points) {
      for (int k = 0; k < 4; ++k) {
        if (k) out << ' ';
        put_csv_number(out, p[k], [&] {
          return "mode track " + std::to_string(id) + " at " + std::to_string(p[0]) + " m/s";
        });
      }
      out << '\n';
    }
    out << "\n\n";
    ++blocks;
  }
  return blocks;
}

// Ranges on both axes are explicit: with no plottable point (a one-speed
// grid, every mode above the band) gnuplot's autoscale fails ("x range is
// invalid"); with them the plot is made, empty.
std::vector<std::string> plot_stability(OutputSet& outputs, const std::string& stem,
                                        const std::string& csv, const std::string& tracks,
                                        int n_tracks, const CriticalSpeedResult& r,
                                        const std::string& title, double max_hz) {
  const std::string script = stem + "_stability_plots.gp";
  std::vector<std::string> pngs = {stem + "_root_locus.png", stem + "_damping_vs_speed.png",
                                   stem + "_frequency_vs_speed.png"};
  const double v_lo = r.from_m_per_s, v_hi = r.to_m_per_s > r.from_m_per_s ? r.to_m_per_s
                                                                          : r.from_m_per_s + 1.0;
  auto titled = [&](const std::string& what) { return gnuplot_text(title + ": " + what); };
  std::ostringstream band;
  band << max_hz;
  outputs.write(script, [&](std::ostream& gp) {
    gp << "# Run from the output folder: gnuplot " << script << "\n"
       << "set datafile separator ','\nset terminal pngcairo size 900,560 font 'Sans,10' "
          "noenhanced\nset grid\n";
    gp << "set output " << gnuplot_text(pngs[0]) << "\nset title "
       << titled("root locus, real part >= -20 1/s (colour = speed)") << "\n"
       << "set xlabel 'real part [1/s]'\nset arrow 2 from 0, graph 0 to 0, graph 1 nohead lc 'black'\n"
       << "set ylabel 'frequency [Hz]'\nset cblabel 'speed [m/s]'\nset palette rgb 33,13,10\n"
       << "set yrange [0:" << max_hz << "]\nset xrange [-20:*]\nset cbrange [" << v_lo << ":"
       << v_hi << "]\n"
       << "plot " << gnuplot_path(csv) << " skip 1 using 3:($5<=" << max_hz
       << " && $7==0 && $3>=-20 ? $5 : 1/0):1 with points pt 7 ps 0.6 palette notitle\n";
    gp << "set datafile separator whitespace\nunset yrange\nunset xrange\nset autoscale\n"
       << "unset cblabel\nunset arrow 2\nset xrange [" << v_lo << ":" << v_hi << "]\n";
    const double vc = r.critical_speed_found ? r.critical_speed_m_per_s : NAN;
    if (std::isfinite(vc))
      gp << "set arrow 1 from " << vc << ", graph 0 to " << vc
         << ", graph 1 nohead dt 2 lc 'red'\nset label 1 'V_crit = " << std::fixed
         << std::setprecision(2) << vc << " m/s' at " << vc << ", graph 0.95 offset 1,0\n"
         << std::defaultfloat << std::setprecision(6);
    gp << "set output " << gnuplot_text(pngs[1]) << "\nset title "
       << titled("damping ratio of the modes below " + band.str() + " Hz")
       << "\nset xlabel 'speed [m/s]'\nset ylabel 'damping ratio [-]'\n"
       << "set xzeroaxis lt -1\nset yrange [-0.2:1]\n";
    gp << "plot for [i=0:" << std::max(0, n_tracks - 1) << "] " << gnuplot_path(tracks)
       << " index i using 1:4 with lines lw 1.5 notitle\n";
    gp << "set output " << gnuplot_text(pngs[2]) << "\nset title "
       << titled("frequency of the modes below " + band.str() + " Hz")
       << "\nset ylabel 'frequency [Hz]'\nset yrange [0:" << max_hz << "]\n";
    gp << "plot for [i=0:" << std::max(0, n_tracks - 1) << "] " << gnuplot_path(tracks)
       << " index i using 1:3 with lines lw 1.5 notitle\n";
  });
  for (const std::string& png : pngs) outputs.add(png);
  run_gnuplot(script, outputs.staging_dir(), pngs);
  return pngs;
}

void write_mode_json(JsonWriter& j, const ModeReport& m) {
  j.field("eigenvalue_real_per_s", m.eigenvalue.real())
      .field("eigenvalue_imag_per_s", m.eigenvalue.imag())
      .field("frequency_hz", m.frequency_hz)
      .field("damping_ratio", m.damping_ratio)
      .field("residual", m.residual)
      .field("name", m.name);
  j.key("participation").begin_array();
  for (const Participation& p : m.participation)
    j.begin_object()
        .field("body", p.body)
        .field("coordinate", coordinate_word(p.coordinate))
        .field("kinetic_energy_share", p.share)
        .end_object();
  j.end_array();
}

void write_json(std::ostream& out, const Model& model, const CriticalSpeedResult& r,
                const std::string& solver) {
  {
    JsonWriter j(out);
    j.begin_object().field("scene", model.name).field("source", model.source_path);
    j.key("speed_range_m_s").begin_array().value(r.from_m_per_s).value(r.to_m_per_s).end_array();
    j.field("partial", r.partial);
    if (r.partial)
      j.field("partial_reason", r.partial_reason);
    else
      j.key("partial_reason").null();
    j.field("stable_in_range", r.stable_in_range).field("unstable_at_start", r.unstable_at_start);
    if (r.equilibrium_lost_at_m_per_s > 0.0)
      j.field("equilibrium_lost_at_m_s", r.equilibrium_lost_at_m_per_s)
          .field("equilibrium_error", r.equilibrium_error);
    if (r.critical_speed_found) {
      const ModeReport& m = r.at_critical.modes[r.at_critical.least_stable];
      j.field("critical_speed_m_s", r.critical_speed_m_per_s)
          .field("critical_speed_tolerance_m_s", r.speed_tolerance_m_per_s)
          .field("frequency_hz", m.frequency_hz)
          .field("damping_ratio", m.damping_ratio)
          .field("mode", m.name);
      j.key("mode_shape").begin_object();
      write_mode_json(j, m);
      j.end_object();
    } else {
      j.key("critical_speed_m_s").null().key("frequency_hz").null().key("mode").null();
    }
    j.field("eigen_solver", solver)
        .field("states", int(r.grid.empty() ? 0 : r.grid.front().linear.A.rows()))
        .field("evaluations", r.evaluations)
        .field("wall_seconds", r.seconds);
    j.key("removed_cyclic_states").begin_array();
    if (!r.grid.empty())
      for (const std::string& s : r.grid.front().linear.removed_states) j.value(s);
    j.end_array();
    double worst_residual = 0.0;
    for (const StabilityPoint& p : r.grid)
      for (const ModeReport& m : p.modes) worst_residual = std::max(worst_residual, m.residual);
    j.field("max_eigenpair_residual", worst_residual);
    j.key("unstable_modes_above_hunting_band").begin_array();
    for (const StabilityPoint& p : r.grid)
      for (int i : p.unstable_above_band) {
        j.begin_object().field("speed_m_s", p.speed_m_per_s);
        write_mode_json(j, p.modes[i]);
        j.end_object();
      }
    j.end_array();
    j.key("least_stable_by_speed").begin_array();
    for (const StabilityPoint& p : r.grid) {
      j.begin_object().field("speed_m_s", p.speed_m_per_s);
      if (p.least_stable >= 0) write_mode_json(j, p.modes[p.least_stable]);
      j.end_object();
    }
    j.end_array().end_object();
  }
}

// User text in Markdown: one line, no table-cell break, no code-span end.
std::string md_text(const std::string& text) {
  std::string out;
  for (char c : text) {
    const unsigned char u = static_cast<unsigned char>(c);
    if (u < 0x20 || u == 0x7F) out += ' ';
    else if (c == '|' || c == '`' || c == '\\' || c == '<' || c == '>')
      out += std::string("\\") + c;
    else out += c;
  }
  return out;
}

void write_markdown(std::ostream& md_out, const Model& model, const CriticalSpeedResult& r,
                    const std::string& solver, const StabilityFiles& files) {
  auto rel = [&](const std::string& f) { return f; };  // names in the same folder
  {
    std::ostream& md = md_out;
    md << std::setprecision(4);
    md << "# Critical speed: " << md_text(model.name) << "\n\n"
       << "Scene `" << md_text(model.source_path) << "`, speeds " << r.from_m_per_s << " to "
       << r.to_m_per_s << " m/s, " << (r.grid.empty() ? 0 : r.grid.front().linear.A.rows())
       << " states after removing " << (r.grid.empty() ? 0 : r.grid.front().linear.removed_states.size())
       << " cyclic coordinates, eigen-solver " << solver << ".\n\n";
    if (r.partial)
      md << "**Partial result**: the run could not finish what was asked; what it found is "
            "below. Reason: "
         << md_text(r.partial_reason) << "\n\n";
    if (r.equilibrium_lost_at_m_per_s > 0.0)
      md << "No steady state at " << r.equilibrium_lost_at_m_per_s
         << " m/s and above (" << md_text(r.equilibrium_error) << "); the analysis covers the speeds "
         << "below.\n\n";
    if (r.unstable_at_start) {
      md << "**Already unstable at " << r.from_m_per_s << " m/s**: lower the start speed.\n\n";
    } else if (!r.critical_speed_found) {
      md << "**Stable over the whole range analysed** (no non-neutral mode crosses into the "
            "right half-plane).\n\n";
    } else {
      const ModeReport& m = r.at_critical.modes[r.at_critical.least_stable];
      md << "| result | value |\n|---|---|\n"
         << "| critical speed | **" << std::fixed << std::setprecision(2)
         << r.critical_speed_m_per_s << " m/s** (" << r.critical_speed_m_per_s * 3.6
         << " km/h), bracketed to " << r.speed_tolerance_m_per_s << " m/s |\n"
         << std::defaultfloat << std::setprecision(4) << "| hunting frequency | " << m.frequency_hz
         << " Hz |\n| wavelength | "
         << (m.frequency_hz > 0.0 ? r.critical_speed_m_per_s / m.frequency_hz : 0.0)
         << " m |\n"
         << "| damping ratio at the stable side | " << m.damping_ratio << " |\n"
         << "| mode | " << md_text(m.name) << " |\n\n"
         << "Mode shape (kinetic-energy share):\n\n| body | coordinate | share |\n|---|---|---|\n";
      for (const Participation& p : m.participation)
        md << "| " << md_text(p.body) << " | " << coordinate_word(p.coordinate) << " | " << p.share
           << " |\n";
      md << "\n";
    }
    for (const StabilityPoint& p : r.grid)
      if (!p.validity_warning.empty()) {
        md << "- from " << p.speed_m_per_s << " m/s: " << md_text(p.validity_warning) << "\n";
        break;
      }
    for (const StabilityPoint& p : r.grid)
      if (!p.unstable_above_band.empty()) {
        const ModeReport& m = p.modes[p.unstable_above_band.front()];
        md << "- from " << p.speed_m_per_s << " m/s a mode above the hunting band is unstable: "
           << md_text(m.name) << " at " << m.frequency_hz << " Hz, real part " << m.eigenvalue.real()
           << " 1/s (wheel-rail contact mode; the Hertz contact has no damping)\n";
        break;
      }
    md << "\nLeast stable mode by speed:\n\n| speed [m/s] | real part [1/s] | frequency [Hz] | "
          "damping ratio | mode |\n|---|---|---|---|---|\n";
    for (const StabilityPoint& p : r.grid) {
      if (p.least_stable < 0) continue;
      const ModeReport& m = p.modes[p.least_stable];
      md << "| " << p.speed_m_per_s << " | " << m.eigenvalue.real() << " | " << m.frequency_hz
         << " | " << m.damping_ratio << " | " << md_text(m.name) << " |\n";
    }
    md << "\n";
    for (const std::string& png : files.plots) md << "![](" << rel(png) << ")\n\n";
    md << "Data: `" << rel(files.csv) << "` (every eigenvalue at every speed, modes tracked "
       << "by eigenvector continuity), `" << rel(files.json) << "`. Wall time " << r.seconds
       << " s for " << r.evaluations << " speed evaluations.\n";
  }
}

}  // namespace

std::vector<std::string> stability_file_names(const std::string& stem) {
  return {stem + "_eigenvalues.csv",       stem + "_tracks.dat",
          stem + "_stability_plots.gp",    stem + "_root_locus.png",
          stem + "_damping_vs_speed.png",  stem + "_frequency_vs_speed.png",
          stem + "_critical_speed.json",   stem + "_critical_speed.md"};
}

StabilityFiles write_stability_results(const Model& model, const CriticalSpeedResult& result,
                                       OutputSet& outputs, const std::string& stem,
                                       const std::string& eigen_solver_name, bool plots,
                                       double max_plot_frequency_hz) {
  for (const std::string& name : stability_file_names(stem)) outputs.replaces(name);
  StabilityFiles files;
  const auto ids = track_modes(result.grid);
  files.csv = stem + "_eigenvalues.csv";
  outputs.write(files.csv, [&](std::ostream& out) { write_eigenvalue_csv(out, result, ids); });
  files.json = stem + "_critical_speed.json";
  outputs.write(files.json,
                [&](std::ostream& out) { write_json(out, model, result, eigen_solver_name); });
  if (plots)
    files.plots = {stem + "_root_locus.png", stem + "_damping_vs_speed.png",
                   stem + "_frequency_vs_speed.png"};
  files.markdown = stem + "_critical_speed.md";
  outputs.write(files.markdown, [&](std::ostream& out) {
    write_markdown(out, model, result, eigen_solver_name, files);
  });
  if (plots) {
    const std::string tracks = stem + "_tracks.dat";
    int n_tracks = 0;
    outputs.write(tracks, [&](std::ostream& out) {
      n_tracks = write_track_blocks(out, result, ids, max_plot_frequency_hz);
    });
    files.plots = plot_stability(outputs, stem, files.csv, tracks, n_tracks, result, model.name,
                                 max_plot_frequency_hz);
  }
  return files;
}

void print_critical_speed_summary(std::ostream& out, const Model& model,
                                  const CriticalSpeedResult& r, double hunting_band_hz) {
  out << std::setprecision(6);
  if (r.unstable_at_start) {
    out << model.name << ": already unstable at " << r.from_m_per_s << " m/s\n";
  } else if (!r.critical_speed_found) {
    const double top = r.grid.back().speed_m_per_s;
    out << model.name << ": stable over the whole range analysed " << r.from_m_per_s << " - "
        << top << " m/s\n";
  } else {
    const ModeReport& m = r.at_critical.modes[r.at_critical.least_stable];
    out << model.name << ": critical speed " << std::fixed << std::setprecision(2)
        << r.critical_speed_m_per_s << " m/s (" << r.critical_speed_m_per_s * 3.6 << " km/h)"
        << std::defaultfloat << std::setprecision(5) << ", frequency " << m.frequency_hz
        << " Hz, mode " << m.name << "\n";
  }
  if (r.partial)
    out << "partial result: " << r.partial_reason << "\n";
  else if (r.equilibrium_lost_at_m_per_s > 0.0)
    out << "no steady state from " << r.equilibrium_lost_at_m_per_s
        << " m/s: " << r.equilibrium_error << "\n";
  for (const StabilityPoint& p : r.grid)
    if (!p.validity_warning.empty()) {
      out << "warning from " << p.speed_m_per_s << " m/s: " << p.validity_warning << "\n";
      break;
    }
  for (const StabilityPoint& p : r.grid)
    if (!p.unstable_above_band.empty()) {
      const ModeReport& m = p.modes[p.unstable_above_band.front()];
      out << "warning from " << p.speed_m_per_s << " m/s: mode above the hunting band ("
          << hunting_band_hz << " Hz) unstable: " << m.name << " at " << m.frequency_hz
          << " Hz, real part " << m.eigenvalue.real() << " 1/s\n";
      break;
    }
  out << r.evaluations << " speed evaluations in " << r.seconds << " s\n";
}

}  // namespace railstab
