#include <railstab/report/sensitivity_report.hpp>

#include <railstab/report/parameter_titles.hpp>

#include <railstab/io/csv.hpp>
#include <railstab/io/gnuplot.hpp>
#include <railstab/io/json_writer.hpp>

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace railstab {

namespace {

void write_csv(std::ostream& out, const CriticalSpeedSensitivities& s) {
  out << "rank,parameter,value,critical_speed_derivative_m_per_s_per_unit,elasticity,"
         "eigenvalue_real_derivative_per_s_per_unit,eigenvalue_imag_derivative_per_s_per_unit\n";
  for (size_t i = 0; i < s.parameters.size(); ++i) {
    const ParameterSensitivity& p = s.parameters[i];
    out << i + 1 << "," << csv_field(p.key) << "," << csv_number(p.value, p.key, 12) << ","
        << csv_number(p.critical_speed_derivative, "dVc/d " + p.key, 10) << ","
        << csv_number(p.elasticity, "elasticity of " + p.key, 10) << ","
        << csv_number(p.eigenvalue_derivative.real(), "dRe(lambda)/d " + p.key, 10) << ","
        << csv_number(p.eigenvalue_derivative.imag(), "dIm(lambda)/d " + p.key, 10) << "\n";
  }
}

void write_json(std::ostream& out, const CriticalSpeedSensitivities& s, const SensitivityReportContext& c) {
  JsonWriter j(out);
  j.begin_object()
      .field("scene_file", c.scene_path)
      .field("scene", c.scene_name)
      .field("critical_speed_m_per_s", s.critical_speed_m_per_s)
      .field("hunting_frequency_Hz", c.hunting_frequency_hz)
      .field("hunting_mode", c.mode)
      .field("eigenvalue_real_per_s", s.eigenvalue.real())
      .field("eigenvalue_imag_per_s", s.eigenvalue.imag())
      .field("eigenvalue_real_speed_derivative_per_m", s.real_part_speed_derivative)
      .field("method", "dVc/dp = -(dRe lambda/dp)/(dRe lambda/dV) at the critical speed; dlambda/dp "
                       "exact (left/right eigenvectors, AD dA/dp), dRe lambda/dV exact (AD dA/dV)");
  j.key("parameters").begin_array();
  for (size_t i = 0; i < s.parameters.size(); ++i) {
    const ParameterSensitivity& p = s.parameters[i];
    j.begin_object()
        .field("rank", int(i + 1))
        .field("parameter", p.key)
        .field("value", p.value)
        .field("critical_speed_derivative_m_per_s_per_unit", p.critical_speed_derivative)
        .field("elasticity", p.elasticity)
        .field("eigenvalue_real_derivative_per_s_per_unit", p.eigenvalue_derivative.real())
        .field("eigenvalue_imag_derivative_per_s_per_unit", p.eigenvalue_derivative.imag())
        .end_object();
  }
  j.end_array().end_object();
}

std::string md_text(const std::string& s) {
  std::string out;
  for (char ch : s) {
    if (ch == '|' || ch == '*' || ch == '_' || ch == '[' || ch == ']' || ch == '`') out += '\\';
    out += ch;
  }
  return out;
}

void write_markdown(std::ostream& md, const CriticalSpeedSensitivities& s, const SensitivityReportContext& c,
                    bool plot, const std::string& stem) {
  md << "# Critical-speed sensitivities: " << md_text(c.scene_name) << "\n\n"
     << std::fixed << std::setprecision(3) << "Critical speed **" << s.critical_speed_m_per_s
     << " m/s**, " << md_text(c.mode) << " at " << c.hunting_frequency_hz << " Hz.\n\n"
     << std::defaultfloat << std::setprecision(6)
     << "dVc/dp = -(d Re lambda/dp) / (d Re lambda/dV) at the critical speed (implicit function "
        "theorem); d lambda/dp from the left and right eigenvectors and the exact AD dA/dp "
        "(equilibrium and preloads included), d Re lambda/dV = "
     << s.real_part_speed_derivative
     << " 1/s per m/s, exact the same way with the speed as the parameter. Elasticity = (p/Vc) dVc/dp: the relative change of "
        "the critical speed per relative change of p.\n\n";
  if (plot) md << "![tornado plot](" << stem << "_sensitivity_tornado.png)\n\n";
  md << "| rank | parameter | value | dVc/dp (m/s per unit) | elasticity |\n|---|---|---|---|---|\n";
  for (size_t i = 0; i < s.parameters.size(); ++i) {
    const ParameterSensitivity& p = s.parameters[i];
    md << "| " << i + 1 << " | " << md_text(p.key) << " | " << p.value << " | "
       << p.critical_speed_derivative << " | " << p.elasticity << " |\n";
  }
}

void plot_tornado(OutputSet& outputs, const std::string& stem, const CriticalSpeedSensitivities& s,
                  const SensitivityReportContext& c) {
  const std::string data = stem + "_sensitivity_tornado.dat", script = stem + "_sensitivity_tornado.gp";
  const std::size_t n = std::min(c.top, s.parameters.size());
  outputs.write(data, [&](std::ostream& out) {
    out << "# row elasticity (largest at the top)\n" << std::setprecision(10);
    for (size_t i = 0; i < n; ++i) out << n - i << " " << s.parameters[i].elasticity << "\n";
  });
  const std::vector<std::string> files = {stem + "_sensitivity_tornado.png", stem + "_sensitivity_tornado.svg"};
  outputs.write(script, [&](std::ostream& gp) {
    std::ostringstream title;
    title << c.scene_name << ": critical speed " << std::fixed << std::setprecision(2)
          << s.critical_speed_m_per_s << " m/s, elasticity (p/Vc) dVc/dp of the " << n
          << " largest";
    gp << "# Run from the output folder: gnuplot " << script << "\n"
       << "set title " << gnuplot_text(title.str()) << "\nset xlabel 'elasticity (p/Vc) dVc/dp [-]'\n"
       << "set grid x\nunset key\nset style fill solid 0.8\nset yrange [0.4:" << n + 0.6 << "]\n"
       << "set ytics (";
    // The keys in words with their units (the CSV and JSON keep the keys).
    for (size_t i = 0; i < n; ++i)
      gp << (i ? ", " : "") << gnuplot_text(parameter_axis_title(s.parameters[i].key)) << " " << n - i;
    gp << ") font ',9'\nset xzeroaxis lt -1\n";
    const std::string plot = "plot " + gnuplot_path(data) +
                             " using (0):1:(0):2:($1-0.35):($1+0.35):($2 >= 0 ? 0x2e8b57 : 0xcd3333) "
                             "with boxxyerror lc rgb variable";
    gp << "set terminal pngcairo size 1100," << 200 + 28 * n << " font 'Sans,10' noenhanced\n"
       << "set output " << gnuplot_text(files[0]) << "\n" << plot << "\n"
       << "set terminal svg size 1100," << 200 + 28 * n << " dynamic font 'Sans,10' noenhanced\n"
       << "set output " << gnuplot_text(files[1]) << "\nreplot\nunset output\n";
  });
  for (const std::string& f : files) outputs.add(f);
  run_gnuplot(script, outputs.staging_dir(), files);
}

}  // namespace

std::vector<std::string> write_sensitivity_results(const CriticalSpeedSensitivities& s,
                                                   const SensitivityReportContext& c,
                                                   OutputSet& outputs, const std::string& stem,
                                                   bool plots) {
  const std::vector<std::string> all = {stem + "_sensitivity.csv", stem + "_sensitivity.json",
                                        stem + "_sensitivity.md", stem + "_sensitivity_tornado.dat",
                                        stem + "_sensitivity_tornado.gp", stem + "_sensitivity_tornado.png",
                                        stem + "_sensitivity_tornado.svg"};
  for (const std::string& f : all) outputs.replaces(f);
  const bool plot = plots && !s.parameters.empty();
  outputs.write(all[0], [&](std::ostream& out) { write_csv(out, s); });
  outputs.write(all[1], [&](std::ostream& out) { write_json(out, s, c); });
  outputs.write(all[2], [&](std::ostream& out) { write_markdown(out, s, c, plot, stem); });
  if (plot) plot_tornado(outputs, stem, s, c);
  return all;
}

void print_sensitivity_summary(std::ostream& out, const CriticalSpeedSensitivities& s,
                               const SensitivityReportContext& c, std::size_t rows) {
  out << c.scene_name << ": critical speed " << std::fixed << std::setprecision(3)
      << s.critical_speed_m_per_s << " m/s (" << c.mode << ", " << c.hunting_frequency_hz
      << " Hz); largest elasticities (p/Vc) dVc/dp:\n" << std::defaultfloat << std::setprecision(4);
  for (size_t i = 0; i < std::min(rows, s.parameters.size()); ++i)
    out << "  " << std::setw(10) << s.parameters[i].elasticity << "  " << s.parameters[i].key
        << " (dVc/dp = " << s.parameters[i].critical_speed_derivative << ")\n";
}

}  // namespace railstab
