#include "report/stability_report.hpp"

#include "io/json_writer.hpp"
#include "io/output_files.hpp"
#include "report/time_plots.hpp"

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <map>
#include <sstream>

namespace railstab {

namespace {

void write_eigenvalue_csv(const std::string& path, const CriticalSpeedResult& r,
                          const std::vector<std::vector<int>>& ids) {
  write_file_atomically(path, [&](std::ostream& out) {
    out << "speed_m_s,mode_track,real_per_s,imag_per_s,frequency_hz,damping_ratio,neutral,"
           "residual,mode\n"
        << std::setprecision(12);
    for (size_t i = 0; i < r.grid.size(); ++i)
      for (size_t j = 0; j < r.grid[i].modes.size(); ++j) {
        const ModeReport& m = r.grid[i].modes[j];
        if (!std::isfinite(m.eigenvalue.real()) || !std::isfinite(m.eigenvalue.imag()))
          throw std::runtime_error("non-finite eigenvalue at " +
                                   std::to_string(r.grid[i].speed_m_per_s) + " m/s");
        out << r.grid[i].speed_m_per_s << ',' << ids[i][j] << ',' << m.eigenvalue.real() << ','
            << m.eigenvalue.imag() << ',' << m.frequency_hz << ',' << m.damping_ratio << ','
            << (m.neutral ? 1 : 0) << ',' << m.residual << ",\"" << m.name << "\"\n";
      }
  });
}

// One gnuplot data block per tracked mode (speed, real, frequency, damping),
// only for modes below the frequency cap.
int write_track_blocks(const std::string& path, const CriticalSpeedResult& r,
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
  write_file_atomically(path, [&](std::ostream& out) {
    out << std::setprecision(10);
    for (const auto& [id, points] : tracks) {
      if (points.size() < 2) continue;
      out << "# track " << id << "\n";
      for (const auto& p : points) out << p[0] << ' ' << p[1] << ' ' << p[2] << ' ' << p[3] << '\n';
      out << "\n\n";
      ++blocks;
    }
  });
  return blocks;
}

std::vector<std::string> plot_stability(const std::string& prefix, const std::string& csv,
                                        const std::string& tracks, int n_tracks,
                                        const CriticalSpeedResult& r, const std::string& title,
                                        double max_hz) {
  const std::string script = prefix + "_stability_plots.gp";
  std::vector<std::string> pngs = {prefix + "_root_locus.png", prefix + "_damping_vs_speed.png",
                                   prefix + "_frequency_vs_speed.png"};
  write_file_atomically(script, [&](std::ostream& gp) {
    gp << "set datafile separator ','\nset terminal pngcairo size 900,560 font 'Sans,10' "
          "noenhanced\nset grid\n";
    gp << "set output '" << pngs[0] << "'\nset title '" << title
       << ": root locus, real part >= -20 1/s (colour = speed)'\n"
       << "set xlabel 'real part [1/s]'\nset arrow 2 from 0, graph 0 to 0, graph 1 nohead lc 'black'\n"
       << "set ylabel 'frequency [Hz]'\nset cblabel 'speed [m/s]'\nset palette rgb 33,13,10\n"
       << "set yrange [0:" << max_hz << "]\nset xrange [*:*]\n"
       << "set xrange [-20:*]\n"
       << "plot '" << csv << "' skip 1 using 3:($5<=" << max_hz
       << " && $7==0 && $3>=-20 ? $5 : 1/0):1 with points pt 7 ps 0.6 palette notitle\n";
    gp << "set datafile separator whitespace\nunset yrange\nunset xrange\nset autoscale\n"
       << "unset cblabel\nunset arrow 2\n";
    const double vc = r.critical_speed_found ? r.critical_speed_m_per_s : NAN;
    auto marker = [&](std::ostream& o) {
      if (std::isfinite(vc))
        o << "set arrow 1 from " << vc << ", graph 0 to " << vc
          << ", graph 1 nohead dt 2 lc 'red'\nset label 1 'V_crit = " << std::fixed
          << std::setprecision(2) << vc << " m/s' at " << vc << ", graph 0.95 offset 1,0\n"
          << std::defaultfloat;
    };
    marker(gp);
    gp << "set output '" << pngs[1] << "'\nset title '" << title
       << ": damping ratio of the modes below " << max_hz
       << " Hz'\nset xlabel 'speed [m/s]'\nset ylabel 'damping ratio [-]'\n"
       << "set xzeroaxis lt -1\nset yrange [-0.2:1]\n";
    gp << "plot for [i=0:" << std::max(0, n_tracks - 1) << "] '" << tracks
       << "' index i using 1:4 with lines lw 1.5 notitle\n";
    gp << "set output '" << pngs[2] << "'\nset title '" << title
       << ": frequency of the modes below " << max_hz
       << " Hz'\nset ylabel 'frequency [Hz]'\nset yrange [0:" << max_hz << "]\n";
    gp << "plot for [i=0:" << std::max(0, n_tracks - 1) << "] '" << tracks
       << "' index i using 1:3 with lines lw 1.5 notitle\n";
  });
  run_gnuplot(script);
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

void write_json(const std::string& path, const Model& model, const CriticalSpeedResult& r,
                const std::string& solver) {
  write_file_atomically(path, [&](std::ostream& out) {
    JsonWriter j(out);
    j.begin_object().field("scene", model.name).field("source", model.source_path);
    j.key("speed_range_m_s").begin_array().value(r.from_m_per_s).value(r.to_m_per_s).end_array();
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
  });
}

void write_markdown(const std::string& path, const Model& model, const CriticalSpeedResult& r,
                    const std::string& solver, const StabilityFiles& files) {
  auto rel = [&](const std::string& f) {
    return std::filesystem::path(f).filename().string();
  };
  write_file_atomically(path, [&](std::ostream& md) {
    md << std::setprecision(4);
    md << "# Critical speed: " << model.name << "\n\n"
       << "Scene `" << model.source_path << "`, speeds " << r.from_m_per_s << " to "
       << r.to_m_per_s << " m/s, " << (r.grid.empty() ? 0 : r.grid.front().linear.A.rows())
       << " states after removing " << (r.grid.empty() ? 0 : r.grid.front().linear.removed_states.size())
       << " cyclic coordinates, eigen-solver " << solver << ".\n\n";
    if (r.equilibrium_lost_at_m_per_s > 0.0)
      md << "No steady state at " << r.equilibrium_lost_at_m_per_s
         << " m/s and above (" << r.equilibrium_error << "); the analysis covers the speeds "
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
         << " Hz |\n| wavelength | " << r.critical_speed_m_per_s / m.frequency_hz << " m |\n"
         << "| damping ratio at the stable side | " << m.damping_ratio << " |\n"
         << "| mode | " << m.name << " |\n\n"
         << "Mode shape (kinetic-energy share):\n\n| body | coordinate | share |\n|---|---|---|\n";
      for (const Participation& p : m.participation)
        md << "| " << p.body << " | " << coordinate_word(p.coordinate) << " | " << p.share
           << " |\n";
      md << "\n";
    }
    for (const StabilityPoint& p : r.grid)
      if (!p.validity_warning.empty()) {
        md << "- from " << p.speed_m_per_s << " m/s: " << p.validity_warning << "\n";
        break;
      }
    for (const StabilityPoint& p : r.grid)
      if (!p.unstable_above_band.empty()) {
        const ModeReport& m = p.modes[p.unstable_above_band.front()];
        md << "- from " << p.speed_m_per_s << " m/s a mode above the hunting band is unstable: "
           << m.name << " at " << m.frequency_hz << " Hz, real part " << m.eigenvalue.real()
           << " 1/s (wheel-rail contact mode; the Hertz contact has no damping)\n";
        break;
      }
    md << "\nLeast stable mode by speed:\n\n| speed [m/s] | real part [1/s] | frequency [Hz] | "
          "damping ratio | mode |\n|---|---|---|---|---|\n";
    for (const StabilityPoint& p : r.grid) {
      if (p.least_stable < 0) continue;
      const ModeReport& m = p.modes[p.least_stable];
      md << "| " << p.speed_m_per_s << " | " << m.eigenvalue.real() << " | " << m.frequency_hz
         << " | " << m.damping_ratio << " | " << m.name << " |\n";
    }
    md << "\n";
    for (const std::string& png : files.plots) md << "![](" << rel(png) << ")\n\n";
    md << "Data: `" << rel(files.csv) << "` (every eigenvalue at every speed, modes tracked "
       << "by eigenvector continuity), `" << rel(files.json) << "`. Wall time " << r.seconds
       << " s for " << r.evaluations << " speed evaluations.\n";
  });
}

}  // namespace

StabilityFiles write_stability_results(const Model& model, const CriticalSpeedResult& result,
                                       const std::string& output_prefix,
                                       const std::string& eigen_solver_name,
                                       double max_plot_frequency_hz) {
  StabilityFiles files;
  const auto ids = track_modes(result.grid);
  files.csv = output_prefix + "_eigenvalues.csv";
  write_eigenvalue_csv(files.csv, result, ids);
  const std::string tracks = output_prefix + "_tracks.dat";
  const int n_tracks = write_track_blocks(tracks, result, ids, max_plot_frequency_hz);
  files.plots = plot_stability(output_prefix, files.csv, tracks, n_tracks, result, model.name,
                               max_plot_frequency_hz);
  files.json = output_prefix + "_critical_speed.json";
  write_json(files.json, model, result, eigen_solver_name);
  files.markdown = output_prefix + "_critical_speed.md";
  write_markdown(files.markdown, model, result, eigen_solver_name, files);
  return files;
}

}  // namespace railstab
