#include <railstab/report/verify_report.hpp>

#include <railstab/io/csv.hpp>
#include <railstab/io/gnuplot.hpp>
#include <railstab/io/json_writer.hpp>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace railstab {

void write_verification_json(std::ostream& out, const Model& model, const VerificationResult& r) {
  JsonWriter j(out);
  j.begin_object()
      .field("scene", model.name)
      .field("speed_m_per_s", r.speed_m_per_s)
      .field("mode", r.mode_name)
      .field("signal", r.signal)
      .field("eigenvalue_real_per_s", r.eigen_real_per_s)
      .field("eigenvalue_frequency_Hz", r.eigen_frequency_hz)
      .field("fitted_real_per_s", r.fitted_real_per_s)
      .field("fitted_frequency_Hz", r.fitted_frequency_hz)
      .field("real_difference_relative", r.real_difference_relative)
      .field("frequency_difference_relative", r.frequency_difference_relative)
      .field("fit_rms_residual_relative", r.fit.rms_residual / r.fit.rms_signal)
      .field("fit_window_from_s", r.window_start_s)
      .field("fit_window_to_s", r.window_end_s)
      .field("response", r.fitted_real_per_s > 0.0 ? "grows" : "decays")
      .field("integration_error_relative", r.integration_error_relative)
      .field("integration_wall_s", r.integration_seconds)
      .field("integration_cpu_s", r.integration_cpu_seconds)
      .field("reference_integration_wall_s", r.reference_integration_seconds)
      .field("reference_integration_cpu_s", r.reference_integration_cpu_seconds)
      .field("integrator", r.integrator)
      .field("relative_tolerance", r.relative_tolerance)
      .field("start", r.start)
      .field("stopped_at_track_change", r.track_limited)
      .end_object();
}

std::vector<std::string> verification_plot_file_names(const std::string& stem) {
  return {stem + "_fit.dat", stem + "_fit.gp", stem + "_fit.png"};
}

void write_verification_plot(const VerificationResult& r, OutputSet& outputs,
                             const std::string& stem, const Model& model) {
  const std::string data = stem + "_fit.dat";
  outputs.write(data, [&](std::ostream& out) {
    out << std::setprecision(10);
    const double t0 = r.window_times.front();
    for (size_t i = 0; i < r.window_times.size(); ++i) {
      // The fitted signal c + exp(sigma tau) (a cos(omega tau) + b sin(omega tau)),
      // tau measured from the start of the fit window.
      const double tau = r.window_times[i] - t0;
      const double fit = std::exp(r.fit.sigma_per_s * tau) *
                             (r.fit.a * std::cos(r.fit.omega_rad_s * tau) +
                              r.fit.b * std::sin(r.fit.omega_rad_s * tau)) +
                         r.fit.c;
      const auto what = [&] { return "fit data at t = " + std::to_string(r.window_times[i]) + " s"; };
      put_csv_number(out, r.window_times[i], what);
      out << ' ';
      put_csv_number(out, r.window_signal[i] * 1e3, what);
      out << ' ';
      put_csv_number(out, fit * 1e3, what);
      out << '\n';
    }
  });
  const std::string png = stem + "_fit.png";
  const std::string script = stem + "_fit.gp";
  std::ostringstream title;
  title << model.name << " at " << r.speed_m_per_s << " m/s: eigenvalue " << r.eigen_real_per_s
        << " 1/s, " << r.eigen_frequency_hz << " Hz; fit " << r.fitted_real_per_s << " 1/s, "
        << r.fitted_frequency_hz << " Hz";
  outputs.write(script, [&](std::ostream& gp) {
    gp << "# Run from the output folder: gnuplot " << script << "\n"
       << "set terminal pngcairo size 900,480 font 'Sans,10' noenhanced\nset output "
       << gnuplot_text(png) << "\nset grid\nset xlabel 'time [s]'\nset ylabel "
       << gnuplot_text(r.signal + " - equilibrium (x 1000: mm, mrad)") << "\n"
       << "set title " << gnuplot_text(title.str()) << "\n"
       << "plot " << gnuplot_path(data) << " using 1:2 with lines lw 2 title 'nonlinear time "
       << "domain', " << gnuplot_path(data)
       << " using 1:3 with lines dt 2 lw 1.5 title 'fitted damped sinusoid'\n";
  });
  outputs.add(png);
  run_gnuplot(script, outputs.staging_dir(), {png});
}

void print_verification_summary(std::ostream& out, const Model& model,
                                const VerificationResult& r) {
  out << std::setprecision(6) << model.name << " at " << r.speed_m_per_s
      << " m/s, least stable mode: " << r.mode_name << " (signal " << r.signal << ")\n"
      << "                 real part [1/s]   frequency [Hz]\n"
      << "  eigenvalue     " << std::setw(15) << r.eigen_real_per_s << std::setw(17)
      << r.eigen_frequency_hz << "\n"
      << "  time domain    " << std::setw(15) << r.fitted_real_per_s << std::setw(17)
      << r.fitted_frequency_hz << "\n"
      << "  difference     " << std::setw(14) << 100.0 * r.real_difference_relative << "%"
      << std::setw(16) << 100.0 * r.frequency_difference_relative << "%\n"
      << "response " << (r.fitted_real_per_s > 0.0 ? "grows" : "decays") << "; fit window "
      << r.window_start_s << "-" << r.window_end_s << " s, fit residual "
      << r.fit.rms_residual / r.fit.rms_signal << " of the signal rms\n"
      << "integration: error estimate " << r.integration_error_relative
      << " of the signal (vs 100x tighter tolerances); run: wall " << r.integration_seconds
      << " s, CPU " << r.integration_cpu_seconds << " s; tighter reference run: wall "
      << r.reference_integration_seconds << " s, CPU " << r.reference_integration_cpu_seconds
      << " s\n";
}

}  // namespace railstab
