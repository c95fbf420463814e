#include <railstab/report/assessment_report.hpp>

#include <railstab/io/csv.hpp>
#include <railstab/io/gnuplot.hpp>
#include <railstab/io/json_writer.hpp>

#include <filesystem>
#include <iomanip>
#include <sstream>

namespace railstab {

namespace {

bool is_stability(const AssessedQuantity& q) { return !q.windows.empty(); }

std::string verdict(bool passed) { return passed ? "pass" : "FAIL"; }

}  // namespace

std::string write_assessment_report(const Model& model, const RunningStabilityAssessment& a,
                                    const AssessmentSpec& spec, const AssessmentRunConditions& run,
                                    OutputSet& outputs, const std::string& stem, bool plots) {
  const std::string windows_csv = stem + "_assessment_windows.csv";
  const std::filesystem::path windows_staged = outputs.write(windows_csv, [&](std::ostream& out) {
    out << "quantity,subject,window_start_m,window_end_m,rms,limit,rms_over_limit\n" << std::setprecision(10);
    for (const AssessedQuantity& q : a.quantities)
      for (const WindowValue& w : q.windows) {
        out << q.quantity << ',' << csv_field(q.subject) << ',' << w.start_m << ',' << w.end_m << ',';
        put_csv_number(out, w.value, [&] { return q.quantity + " of " + q.subject; });
        out << ',' << q.limit << ',' << w.value / q.limit << '\n';
      }
  });
  outputs.write(stem + "_assessment.json", [&](std::ostream& out) {
    JsonWriter j(out);
    j.begin_object()
        .field("scene", model.name)
        .field("speed_m_per_s", run.speed_m_per_s)
        .field("standard", "EN 14363 running stability (normal measuring method: Sum Y rms; simplified "
                           "method: bogie frame lateral acceleration rms) and the 2 m safety quantities")
        .field("excitation", run.excitation)
        .field("integrator", run.integrator)
        .field("relative_tolerance", run.relative_tolerance)
        .field("output_interval_s", run.output_interval_s)
        .field("simulated_s", run.simulated_s)
        .field("distance_m", a.distance_m)
        .field("stopped_early", a.stopped_early)
        .field("instability_frequency_Hz", a.instability_frequency_Hz)
        .field("band_low_Hz", a.band_low_Hz)
        .field("band_high_Hz", a.band_high_Hz)
        .field("filter_order", spec.stability_filter_order)
        .field("window_m", spec.stability_window_m)
        .field("window_step_m", spec.stability_window_step_m)
        .field("passed", a.passed);
    j.key("failures_without_value").begin_array();
    for (const std::string& f : a.failures_without_value) j.value(f);
    j.end_array();
    j.key("quantities").begin_array();
    for (const AssessedQuantity& q : a.quantities)
      j.begin_object()
          .field("quantity", q.quantity)
          .field("subject", q.subject)
          .field("unit", q.unit)
          .field("value", q.value)
          .field("limit", q.limit)
          .field("margin", q.margin)
          .field("passed", q.passed)
          .end_object();
    j.end_array().end_object();
  });
  std::ostringstream md, shown;
  md << std::setprecision(4) << "# EN 14363 running-stability assessment: " << model.name << " at "
     << run.speed_m_per_s << " m/s\n\n"
     << "**Verdict: " << (a.passed ? "pass" : "FAIL") << "**"
     << (a.stopped_early.empty() ? "" : " (the run stopped early: " + a.stopped_early + ")") << "\n\n"
     << "## Run\n\n"
     << "- excitation: " << run.excitation << "\n"
     << "- integrator " << run.integrator << ", rtol " << run.relative_tolerance << ", outputs every "
     << run.output_interval_s << " s, " << run.simulated_s
     << " s simulated, " << a.distance_m << " m of track\n"
     << "- instability frequency f0 = " << a.instability_frequency_Hz
     << " Hz (peak of the leading wheelset's Sum Y spectrum over the run's second half); band-pass "
     << a.band_low_Hz << "-" << a.band_high_Hz << " Hz, Butterworth, prototype order "
     << spec.stability_filter_order << " (EN 14363's order is not public to us: `assessment.stability_filter_order`)\n"
     << "- rms over " << spec.stability_window_m << " m windows stepped by " << spec.stability_window_step_m
     << " m; 2 m means stepped by 0.5 m\n\n"
     << "## Quantities\n\n| quantity | subject | value | limit | margin | verdict |\n|---|---|---|---|---|---|\n";
  for (const AssessedQuantity& q : a.quantities) {
    const double scale = q.unit == "N" ? 1e-3 : 1.0;
    const std::string unit = q.unit == "N" ? " kN" : (q.unit.empty() ? "" : " " + q.unit);
    md << "| " << q.quantity << " | " << q.subject << " | " << q.value * scale << unit << " | " << q.limit * scale
       << unit << " | " << 100.0 * q.margin << " % | " << verdict(q.passed) << " |\n";
  }
  for (const std::string& f : a.failures_without_value) md << "\n**FAIL:** " << f << "\n";
  md << "\nLimits: Sum Y rms <= alpha (10 kN + P0/3) / 2 (half Prud'homme's limit, P0 the static axle load, "
     << "alpha = " << spec.prudhomme_factor << "); bogie frame lateral acceleration rms <= (12 - m_b/5) / 2 m/s2 "
     << "(m_b the bogie's mass in t: frame and wheelsets); Sum Y over 2 m <= alpha (10 kN + P0/3); "
     << "Y/Q over 2 m <= " << spec.y_over_q_limit << ". The clause numbers and the filter order of EN 14363 "
     << "are not public to us; the formulas are those EN 14363 and UIC 518 are quoted with "
     << "(docs/assessment.md).\n";
  outputs.write(stem + "_assessment.md", [&](std::ostream& out) { out << md.str(); });
  shown << std::setprecision(4) << "EN 14363 running stability of " << model.name << " at " << run.speed_m_per_s
        << " m/s: " << (a.passed ? "pass" : "FAIL") << " (";
  if (!a.quantities.empty()) shown << "f0 " << a.instability_frequency_Hz << " Hz, ";
  shown << a.distance_m << " m)\n";
  for (const AssessedQuantity& q : a.quantities)
    shown << "  " << std::left << std::setw(32) << q.quantity << std::setw(12) << q.subject << std::right
          << " " << q.value << " / " << q.limit << " " << q.unit << "  " << verdict(q.passed) << "\n";
  for (const std::string& f : a.failures_without_value) shown << "  FAIL: " << f << "\n";
  if (!a.stopped_early.empty()) shown << "  the run stopped early: " << a.stopped_early << "\n";
  if (plots) {
    const std::string script = stem + "_assessment_plots.gp", png = stem + "_assessment_rms.png";
    outputs.write(script, [&](std::ostream& gp) {
      gp << "# Run from the output folder: gnuplot " << script << "\n"
         << "if (!exists(\"windows_csv\")) windows_csv = " << gnuplot_path(windows_csv) << "\n"
         << "set datafile separator ','\nset terminal pngcairo size 900,520 font 'Sans,10' noenhanced\n"
         << "set output " << gnuplot_text(png) << "\nset grid\nset key outside right\n"
         << "set title " << gnuplot_text(model.name + ": EN 14363 running stability, rms over distance / limit") << "\n"
         << "set xlabel 'window end [m]'\nset ylabel 'rms / limit [-]'\nset yrange [0:*]\n"
         // a margin above, so that the limit line (1) on a tic is not hidden
         // in the frame's border
         << "set offsets 0, 0, graph 0.08, 0\nplot ";
      int curve = 0;
      for (const AssessedQuantity& q : a.quantities) {
        if (!is_stability(q)) continue;
        gp << (curve++ ? ", " : "") << "windows_csv skip 1 using ((strcol(1) eq " << gnuplot_text(q.quantity)
           << " && strcol(2) eq " << gnuplot_text(q.subject) << ") ? $4 : 1/0):7 with lines lw 1.5 title "
           << gnuplot_text(q.subject + (q.quantity == "sum_y_rms" ? " Sum Y" : " frame acceleration"));
      }
      gp << (curve ? ", " : "") << "1 with lines dt 2 lc 'black' title 'limit'\n";
    });
    outputs.add(png);
    run_gnuplot(script, outputs.staging_dir(), {png},
                {{"windows_csv", std::filesystem::absolute(windows_staged).string()}});
  }
  return shown.str();
}

}  // namespace railstab
