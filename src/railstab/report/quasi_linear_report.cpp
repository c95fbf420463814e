#include <railstab/report/quasi_linear_report.hpp>

#include <railstab/io/gnuplot.hpp>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace railstab {

namespace {

void write_csv(std::ostream& out, const QuasiLinearCurve& c) {
  out << "amplitude_m,equivalent_conicity,critical_speed_found,critical_speed_m_per_s,"
         "frequency_Hz,mode,note\n";
  out << std::setprecision(10);
  for (const QuasiLinearCurvePoint& p : c.points) {
    out << p.amplitude_m << "," << p.equivalent_conicity << "," << (p.critical_speed_found ? 1 : 0)
        << ",";
    if (p.critical_speed_found) out << p.critical_speed_m_per_s << "," << p.frequency_Hz;
    else out << ",";
    out << ",\"" << p.mode << "\",\"" << p.note << "\"\n";
  }
}

void write_json(std::ostream& out, const Model& model, const QuasiLinearCurve& c, double plain) {
  JsonWriter j(out);
  j.begin_object();
  j.field("scene", model.name);
  j.field("method", std::string("harmonic linearisation of the rigid-contact characteristic "
                                "functions at each amplitude (docs/quasi_linear.md)"));
  j.field("has_profile_contact", c.has_profile_contact);
  j.key("plain_critical_speed_m_per_s");
  if (plain > 0) j.value(plain); else j.null();
  j.field("flange_contact_amplitude_m", c.flange_contact_amplitude_m);
  j.field("cpu_s", c.cpu_seconds);
  j.key("points").begin_array();
  for (const QuasiLinearCurvePoint& p : c.points) {
    j.begin_object();
    j.field("amplitude_m", p.amplitude_m);
    j.field("equivalent_conicity", p.equivalent_conicity);
    j.field("critical_speed_found", p.critical_speed_found);
    j.key("critical_speed_m_per_s");
    if (p.critical_speed_found) j.value(p.critical_speed_m_per_s); else j.null();
    j.key("frequency_Hz");
    if (p.critical_speed_found) j.value(p.frequency_Hz); else j.null();
    j.field("mode", p.mode);
    j.field("note", p.note);
    j.end_object();
  }
  j.end_array();
  j.end_object();
  out << "\n";
}

}  // namespace

std::vector<std::string> quasi_linear_curve_file_names(const std::string& stem) {
  const std::string b = stem + "_quasi_linear_curve";
  return {b + ".csv", b + ".json", b + ".dat", b + ".gp", b + ".png", b + ".svg"};
}

std::vector<std::string> write_quasi_linear_curve(const Model& model, const QuasiLinearCurve& curve,
                                                  double plain, double from_m_per_s,
                                                  double to_m_per_s, OutputSet& outputs,
                                                  const std::string& stem, bool plots) {
  const std::vector<std::string> names = quasi_linear_curve_file_names(stem);
  std::vector<std::string> written{names[0], names[1]};
  outputs.write(names[0], [&](std::ostream& out) { write_csv(out, curve); });
  outputs.write(names[1], [&](std::ostream& out) { write_json(out, model, curve, plain); });
  if (!plots) return written;
  // Data: speed [m/s], amplitude [mm]; a blank line where no speed was found
  // (the line is broken there).
  outputs.write(names[2], [&](std::ostream& out) {
    out << "# critical_speed_m_per_s amplitude_mm (quasi-linear; blank line: none found)\n"
        << std::setprecision(10);
    for (const QuasiLinearCurvePoint& p : curve.points) {
      if (p.critical_speed_found)
        out << p.critical_speed_m_per_s << " " << p.amplitude_m * 1e3 << "\n";
      else
        out << "\n";
    }
  });
  outputs.write(names[3], [&](std::ostream& gp) {
    gp << "# Run from the output folder: gnuplot " << names[3] << "\n"
       << "set datafile separator whitespace\nset grid\nset key top left noenhanced\n"
       << "set title " << gnuplot_text(model.name + ": quasi-linear critical speed by amplitude")
       << "\nset xlabel 'speed [m/s]'\nset ylabel 'wheelset lateral amplitude A [mm]'\n"
       << "set xrange [" << from_m_per_s << ":" << to_m_per_s << "]\nset yrange [0:*]\n";
    if (curve.flange_contact_amplitude_m > 0)
      gp << "set arrow from graph 0, first " << curve.flange_contact_amplitude_m * 1e3
         << " to graph 1, first " << curve.flange_contact_amplitude_m * 1e3
         << " nohead dt 3 lc rgb 'gray40'\nset label 'flange contact' at graph 0.02, first "
         << curve.flange_contact_amplitude_m * 1e3 << " offset 0,0.6 tc rgb 'gray40'\n";
    std::string plot = "plot " + gnuplot_path(names[2]) +
                       " using 1:2 with linespoints pt 7 ps 0.6 lw 2 title 'V_c(A), quasi-linear'";
    if (plain > 0) {
      std::ostringstream v, label;
      v << std::setprecision(10) << plain;
      label << std::fixed << std::setprecision(2) << plain;
      gp << "set arrow from " << v.str() << ", graph 0 to " << v.str()
         << ", graph 1 nohead lw 1.5 lc rgb 'red'\n"
         << "set label " << gnuplot_text("linear V_c = " + label.str() + " m/s") << " at " << v.str()
         << ", graph 0.95 offset 0.5,0 tc rgb 'red'\n";
    }
    for (const char* ext : {".png", ".svg"}) {
      gp << (std::string(ext) == ".png"
                 ? "set terminal pngcairo size 900,600 font 'Sans,10' noenhanced\n"
                 : "set terminal svg size 900,600 dynamic font 'Sans,10' noenhanced\n")
         << "set output " << gnuplot_text(names[0].substr(0, names[0].size() - 4) + ext) << "\n"
         << plot << "\nunset output\n";
    }
  });
  for (size_t k : {size_t(4), size_t(5)}) outputs.add(names[k]);
  run_gnuplot(names[3], outputs.staging_dir(), {names[4], names[5]});
  for (size_t k = 2; k < names.size(); ++k) written.push_back(names[k]);
  return written;
}

void write_quasi_linear_json(JsonWriter& j, const QuasiLinearCriticalSpeed& q) {
  j.key("quasi_linear").begin_object();
  j.field("amplitude_m", q.amplitude_m);
  j.field("has_profile_contact", q.has_profile_contact);
  j.key("wheelsets").begin_array();
  for (const QuasiLinearWheelset& w : q.wheelsets) {
    j.begin_object();
    j.field("body", w.body);
    j.field("centre_m", w.centre_m);
    j.field("equivalent_conicity", w.equivalent_conicity);
    j.field("rolling_radius_gain", w.rolling_radius_gain);
    j.field("contact_angle_gain_rad_per_m", w.contact_angle_gain_per_m);
    j.field("roll_gain_rad_per_m", w.roll_gain_per_m);
    j.end_object();
  }
  j.end_array();
  j.end_object();
}

std::string quasi_linear_markdown(const QuasiLinearCriticalSpeed& q) {
  std::ostringstream s;
  s << "\n## Quasi-linear contact\n\n"
    << "Wheelset lateral amplitude A = " << q.amplitude_m * 1e3 << " mm. ";
  if (!q.has_profile_contact) {
    s << "No profile contact: the contact functions are linear in the wheelset's shift, their "
         "harmonic linearisation is the function itself, and this is the plain critical speed.\n";
    return s.str();
  }
  s << "The profile contacts are replaced by the harmonic (describing-function) linearisation "
       "of their rigid-contact characteristic functions at A (docs/quasi_linear.md); the Hopf "
       "criticality is not assessed on this model.\n\n"
    << "| wheelset | centre y_c [mm] | equivalent conicity N_dr(A)/2 | roll gain [rad/m] |\n"
    << "|---|---|---|---|\n";
  for (const QuasiLinearWheelset& w : q.wheelsets)
    s << "| " << w.body << " | " << w.centre_m * 1e3 << " | " << w.equivalent_conicity << " | "
      << w.roll_gain_per_m << " |\n";
  return s.str();
}

}  // namespace railstab
