#include "cli/verify_command.hpp"

#include "cli/numeric_flags.hpp"
#include "setup/prepare_scene.hpp"
#include "io/csv.hpp"
#include "io/file_names.hpp"
#include "io/gnuplot.hpp"
#include "io/json_writer.hpp"
#include "io/output_set.hpp"
#include "verify/verification.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <iomanip>
#include <iostream>
#include <memory>

namespace railstab {

namespace {

struct VerifyArgs {
  std::string scene;
  SceneOverrides overrides;
  VerificationOptions options;
  std::string json;
  std::string out_dir = "out";
  bool scene_offsets = false;
  bool plots = true;
};

void write_verification_json(std::ostream& out, const Model& model,
                             const VerificationResult& r) {
  {
    JsonWriter j(out);
    j.begin_object()
        .field("scene", model.name)
        .field("speed_m_s", r.speed_m_per_s)
        .field("mode", r.mode_name)
        .field("signal", r.signal)
        .field("eigen_real_per_s", r.eigen_real_per_s)
        .field("eigen_frequency_hz", r.eigen_frequency_hz)
        .field("fitted_real_per_s", r.fitted_real_per_s)
        .field("fitted_frequency_hz", r.fitted_frequency_hz)
        .field("real_difference_relative", r.real_difference_relative)
        .field("frequency_difference_relative", r.frequency_difference_relative)
        .field("fit_rms_residual_relative", r.fit.rms_residual / r.fit.rms_signal)
        .field("fit_window_s_from", r.window_start_s)
        .field("fit_window_s_to", r.window_end_s)
        .field("response", r.fitted_real_per_s > 0.0 ? "grows" : "decays")
        .field("integration_error_relative", r.integration_error_relative)
        .field("integration_wall_seconds", r.integration_seconds)
        .field("integrator", r.integrator)
        .field("relative_tolerance", r.relative_tolerance)
        .field("start", r.start)
        .field("stopped_at_track_change", r.track_limited)
        .end_object();
  }
}

std::vector<std::string> fit_plot_file_names(const std::string& stem) {
  return {stem + "_fit.dat", stem + "_fit.gp", stem + "_fit.png"};
}

void plot_fit(const VerificationResult& r, OutputSet& outputs, const std::string& stem,
              const Model& model) {
  const std::string data = stem + "_fit.dat";
  outputs.write(data, [&](std::ostream& out) {
    out << std::setprecision(10);
    const double t0 = r.window_times.front();
    for (size_t i = 0; i < r.window_times.size(); ++i) {
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
       << gnuplot_text(r.signal + " - equilibrium [mm]") << "\n"
       << "set title " << gnuplot_text(title.str()) << "\n"
       << "plot " << gnuplot_path(data) << " using 1:2 with lines lw 2 title 'nonlinear time "
       << "domain', " << gnuplot_path(data)
       << " using 1:3 with lines dt 2 lw 1.5 title 'fitted damped sinusoid'\n";
  });
  outputs.add(png);
  run_gnuplot(script, outputs.staging_dir(), {png});
}

void run_verify(const VerifyArgs& a) {
  if (!(a.options.settle_periods < a.options.periods)) {
    std::ostringstream msg;
    msg << "--settle-periods " << a.options.settle_periods << " must be below --periods "
        << a.options.periods << " (the fit window lies between them)";
    throw std::invalid_argument(msg.str());
  }
  if (a.plots) require_gnuplot();
  const PreparedScene s = prepare_scene(a.scene, a.overrides);
  std::cerr << "verify " << s.model.name << " at " << s.speed_m_per_s
            << " m/s: eigen-analysis, then two time-domain runs (tolerance and 100x tighter)\n";
  VerificationOptions options = a.options;
  if (a.scene_offsets) options.initial_state = perturbed_initial_state(s);
  const VerificationResult r = verify_least_stable_mode(s.model, s.speed_m_per_s, s.equilibrium.state, options);
  const std::string stem =
      file_stem(s.model.name) + "_verify_" + speed_file_tag(r.speed_m_per_s);
  OutputSet outputs(a.out_dir);
  for (const std::string& name : fit_plot_file_names(stem)) outputs.replaces(name);
  auto json_writer = [&](std::ostream& out) { write_verification_json(out, s.model, r); };
  outputs.replaces(stem + ".json");  // with --json elsewhere, an earlier default goes
  if (a.json.empty()) outputs.write(stem + ".json", json_writer);
  else outputs.write_at(a.json, json_writer);
  if (a.plots) plot_fit(r, outputs, stem, s.model);
  const std::vector<std::string> written = outputs.commit();
  std::cout << std::setprecision(6) << s.model.name << " at " << r.speed_m_per_s
            << " m/s, least stable lateral mode: " << r.mode_name << " (signal " << r.signal << ")\n"
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
            << " of the signal (vs 100x tighter tolerances), wall " << r.integration_seconds
            << " s\n";
  for (const std::string& f : written) std::cout << "wrote " << f << "\n";
}

}  // namespace

void register_verify_command(CLI::App& app) {
  auto a = std::make_shared<VerifyArgs>();
  CLI::App* cmd = app.add_subcommand(
      "verify", "time-domain check of the least stable mode: fitted rate and frequency against "
                "the eigenvalue");
  cmd->add_option("scene", a->scene, "scene file (TOML)")->required()->check(CLI::ExistingFile);
  cmd->add_option("--speed", a->overrides.speed_m_per_s, "speed V in m/s")
      ->check(finite_in(flag_ranges::speed_m_per_s));
  cmd->add_option("--arc-length", a->overrides.reference_arc_length_m,
                  "arc length (m) of the reference point at t = 0")
      ->check(finite_in(flag_ranges::arc_length_m));
  cmd->add_option("--amplitude", a->options.amplitude_m,
                  "initial lateral amplitude (m) of the body that moves most laterally")
      ->capture_default_str()
      ->check(finite_in(flag_ranges::amplitude_m));
  cmd->add_option("--periods", a->options.periods,
                  "simulated length in periods of the mode (cut where the uniform track ends)")
      ->capture_default_str()
      ->check(finite_in(flag_ranges::periods));
  cmd->add_option("--settle-periods", a->options.settle_periods,
                  "periods skipped before the fit window")
      ->capture_default_str()
      ->check(finite_in(flag_ranges::settle_periods));
  cmd->add_flag("--scene-offsets", a->scene_offsets,
                "start from the scene's initial offsets and rates instead of the mode "
                "perturbation (e.g. the thesis cases' 1 mm offset of wheelset1)");
  cmd->add_option("--json", a->json, "JSON output (default OUT/<scene>_verify_<V>mps.json)");
  cmd->add_option("--out", a->out_dir, "output directory")->capture_default_str();
  cmd->add_flag("!--no-plots", a->plots, "do not run gnuplot (JSON only)");
  cmd->callback([a] { run_verify(*a); });
}

}  // namespace railstab
