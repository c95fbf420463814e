#include "report/time_plots.hpp"

#include "io/output_files.hpp"

#include <cstdlib>
#include <functional>
#include <sstream>
#include <stdexcept>

namespace railstab {

void run_gnuplot(const std::string& script_path) {
  const std::string cmd = "gnuplot '" + script_path + "'";
  const int status = std::system(cmd.c_str());
  if (status != 0)
    throw std::runtime_error("gnuplot failed (status " + std::to_string(status) + ") on " +
                             script_path);
}

namespace {

struct PlotSpec {
  std::string suffix;
  bool absolute_roll_file;  // from the absolute-roll CSV (one column per body)
  std::string title, ylabel;
  int coordinate;  // 0..5
  double scale;    // to the plotted unit
  std::function<bool(const Body&)> include;
};

}  // namespace

std::vector<std::string> plot_time_histories(const Model& model, double speed_m_per_s,
                                             const std::string& csv_path,
                                             const std::string& absolute_roll_csv_path,
                                             const std::string& output_prefix) {
  const auto wheelsets = [](const Body& b) { return b.wheelset() != nullptr; };
  const auto others = [](const Body& b) { return b.wheelset() == nullptr; };
  const auto all = [](const Body&) { return true; };
  const std::vector<PlotSpec> plots = {
      {"wheelset_lateral", false, "Lateral shift of the wheelsets", "lateral shift y [mm]", 1, 1e3,
       wheelsets},
      {"wheelset_yaw", false, "Yaw angle of the wheelsets", "yaw [mrad]", 5, 1e3, wheelsets},
      {"body_lateral", false, "Lateral shift of bogie frames and car body", "lateral shift y [mm]", 1,
       1e3, others},
      {"body_yaw", false, "Yaw angle of bogie frames and car body", "yaw [mrad]", 5, 1e3, others},
      {"roll", false, "Roll angle of all bodies (relative to their track frames)", "roll [mrad]", 3,
       1e3, all},
      {"absolute_roll", true, "Roll angle of all bodies in the fixed frame (follows the cant)",
       "roll [mrad]", 0, 1e3, all},
  };
  const std::string script = output_prefix + "_plots.gp";
  std::vector<std::string> pngs;
  write_file_atomically(script, [&](std::ostream& gp) {
    gp << "set datafile separator ','\n"
       << "set terminal pngcairo size 900,520 font 'Sans,10' noenhanced\n"
       << "set grid\nset key outside right\nset xlabel 'time [s]'\n";
    for (const PlotSpec& p : plots) {
      std::vector<int> cols;
      std::vector<std::string> names;
      for (size_t b = 0; b < model.bodies.size(); ++b)
        if (p.include(model.bodies[b])) {
          cols.push_back(p.absolute_roll_file ? 2 + int(b) : 2 + int(b) * 6 + p.coordinate);
          names.push_back(model.bodies[b].name);
        }
      if (cols.empty()) continue;
      const std::string png = output_prefix + "_" + p.suffix + ".png";
      pngs.push_back(png);
      gp << "set output '" << png << "'\n"
         << "set title '" << model.name << ": " << p.title << " at "
         << speed_m_per_s << " m/s'\n"
         << "set ylabel '" << p.ylabel << "'\nplot ";
      for (size_t i = 0; i < cols.size(); ++i)
        gp << (i ? ", " : "") << "'" << (p.absolute_roll_file ? absolute_roll_csv_path : csv_path)
           << "' skip 1 using 1:($" << cols[i] << "*"
           << p.scale << ") with lines lw 1.5 title '" << names[i] << "'";
      gp << "\n";
    }
  });
  run_gnuplot(script);
  return pngs;
}

}  // namespace railstab
