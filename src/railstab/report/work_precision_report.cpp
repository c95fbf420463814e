#include <railstab/report/work_precision_report.hpp>

#include <railstab/io/csv.hpp>
#include <railstab/io/gnuplot.hpp>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace railstab {

namespace {

// Empty for a run without a result (gave up, failed, skipped): the status
// column says why. Only the run's outcome columns may be empty this way.
std::string number(double v) {
  if (!std::isfinite(v)) return "";
  std::ostringstream s;
  s << std::setprecision(6) << v;
  return s.str();
}

// A value every run has (tolerances, the reference's): never empty, never
// non-finite.
std::string required_number(double v, const std::string& what) { return csv_number(v, what, 6); }

std::vector<std::string> labels_in_order(const WorkPrecisionResult& r) {
  std::vector<std::string> labels;
  for (const WorkPrecisionRun& run : r.runs)
    if (labels.empty() || labels.back() != run.label) labels.push_back(run.label);
  return labels;
}

}  // namespace

std::vector<std::string> work_precision_plot_file_names(const std::string& stem) {
  return {stem + "_work_precision.dat", stem + "_work_precision.gp",
          stem + "_work_precision.png"};
}

void write_work_precision_csv(std::ostream& out, const WorkPrecisionResult& r) {
  out << "integrator,relative_tolerance,absolute_tolerance,position_error,cpu_s,steps,"
         "rhs_evaluations,jacobian_evaluations,status,wall_s,position_error_at,lateral_error\n";
  for (const WorkPrecisionRun& run : r.runs) {
    const bool done = std::isfinite(run.error);
    out << csv_field(run.label) << ',' << required_number(run.rtol, run.label + " rtol") << ','
        << required_number(run.atol, run.label + " atol") << ','
        << number(run.error) << ',' << (done ? number(run.cpu_seconds) : "") << ','
        << run.stats.steps << ',' << run.stats.rhs_evaluations << ','
        << run.stats.jacobian_evaluations << ',' << csv_field(run.status) << ','
        << (done ? number(run.wall_seconds) : "") << ',' << csv_field(run.error_coordinate) << ','
        << number(run.lateral_error) << '\n';
  }
}

// Gnuplot data: one block per integrator (finished runs only), then the plot.
void write_work_precision_plot(OutputSet& outputs, const std::string& stem, const Model& model,
                               double speed_m_per_s, double t_end,
                               const WorkPrecisionResult& r) {
  const std::string dat = stem + "_work_precision.dat";
  const std::string png = stem + "_work_precision.png";
  const std::string gp = stem + "_work_precision.gp";
  const std::vector<std::string> labels = labels_in_order(r);
  std::vector<std::string> plotted;
  outputs.write(dat, [&](std::ostream& out) {
    out << "# cpu_s position_error relative_tolerance (one block per integrator)\n";
    for (const std::string& label : labels) {
      std::ostringstream block;
      for (const WorkPrecisionRun& run : r.runs)
        if (run.label == label && run.status == "ok" && run.error > 0.0)
          block << number(run.cpu_seconds) << ' ' << number(run.error) << ' ' << number(run.rtol)
                << '\n';
      if (block.str().empty()) continue;
      out << "# " << label << '\n' << block.str() << "\n\n";
      plotted.push_back(label);
    }
  });
  std::ostringstream title;
  title << model.name << " at " << speed_m_per_s << " m/s, " << t_end
        << " s: work-precision (reference " << integrator_name(r.reference.kind) << " rtol "
        << number(r.reference.rtol) << ")";
  outputs.write(gp, [&](std::ostream& out) {
    out << "# Run from the output folder: gnuplot " << gp << "\n"
        << "set terminal pngcairo size 900,600 font 'Sans,10' noenhanced\n"
        << "set output " << gnuplot_text(png) << "\n"
        << "set title " << gnuplot_text(title.str()) << "\n"
        << "set logscale xy\nset grid\nset key outside right\n"
        << "set xlabel 'CPU time [s]'\n"
        << "set ylabel 'max position error [m, rad]'\n"
        << "set format y '%.0e'\n";
    // Dark, distinguishable colours (gnuplot's default cycle has a pale yellow).
    static const char* colours[] = {"#1b9e77", "#d95f02", "#7570b3", "#e7298a",
                                    "#66a61e", "#a6761d", "#000000", "#1f78b4"};
    // Without a finished run gnuplot cannot autoscale ("all points y value
    // undefined"): fixed ranges make an empty, titled plot instead.
    if (plotted.empty()) out << "set xrange [1e-3:10]\nset yrange [1e-12:1]\n";
    out << "plot ";
    for (size_t i = 0; i < plotted.size(); ++i)
      out << (i ? ", \\\n     " : "") << gnuplot_path(dat) << " index " << i
          << " using 1:2 with linespoints lw 1.5 pt " << (i + 4) << " lc rgb '" << colours[i % 8]
          << "' title " << gnuplot_text(plotted[i]);
    if (plotted.empty()) out << "NaN title 'no finished run'";
    out << "\n";
  });
  outputs.add(png);
  run_gnuplot(gp, outputs.staging_dir(), {png});
}

void write_work_precision_markdown(std::ostream& out, const Model& model, double speed_m_per_s,
                                   const WorkPrecisionSettings& s, const WorkPrecisionResult& r) {
  const double t_end = s.t_end_s;
  const ReferenceSolution& ref = r.reference;
  out << "# Work-precision: " << model.name << " at " << speed_m_per_s << " m/s, "
      << t_end << " s\n\n"
      << "- Error: max over the output times (every " << s.output_interval_s
      << " s) and the body coordinates of |x - x_ref|, positions only (m, rad), wheelset spin "
         "angles excluded.\n"
      << "- Lateral error: the same over the lateral shifts and yaw angles only (the hunting "
         "motion).\n"
      << "- Work: process CPU seconds (std::clock) of the integration.\n"
      << "- Tolerances: atol = rtol x " << s.absolute_tolerance_scale << " on every state.\n"
      << "- Reference: " << integrator_name(ref.kind) << " at rtol " << number(ref.rtol)
      << ", atol " << number(ref.atol) << " (CPU " << number(ref.cpu_seconds) << " s); "
      << integrator_name(ref.check_kind) << " at rtol " << number(ref.check_rtol)
      << " differs from it by " << number(ref.check_difference)
      << ", an upper estimate of the reference's error. Errors below about that are not "
         "resolved.\n"
      << "- A run over " << s.cpu_budget_per_run_s
      << " CPU s is abandoned (\"gave up\"); tighter tolerances of that integrator are then "
         "skipped.\n\n";
  out << "| integrator | rtol | atol | error | (where) | lateral error | CPU s | steps | rhs | "
         "Jacobians | status |\n"
      << "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const WorkPrecisionRun& run : r.runs) {
    const bool done = std::isfinite(run.error);
    out << "| " << run.label << " | " << number(run.rtol) << " | " << number(run.atol) << " | "
        << (done ? number(run.error) : "-") << " | " << run.error_coordinate << " | "
        << (done ? number(run.lateral_error) : "-") << " | "
        << (done ? number(run.cpu_seconds) : "-")
        << " | " << run.stats.steps << " | " << run.stats.rhs_evaluations << " | "
        << run.stats.jacobian_evaluations << " | " << run.status << " |\n";
  }
  out << "\nCheapest run reaching an error bound, per integrator:\n\n"
      << "| integrator | error <= 1e-4: rtol, CPU s | error <= 1e-6: rtol, CPU s |\n"
      << "|---|---|---|\n";
  for (const std::string& label : labels_in_order(r)) {
    out << "| " << label;
    for (double bound : {1e-4, 1e-6}) {
      const WorkPrecisionRun* best = nullptr;
      for (const WorkPrecisionRun& run : r.runs)
        if (run.label == label && run.status == "ok" && run.error <= bound &&
            (!best || run.cpu_seconds < best->cpu_seconds))
          best = &run;
      out << " | "
          << (best ? number(best->rtol) + ", " + number(best->cpu_seconds) : std::string("-"));
    }
    out << " |\n";
  }
}

}  // namespace railstab
