#include <railstab/report/time_plots.hpp>

#include <railstab/io/gnuplot.hpp>

#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>

namespace railstab {

namespace {

struct PlotSpec {
  std::string suffix;
  bool absolute_roll_file;  // from the absolute-roll CSV (one column per body)
  std::string title, ylabel;
  int coordinate;  // 0..5
  double scale;    // to the plotted unit
  std::function<bool(const Body&)> include;
};

std::vector<PlotSpec> plot_specs() {
  const auto wheelsets = [](const Body& b) { return b.wheelset() != nullptr; };
  const auto others = [](const Body& b) { return b.wheelset() == nullptr; };
  return {
      {"wheelset_lateral", false, "Lateral shift of the wheelsets", "lateral shift y [mm]", 1, 1e3,
       wheelsets},
      {"wheelset_yaw", false, "Yaw angle of the wheelsets", "yaw [mrad]", 5, 1e3, wheelsets},
      {"body_lateral", false, "Lateral shift of bogie frames and car body", "lateral shift y [mm]", 1,
       1e3, others},
      {"body_yaw", false, "Yaw angle of bogie frames and car body", "yaw [mrad]", 5, 1e3, others},
      // Roll split by body kind as the other plots are: one plot of every
      // body's roll had seven lines on the thesis vehicle, unreadable.
      {"wheelset_roll", false, "Roll angle of the wheelsets (relative to their track frames)",
       "roll [mrad]", 3, 1e3, wheelsets},
      {"body_roll", false, "Roll angle of bogie frames and car body (relative to their track frames)",
       "roll [mrad]", 3, 1e3, others},
      {"wheelset_absolute_roll", true, "Roll angle of the wheelsets in the fixed frame (follows the cant)",
       "roll [mrad]", 0, 1e3, wheelsets},
      {"body_absolute_roll", true,
       "Roll angle of bogie frames and car body in the fixed frame (follows the cant)", "roll [mrad]",
       0, 1e3, others},
  };
}

}  // namespace

std::vector<std::string> time_plot_file_names(const std::string& stem) {
  std::vector<std::string> names = {stem + "_plots.gp"};
  for (const PlotSpec& p : plot_specs()) names.push_back(stem + "_" + p.suffix + ".png");
  return names;
}

void plot_time_histories(const Model& model, double speed_m_per_s, OutputSet& outputs, const std::string& stem,
                         const PlottedCsv& trajectory, const PlottedCsv& absolute_roll,
                         double t_start_s, double t_end_s) {
  // An explicit x range: a run stopped at t = 0 (one row) still plots.
  const double t_hi = t_end_s > t_start_s ? t_end_s : t_start_s + 1.0;
  const std::string script = stem + "_plots.gp";
  std::vector<std::string> pngs;
  outputs.write(script, [&](std::ostream& gp) {
    gp << "# Run from the output folder: gnuplot " << script << "\n"
       << "if (!exists(\"trajectory_csv\")) trajectory_csv = " << gnuplot_path(trajectory.final_path)
       << "\n"
       << "if (!exists(\"absolute_roll_csv\")) absolute_roll_csv = "
       << gnuplot_path(absolute_roll.final_path) << "\n"
       << "set datafile separator ','\n"
       << "set terminal pngcairo size 900,520 font 'Sans,10' noenhanced\n"
       << "set grid\nset key outside right\nset xlabel 'time [s]'\n"
       << "set xrange [" << t_start_s << ":" << t_hi << "]\n";
    for (const PlotSpec& p : plot_specs()) {
      std::vector<int> cols;
      std::vector<std::string> names;
      for (size_t b = 0; b < model.bodies.size(); ++b)
        if (p.include(model.bodies[b])) {
          cols.push_back(p.absolute_roll_file ? 2 + int(b) : 2 + int(b) * 6 + p.coordinate);
          names.push_back(model.bodies[b].name);
        }
      if (cols.empty()) continue;
      const std::string png = stem + "_" + p.suffix + ".png";
      outputs.add(png);
      pngs.push_back(png);
      std::ostringstream title;
      title << model.name << ": " << p.title << " at " << speed_m_per_s << " m/s";
      const PlottedCsv& csv = p.absolute_roll_file ? absolute_roll : trajectory;
      gp << "set output " << gnuplot_text(png) << "\n"
         << "set title " << gnuplot_text(title.str()) << "\n"
         << "set ylabel " << gnuplot_text(p.ylabel) << "\nplot ";
      for (size_t i = 0; i < cols.size(); ++i)
        gp << (i ? ", " : "") << (p.absolute_roll_file ? "absolute_roll_csv" : "trajectory_csv")
           << " skip " << csv.header_lines << " using 1:($" << cols[i] << "*" << p.scale
           << ") with lines lw 1.5 title " << gnuplot_text(names[i]);
      gp << "\n";
    }
  });
  run_gnuplot(script, outputs.staging_dir(), pngs,
              {{"trajectory_csv", trajectory.staged_path},
               {"absolute_roll_csv", absolute_roll.staged_path}});
}

}  // namespace railstab
