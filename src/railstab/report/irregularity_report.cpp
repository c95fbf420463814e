#include <railstab/report/irregularity_report.hpp>

#include <railstab/io/csv.hpp>
#include <railstab/io/gnuplot.hpp>
#include <railstab/io/json_writer.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <numbers>
#include <sstream>

namespace railstab {

namespace {

std::string channel_name(int c) { return std::string(name_in(kIrregularityChannelNames, IrregularityChannel(c))); }

}  // namespace

std::string write_irregularity_report(const TrackIrregularities& irr, const IrregularityCheck& check,
                                      const std::string& scene_name, OutputSet& outputs,
                                      const std::string& stem, bool plots) {
  const IrregularitySpec& spec = irr.spec();
  const std::string channels_csv = stem + "_irregularities.csv";
  const std::string psd_csv = stem + "_irregularity_psd.csv";
  const std::filesystem::path channels_staged = outputs.write(channels_csv, [&](std::ostream& out) {
    out << "arc_length_m";
    for (int c = 0; c < kIrregularityChannels; ++c) out << ',' << channel_name(c) << "_m";
    out << '\n' << std::setprecision(10);
    const std::vector<double>& s = irr.sample_arc_lengths_m();
    for (size_t i = 0; i < s.size(); ++i) {
      put_csv_number(out, s[i], [] { return std::string("arc_length_m"); });
      for (int c = 0; c < kIrregularityChannels; ++c) {
        out << ',';
        put_csv_number(out, irr.samples(IrregularityChannel(c))[i], [&] { return channel_name(c) + "_m"; });
      }
      out << '\n';
    }
  });
  const std::filesystem::path psd_staged = outputs.write(psd_csv, [&](std::ostream& out) {
    out << "omega_rad_per_m,wavelength_m";
    for (int c = 0; c < kIrregularityChannels; ++c)
      out << ',' << channel_name(c) << "_welch_m2_per_rad_per_m," << channel_name(c)
          << "_target_m2_per_rad_per_m";
    out << '\n' << std::setprecision(10);
    const std::vector<double>& w = check.channels[0].welch.omega_rad_per_m;
    for (size_t k = 1; k < w.size(); ++k) {  // no DC bin: its wavelength is infinite
      out << w[k] << ',' << 2.0 * std::numbers::pi / w[k];
      for (int c = 0; c < kIrregularityChannels; ++c) {
        out << ',';
        put_csv_number(out, check.channels[size_t(c)].welch.psd_m2_per_rad_per_m[k], [] { return std::string("welch"); });
        out << ',' << check.channels[size_t(c)].target_psd_m2_per_rad_per_m[k];
      }
      out << '\n';
    }
  });
  const std::string source = irr.measured() ? "measured (" + spec.measured->path + ")"
                                            : std::string(name_in(kIrregularitySpectrumNames, spec.spectrum));
  std::ostringstream shown;
  shown << std::setprecision(4) << scene_name << ": " << source;
  if (!irr.measured())
    shown << ", seed " << spec.seed << ", wavelengths " << spec.wavelength_min_m << "-" << spec.wavelength_max_m << " m";
  shown << ", " << irr.last_m() - irr.first_m() << " m from " << irr.first_m() << " m\n";
  outputs.write(stem + "_irregularities.json", [&](std::ostream& out) {
    JsonWriter j(out);
    j.begin_object()
        .field("scene", scene_name);
    if (irr.measured()) {
      j.key("psd").null().field("file", spec.measured->path);
      j.key("channels_in_file").begin_array();
      for (int c = 0; c < kIrregularityChannels; ++c)
        if (spec.measured->in_file[size_t(c)]) j.value(channel_name(c));
      j.end_array();
    } else {
      j.field("psd", std::string(name_in(kIrregularitySpectrumNames, spec.spectrum)))
          .field("seed", double(spec.seed))
          .field("wavelength_min_m", spec.wavelength_min_m)
          .field("wavelength_max_m", spec.wavelength_max_m)
          .field("components", spec.components);
    }
    j.field("start_m", irr.first_m())
        .field("length_m", irr.last_m() - irr.first_m())
        .field("sample_interval_m", spec.sample_interval_m)
        .field("amplitude_scale", spec.amplitude_scale)
        .field("fade_in_m", spec.fade_in_m)
        .field("fade_out_m", spec.fade_out_m)
        .field("welch_segment_m", check.segment_samples * spec.sample_interval_m)
        .field("welch_segments", check.channels[0].welch.segments);
    j.key("channels").begin_array();
    for (int c = 0; c < kIrregularityChannels; ++c) {
      const IrregularityChannelCheck& ch = check.channels[size_t(c)];
      j.begin_object().field("name", channel_name(c)).field("sample_rms_m", ch.sample_rms_m);
      if (check.has_target)
        j.field("synthesised_rms_m", ch.synthesised_rms_m).field("target_rms_m", ch.target_rms_m);
      j.end_object();
      shown << "  " << std::left << std::setw(12) << channel_name(c) << std::right << " rms "
            << ch.sample_rms_m * 1e3 << " mm";
      if (check.has_target) shown << " (target over the band " << ch.target_rms_m * 1e3 << " mm)";
      shown << "\n";
    }
    j.end_array().end_object();
  });
  if (plots) {
    const std::string script = stem + "_irregularity_plots.gp";
    const std::string channels_png = stem + "_irregularities.png", psd_png = stem + "_irregularity_psd.png";
    outputs.write(script, [&](std::ostream& gp) {
      gp << "# Run from the output folder: gnuplot " << script << "\n"
         << "if (!exists(\"channels_csv\")) channels_csv = " << gnuplot_path(channels_csv) << "\n"
         << "if (!exists(\"psd_csv\")) psd_csv = " << gnuplot_path(psd_csv) << "\n"
         << "set datafile separator ','\n"
         << "set terminal pngcairo size 900,700 font 'Sans,10' noenhanced\n"
         << "set output " << gnuplot_text(channels_png) << "\n"
         << "set multiplot layout 4,1 title "
         << gnuplot_text(scene_name + ": track irregularities (" + source + ")")
         << "\nset grid\n";
      for (int c = 0; c < kIrregularityChannels; ++c)
        gp << "set ylabel " << gnuplot_text(channel_name(c) + " [mm]") << "\n"
           << (c == 3 ? "set xlabel 'arc length [m]'\n" : "unset xlabel\n")
           << "plot channels_csv skip 1 using 1:($" << 2 + c << "*1000) with lines lw 1 notitle\n";
      gp << "unset multiplot\n"
         << "set output " << gnuplot_text(psd_png) << "\n"
         << "set multiplot layout 2,2 title "
         << gnuplot_text(scene_name + (check.has_target ? ": PSD of the irregularities (Welch) against the target"
                                                        : ": PSD of the irregularities (Welch)"))
         << "\nset logscale xy\nset format y '1e%L'\nset grid\nset xlabel 'Omega [rad/m]'\nset ylabel 'PSD [m^2/(rad/m)]'\n"
         // The band and an octave either side: beyond it the estimate is the
         // window's leakage floor, decades down.
         << "set xrange [" << std::numbers::pi / spec.wavelength_max_m << ":" << 4.0 * std::numbers::pi / spec.wavelength_min_m << "]\n"
         << "set key bottom left\n";
      // The y range from the estimate inside the band (2 pi / wavelength_max
      // to 2 pi / wavelength_min), a decade either side: beyond the band the
      // synthesis is filtered to nothing, and an autoscaled axis down to
      // that floor (1e-20) squeezes the band into a quarter of the panel.
      const double band_lo = 2.0 * std::numbers::pi / spec.wavelength_max_m;
      const double band_hi = 2.0 * std::numbers::pi / spec.wavelength_min_m;
      for (int c = 0; c < kIrregularityChannels; ++c) {
        const WelchPsd& welch = check.channels[size_t(c)].welch;
        double lo = INFINITY, hi = 0.0;
        for (size_t k = 0; k < welch.omega_rad_per_m.size(); ++k) {
          const double w = welch.omega_rad_per_m[k], v = welch.psd_m2_per_rad_per_m[k];
          if (w < band_lo || w > band_hi || !(v > 0.0) || !std::isfinite(v)) continue;
          lo = std::min(lo, v);
          hi = std::max(hi, v);
        }
        if (hi > 0.0 && lo < hi)
          gp << "set yrange [" << lo / 10.0 << ":" << hi * 10.0 << "]\n";
        else
          gp << "set yrange [*:*]\n";
        gp << "set title " << gnuplot_text(channel_name(c)) << "\n"
           << "plot psd_csv skip 1 using 1:($" << 3 + 2 * c << ">0?$" << 3 + 2 * c
           << ":1/0) with lines lw 1 title 'Welch'";
        if (check.has_target)
          gp << ", psd_csv skip 1 using 1:($" << 4 + 2 * c << ">0?$" << 4 + 2 * c
             << ":1/0) with lines lw 2 lc 'black' dt 2 title 'target'";
        gp << "\n";
      }
      gp << "unset multiplot\n";
    });
    outputs.add(channels_png);
    outputs.add(psd_png);
    run_gnuplot(script, outputs.staging_dir(), {channels_png, psd_png},
                {{"channels_csv", std::filesystem::absolute(channels_staged).string()},
                 {"psd_csv", std::filesystem::absolute(psd_staged).string()}});
  }
  return shown.str();
}

}  // namespace railstab
