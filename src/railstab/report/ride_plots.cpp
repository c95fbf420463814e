#include <railstab/report/ride_plots.hpp>

#include <railstab/io/gnuplot.hpp>
#include <railstab/io/ride_files.hpp>

#include <algorithm>
#include <sstream>

namespace railstab {

namespace {

const char* const kPlotSuffixes[4] = {"sum_y", "y_over_q", "lateral_acceleration",
                                      "vertical_acceleration"};

}  // namespace

std::vector<std::string> ride_plot_file_names(const std::string& stem) {
  std::vector<std::string> names = {stem + "_ride_plots.gp"};
  for (const char* suffix : kPlotSuffixes) names.push_back(stem + "_" + suffix + ".png");
  return names;
}

void plot_ride_quantities(const Model& model, double speed_m_per_s, OutputSet& outputs,
                          const std::string& stem, const RideHistory& history,
                          const PlottedCsv& wheel_forces, const PlottedCsv& accelerations,
                          double t_start_s, double t_end_s) {
  const double t_hi = t_end_s > t_start_s ? t_end_s : t_start_s + 1.0;
  const std::string script = stem + "_ride_plots.gp";
  std::vector<std::string> pngs;
  auto begin_plot = [&](std::ostream& gp, const char* suffix, const std::string& title,
                        const std::string& ylabel) {
    const std::string png = stem + "_" + suffix + ".png";
    outputs.add(png);
    pngs.push_back(png);
    std::ostringstream full;
    full << model.name << ": " << title << " at " << speed_m_per_s << " m/s";
    gp << "set output " << gnuplot_text(png) << "\nset title " << gnuplot_text(full.str())
       << "\nset ylabel " << gnuplot_text(ylabel) << "\nplot ";
  };
  outputs.write(script, [&](std::ostream& gp) {
    gp << "# Run from the output folder: gnuplot " << script << "\n"
       << "if (!exists(\"wheel_forces_csv\")) wheel_forces_csv = "
       << gnuplot_path(wheel_forces.final_path) << "\n"
       << "if (!exists(\"accelerations_csv\")) accelerations_csv = "
       << gnuplot_path(accelerations.final_path) << "\n"
       << "set datafile separator ','\n"
       << "set datafile missing ''\n"  // a lifted wheel has no Y/Q
       << "set terminal pngcairo size 900,520 font 'Sans,10' noenhanced\n"
       << "set grid\nset key outside right\nset xlabel 'time [s]'\n"
       << "set xrange [" << t_start_s << ":" << t_hi << "]\n";
    // Sum Y [kN], with the smallest wheelset's Prud'homme limit as +-lines.
    double limit_kN = 0.0;
    for (const StaticWheelLoad& load : history.static_loads) {
      const double l = prudhomme_limit_N(load.axle_load_N(), history.prudhomme_factor) / 1e3;
      limit_kN = limit_kN == 0.0 ? l : std::min(limit_kN, l);
    }
    if (!history.static_loads.empty()) {
      // A margin above and below, so that a limit line on a tic (Y/Q 0.8)
      // is not hidden in the frame's border.
      gp << "set offsets 0, 0, graph 0.06, graph 0.06\n";
      begin_plot(gp, "sum_y", "Track shift force Sum Y of the wheelsets", "Sum Y [kN]");
      for (size_t w = 0; w < history.static_loads.size(); ++w)
        gp << (w ? ", " : "") << "wheel_forces_csv skip " << wheel_forces.header_lines
           << " using 1:($" << 2 + int(w) * kWheelForceColumnsPerWheelset
           << "/1000) with lines lw 1.5 title "
           << gnuplot_text(model.bodies[size_t(history.static_loads[w].body)].name);
      std::ostringstream limit_title;
      limit_title.precision(3);
      limit_title << "Prud'homme limit +-" << limit_kN << " kN";
      gp << ", " << limit_kN << " with lines dt 2 lc 'black' title " << gnuplot_text(limit_title.str())
         << ", " << -limit_kN << " with lines dt 2 lc 'black' notitle\n";
      begin_plot(gp, "y_over_q", "Derailment quotient Y/Q of the wheels", "Y/Q [-]");
      for (size_t w = 0; w < history.static_loads.size(); ++w)
        for (int s = 0; s < 2; ++s)
          gp << (w || s ? ", " : "") << "wheel_forces_csv skip " << wheel_forces.header_lines
             << " using 1:" << 2 + int(w) * kWheelForceColumnsPerWheelset + 2 + s * 4 + 2
             << " with lines lw 1.2 title "
             << gnuplot_text(model.bodies[size_t(history.static_loads[w].body)].name +
                             (s == 0 ? " left" : " right"));
      gp << ", 0.8 with lines dt 2 lc 'black' title 'EN 14363 limit 0.8'\n";
      gp << "unset offsets\n";
    }
    if (!history.points.empty()) {
      const char* titles[2] = {"Lateral acceleration of the bodies (track frame, gravity excluded)",
                               "Vertical acceleration of the bodies (track frame, gravity excluded)"};
      for (int c = 1; c <= 2; ++c) {
        begin_plot(gp, kPlotSuffixes[1 + c], titles[c - 1], c == 1 ? "lateral [m/s2]" : "vertical [m/s2]");
        for (size_t p = 0; p < history.points.size(); ++p)
          gp << (p ? ", " : "") << "accelerations_csv skip " << accelerations.header_lines
             << " using 1:" << 2 + int(p) * kAccelerationColumnsPerPoint + c
             << " with lines lw 1.2 title " << gnuplot_text(history.points[p].label);
        gp << "\n";
      }
    }
  });
  run_gnuplot(script, outputs.staging_dir(), pngs,
              {{"wheel_forces_csv", wheel_forces.staged_path},
               {"accelerations_csv", accelerations.staged_path}});
}

}  // namespace railstab
