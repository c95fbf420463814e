#include <railstab/report/stability_report.hpp>

#include <railstab/report/quasi_linear_report.hpp>

#include <railstab/report/run_conditions.hpp>

#include <railstab/io/csv.hpp>
#include <railstab/io/gnuplot.hpp>
#include <railstab/io/json_writer.hpp>
#include <railstab/report/markdown_text.hpp>
#include <railstab/report/mode_shape_report.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <map>
#include <sstream>
#include <stdexcept>

namespace railstab {

namespace {

void write_eigenvalue_csv(std::ostream& out, const CriticalSpeedResult& r,
                          const std::vector<std::vector<int>>& ids) {
  out << "speed_m_per_s,mode_track,eigenvalue_real_per_s,eigenvalue_imag_per_s,frequency_Hz,"
         "damping_ratio,neutral,residual,name\n"
      << std::setprecision(12);
  for (size_t i = 0; i < r.grid.size(); ++i)
    for (size_t j = 0; j < r.grid[i].modes.size(); ++j) {
      const ModeReport& m = r.grid[i].modes[j];
      const double speed = r.grid[i].speed_m_per_s;
      auto put = [&](double v, const char* column) {
        put_csv_number(out, v, [&] {
          std::ostringstream what;
          what << "eigenvalue CSV column " << column << " of mode " << m.name << " at " << speed
               << " m/s";
          return what.str();
        });
        out << ',';
      };
      put(speed, "speed_m_per_s");
      out << ids[i][j] << ',';
      put(m.eigenvalue.real(), "eigenvalue_real_per_s");
      put(m.eigenvalue.imag(), "eigenvalue_imag_per_s");
      put(m.frequency_hz, "frequency_Hz");
      put(m.damping_ratio, "damping_ratio");
      out << (m.neutral ? 1 : 0) << ',';
      put(m.residual, "residual");
      out << csv_field(m.name) << '\n';
    }
}

// A tracked mode on the plots: its data block, name, colour and line.
struct PlottedTrack {
  int id = -1;
  std::string name;
  double mean_frequency_hz = 0.0;
  double min_damping_ratio = 0.0;  // over the speeds of the track
  bool hunting = false;
  // The hunting track's legend tag: "[critical mode]" when it decides a
  // critical speed (or is unstable at the start), else "[least damped at
  // 150 m/s]": with no crossing no mode is critical.
  std::string tag;
  // Lateral-plane mode (mean kinetic share in lateral, roll and yaw >= 1/2):
  // these are named before vertical and longitudinal ones of lower damping.
  bool lateral = false;
  // In the legend, in colour; the others are drawn thin and grey under
  // them, counted in one legend entry.
  bool labelled = true;
  int colour = 0;  // index into kTrackColours among the labelled
  // (speed m/s, real part 1/s, frequency Hz, damping ratio), by speed.
  std::vector<std::array<double, 4>> points;
};

// The legend names the modes that matter: the critical (hunting) mode, then
// the lateral-plane modes, then the others, each group by its smallest
// damping ratio over the speed range, at most this many in all; every other
// mode is one thin grey curve, counted in one legend entry. Six distinct
// colours stay distinguishable, and a longer legend of near-identical names
// is what a client cannot read.
constexpr size_t kMaxLabelledTracks = 6;

// Okabe and Ito's colour-blind-safe qualitative palette (without its yellow,
// which is unreadable on white), one colour per named mode, in legend order.
const char* const kTrackColours[kMaxLabelledTracks] = {"#0072b2", "#d55e00", "#009e73",
                                                       "#cc79a7", "#e69f00", "#56b4e9"};

// One gnuplot data block per tracked mode (speed, real, frequency, damping),
// only for modes below the frequency cap, in ascending mean frequency (the
// legend order); returns the blocks in file order. The hunting track is the
// one holding the mode that decides the critical speed (or, without one, the
// least damped mode at the highest speed).
std::vector<PlottedTrack> write_track_blocks(std::ostream& out, const CriticalSpeedResult& r,
                                             const std::vector<std::vector<int>>& ids,
                                             double max_hz) {
  std::map<int, std::vector<std::array<double, 4>>> tracks;
  std::map<int, std::string> names;
  std::map<int, double> lateral_share;  // summed over the track's points
  for (size_t i = 0; i < r.grid.size(); ++i)
    for (size_t j = 0; j < r.grid[i].modes.size(); ++j) {
      const ModeReport& m = r.grid[i].modes[j];
      if (ids[i][j] < 0 || m.frequency_hz > max_hz) continue;
      tracks[ids[i][j]].push_back(
          {r.grid[i].speed_m_per_s, m.eigenvalue.real(), m.frequency_hz, m.damping_ratio});
      names[ids[i][j]] = m.name;
      lateral_share[ids[i][j]] += m.lateral_share;
    }
  std::string hunting_name;
  if (r.critical_speed_found || r.unstable_at_start) {
    if (r.at_critical.least_stable >= 0)
      hunting_name = r.at_critical.modes[size_t(r.at_critical.least_stable)].name;
  } else if (!r.grid.empty() && r.grid.back().least_damped >= 0) {
    hunting_name = r.grid.back().modes[size_t(r.grid.back().least_damped)].name;
  }
  std::vector<PlottedTrack> plotted;
  for (const auto& track : tracks) {
    if (track.second.size() < 2) continue;
    PlottedTrack t;
    t.id = track.first;
    t.name = names[t.id];
    t.min_damping_ratio = INFINITY;
    for (const auto& p : track.second) {
      t.mean_frequency_hz += p[2] / double(track.second.size());
      t.min_damping_ratio = std::min(t.min_damping_ratio, p[3]);
    }
    t.hunting = !hunting_name.empty() && t.name == hunting_name;
    if (t.hunting) {
      std::ostringstream tag;
      if (r.critical_speed_found || r.unstable_at_start) {
        tag << "[critical mode";
        if (r.at_critical.least_stable >= 0) {
          const std::string here =
              shape_here_if_different(r.at_critical.modes[size_t(r.at_critical.least_stable)]);
          if (!here.empty()) tag << ", " << here << " at V_c";
        }
        tag << "]";
      }
      else
        tag << "[least damped at " << r.grid.back().speed_m_per_s << " m/s]";
      t.tag = tag.str();
    }
    t.points = track.second;
    t.lateral = lateral_share[t.id] / double(track.second.size()) >= 0.5;
    plotted.push_back(t);
  }
  std::stable_sort(plotted.begin(), plotted.end(), [](const PlottedTrack& a, const PlottedTrack& b) {
    return a.mean_frequency_hz < b.mean_frequency_hz;
  });
  if (plotted.size() > kMaxLabelledTracks) {
    std::vector<size_t> rank(plotted.size());
    for (size_t k = 0; k < rank.size(); ++k) rank[k] = k;
    std::stable_sort(rank.begin(), rank.end(), [&](size_t a, size_t b) {
      if (plotted[a].hunting != plotted[b].hunting) return plotted[a].hunting;
      if (plotted[a].lateral != plotted[b].lateral) return plotted[a].lateral;
      return plotted[a].min_damping_ratio < plotted[b].min_damping_ratio;
    });
    for (size_t k = kMaxLabelledTracks; k < rank.size(); ++k) plotted[rank[k]].labelled = false;
  }
  int colour = 0;
  for (PlottedTrack& t : plotted)
    if (t.labelled) t.colour = colour++;
  out << std::setprecision(10)
      << "# speed_m_per_s eigenvalue_real_per_s frequency_Hz damping_ratio, one block per "
         "tracked mode\n";
  for (const PlottedTrack& t : plotted) {
    const int id = t.id;
    out << "# track " << id << ": " << gnuplot_text(t.name) << "\n"
        << "# plane: " << (t.lateral ? "lateral" : "vertical/longitudinal") << "\n";
    for (const auto& p : t.points) {
      for (int k = 0; k < 4; ++k) {
        if (k) out << ' ';
        put_csv_number(out, p[k], [&] {
          return "mode track " + std::to_string(id) + " at " + std::to_string(p[0]) + " m/s";
        });
      }
      out << '\n';
    }
    out << "\n\n";
  }
  return plotted;
}

// The plot clause of every track for columns `x:y` of the tracks file: one
// colour per mode (the same in every plot), the hunting mode thick and
// marked in the legend; `using_columns` may hold a gnuplot expression of $n.
std::string track_plot_clauses(const std::vector<PlottedTrack>& tracks, const std::string& file,
                               const std::string& using_columns, const std::string& style) {
  if (tracks.empty()) return "NaN notitle";
  std::ostringstream p;
  bool first = true;
  auto separate = [&] {
    if (!first) p << ", \\\n     ";
    first = false;
  };
  // The unnamed first, so the named ones are drawn over them.
  size_t unnamed = 0;
  for (size_t k = 0; k < tracks.size(); ++k) {
    if (tracks[k].labelled) continue;
    separate();
    p << gnuplot_path(file) << " index " << k << " using " << using_columns << " with " << style
      << " lc rgb '#c8c8c8' lw 1 notitle";
    ++unnamed;
  }
  if (unnamed > 0) {
    separate();
    p << "NaN with lines lc rgb '#c8c8c8' lw 1 title "
      << gnuplot_text(std::to_string(unnamed) + " better-damped modes, unnamed");
  }
  for (size_t k = 0; k < tracks.size(); ++k) {
    const PlottedTrack& t = tracks[k];
    if (!t.labelled) continue;
    separate();
    p << gnuplot_path(file) << " index " << k << " using " << using_columns << " with " << style
      << " lc rgb '" << kTrackColours[size_t(t.colour) % kMaxLabelledTracks] << "' lw "
      << (t.hunting ? 4.0 : 1.5) << " title "
      << gnuplot_text(t.hunting ? t.name + "  " + t.tag : t.name);
  }
  return p.str();
}

// The root locus's frame: every plotted point (real part >= -20 1/s, below
// the frequency cap) with a margin of 6 % of each span, the imaginary axis
// always inside; [-20, 1] x [0, max_hz] when there is none.
struct LocusFrame {
  double re_min = -20.0, re_max = 1.0, f_max = 0.0;
};

LocusFrame locus_frame(const std::vector<PlottedTrack>& tracks, double max_hz) {
  double lo = INFINITY, hi = 0.0, top = 0.0;
  for (const PlottedTrack& t : tracks)
    for (const auto& p : t.points)
      if (p[1] >= -20.0 && p[2] <= max_hz) {
        lo = std::min(lo, p[1]);
        hi = std::max(hi, p[1]);
        top = std::max(top, p[2]);
      }
  LocusFrame f;
  f.f_max = max_hz;
  if (!std::isfinite(lo)) return f;
  lo = std::min(lo, 0.0);
  const double span = std::max(hi - lo, 0.1);
  f.re_min = std::max(-20.0, lo - 0.06 * span);
  f.re_max = hi + 0.06 * span;
  f.f_max = std::min(max_hz, std::max(0.5, 1.08 * top));
  return f;
}

std::string number_text(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// A round speed step giving 4 to 8 marks over [lo, hi] (m/s).
double speed_mark_step(double lo, double hi) {
  const double span = hi - lo;
  for (double step : {0.5, 1.0, 2.0, 2.5, 5.0, 10.0, 20.0, 25.0, 50.0, 100.0, 200.0, 250.0, 500.0})
    if (span / step <= 8.0) return step;
  return span / 4.0;
}

// The eigenvalue of a track at a speed, linear between its grid speeds
// (false outside the track's speeds). Returns (real part, frequency).
bool track_at_speed(const PlottedTrack& t, double v, double& re, double& f) {
  for (size_t k = 1; k < t.points.size(); ++k) {
    const auto& a = t.points[k - 1];
    const auto& b = t.points[k];
    if (v < a[0] || v > b[0] || !(b[0] > a[0])) continue;
    const double w = (v - a[0]) / (b[0] - a[0]);
    re = a[1] + w * (b[1] - a[1]);
    f = a[2] + w * (b[2] - a[2]);
    return true;
  }
  return false;
}

// Speed marks along the named branches of the root locus: a gnuplot data
// block of (real part, frequency) at the round speeds of `step`, and labels
// with the speed on the branch that decides the verdict (the critical mode,
// else the first named, least damped one), placed right of the mark.
void write_speed_marks(std::ostream& gp, const std::vector<PlottedTrack>& tracks, double step,
                       const LocusFrame& frame) {
  const PlottedTrack* numbered = nullptr;
  for (const PlottedTrack& t : tracks)
    if (t.labelled && t.hunting) numbered = &t;
  if (!numbered)
    for (const PlottedTrack& t : tracks)
      if (t.labelled && (!numbered || t.min_damping_ratio < numbered->min_damping_ratio)) numbered = &t;
  gp << "$speed_marks << EOD\n" << std::setprecision(8);
  int label = 10;
  std::ostringstream labels;
  labels.precision(8);
  for (const PlottedTrack& t : tracks) {
    if (!t.labelled || t.points.empty()) continue;
    for (double v = std::ceil(t.points.front()[0] / step - 1e-9) * step;
         v <= t.points.back()[0] + 1e-9; v += step) {
      double re = 0.0, f = 0.0;
      if (!track_at_speed(t, v, re, f) || re < frame.re_min || re > frame.re_max || f > frame.f_max)
        continue;
      gp << re << ' ' << f << '\n';
      if (&t == numbered)
        labels << "set label " << label++ << " '" << v << "' at " << re << ", " << f
               << " left offset 0.7,0 font ',8' tc rgb '#303030' front\n";
    }
  }
  gp << "EOD\n" << labels.str();
}

// Ranges on both axes are explicit: with no plottable point (a one-speed
// grid, every mode above the band) gnuplot's autoscale fails ("x range is
// invalid"); with them the plot is made, empty. Each plot is written as PNG
// and, by `replot` on the svg terminal, as SVG.
std::vector<std::string> plot_stability(OutputSet& outputs, const std::string& stem,
                                        const std::string& tracks_file,
                                        const std::vector<PlottedTrack>& tracks,
                                        const CriticalSpeedResult& r, const std::string& title,
                                        double max_hz) {
  const std::string script = stem + "_stability_plots.gp";
  const std::vector<std::string> kinds = {"_root_locus", "_damping_vs_speed", "_frequency_vs_speed"};
  std::vector<std::string> pngs, all;
  for (const std::string& k : kinds) {
    pngs.push_back(stem + k + ".png");
    all.push_back(stem + k + ".png");
    all.push_back(stem + k + ".svg");
  }
  const double v_lo = r.from_m_per_s, v_hi = r.to_m_per_s > r.from_m_per_s ? r.to_m_per_s
                                                                          : r.from_m_per_s + 1.0;
  std::ostringstream range;
  range << v_lo << " - " << v_hi << " m/s";
  // A label at speed v on a speed axis: on the side of v with more room, so
  // it stays inside the frame.
  const auto inside_frame = [&](double v) {
    return std::string(v > 0.5 * (v_lo + v_hi) ? "right offset -1,0" : "left offset 1,0");
  };
  auto titled = [&](const std::string& what) {
    return gnuplot_text(title + ": " + what + " (" + range.str() + ")");
  };
  std::ostringstream band;
  band << max_hz;
  const bool critical = r.critical_speed_found;
  const double vc = critical ? r.critical_speed_m_per_s : NAN;
  double fc = NAN;
  if (critical && r.at_critical.least_stable >= 0)
    fc = r.at_critical.modes[size_t(r.at_critical.least_stable)].frequency_hz;
  const std::string png_terminal =
      "set terminal pngcairo size 1200,620 font 'Sans,10' noenhanced\n";
  const std::string svg_terminal = "set terminal svg size 1200,620 dynamic font 'Sans,10' noenhanced\n";
  outputs.write(script, [&](std::ostream& gp) {
    gp << "# Run from the output folder: gnuplot " << script << "\n"
       << "# Each curve is one mode, tracked over speed by eigenvector continuity, named from\n"
       << "# its shape; the same mode has the same colour in every plot.\n"
       << "set datafile separator whitespace\n" << png_terminal << "set grid\n"
       // The legend below the frame in columns of four: beside it, the
       // names' length squeezed the frame to less than half the width.
       << "set key outside below left vertical maxrows 4 Left reverse noenhanced font ',9' "
          "spacing 1.1 width 2\n";
    auto emit = [&](size_t k, const std::string& plot) {
      gp << "set output " << gnuplot_text(pngs[k]) << "\n" << plot << "\n"
         << svg_terminal << "set output " << gnuplot_text(stem + kinds[k] + ".svg") << "\nreplot\n"
         << "unset output\n" << png_terminal;
    };
    // The sparse solver computes only the hunting band's box (Re near 0,
    // eigen/band_eigen.hpp): the plot says so rather than look complete.
    const bool sparse = std::any_of(r.grid.begin(), r.grid.end(), [](const StabilityPoint& p) {
      return p.solver_used == EigenSolverKind::sparse;
    });
    gp << "set title "
       << titled(sparse ? "root locus below " + band.str() + " Hz, sparse solver: Re near 0 only"
                        : "root locus of the modes below " + band.str() + " Hz, real part >= -20 1/s")
       << "\nset xlabel 'real part of the eigenvalue [1/s]'\nset ylabel 'frequency [Hz]'\n"
       << "set arrow 2 from 0, graph 0 to 0, graph 1 nohead lc 'black'\n";
    const LocusFrame frame = locus_frame(tracks, max_hz);
    gp << std::setprecision(6) << "set yrange [0:" << frame.f_max << "]\nset xrange ["
       << frame.re_min << ":" << frame.re_max << "]\n";
    // The critical point's label left of the imaginary axis, which is always
    // inside the frame with room on its left (re_min <= -6 % of the span).
    if (std::isfinite(vc) && std::isfinite(fc))
      gp << "set label 3 'V_crit = " << std::fixed << std::setprecision(2) << vc
         << " m/s' at 0, " << std::defaultfloat << std::setprecision(8) << fc
         << " point pt 3 ps 2 lc 'red' right offset -1,1 front\n";
    const double mark_step = speed_mark_step(v_lo, v_hi);
    write_speed_marks(gp, tracks, mark_step, frame);
    std::ostringstream marks;
    marks << "$speed_marks using 1:2 with points pt 6 ps 1.1 lc rgb '#303030' title "
          << gnuplot_text("speed marks every " + number_text(mark_step) + " m/s");
    emit(0, "plot " + track_plot_clauses(tracks, tracks_file, "($2>=-20 ? $2 : 1/0):3",
                                         "linespoints pt 7 ps 0.4") +
                (tracks.empty() ? std::string() : ", \\\n     " + marks.str()));
    gp << "unset label\nunset arrow 2\nunset yrange\nunset xrange\nset autoscale\n"
       << std::defaultfloat << std::setprecision(8) << "set xrange [" << v_lo << ":" << v_hi
       << "]\n";
    if (std::isfinite(vc))
      gp << "set arrow 1 from " << vc << ", graph 0 to " << vc
         << ", graph 1 nohead dt 2 lw 2 lc 'red'\nset label 1 'V_crit = " << std::fixed
         << std::setprecision(2) << vc << " m/s' at " << vc << ", graph 0.95 "
         << inside_frame(vc) << " tc 'red'\n"
         << std::defaultfloat << std::setprecision(8);
    if (r.damping_limit_found)
      gp << "set arrow 4 from " << r.damping_limit_speed_m_per_s << ", graph 0 to "
         << r.damping_limit_speed_m_per_s << ", graph 1 nohead dt 3 lw 2 lc 'dark-orange'\n"
         << "set label 4 'damping ratio < " << r.min_damping_ratio << " at " << std::fixed
         << std::setprecision(2) << r.damping_limit_speed_m_per_s << " m/s' at "
         << r.damping_limit_speed_m_per_s << ", graph 0.88 " << inside_frame(r.damping_limit_speed_m_per_s)
         << " tc 'dark-orange'\n"
         << std::defaultfloat << std::setprecision(8);
    gp << "set title " << titled("damping ratio of the modes below " + band.str() + " Hz")
       << "\nset xlabel 'speed [m/s]'\nset ylabel 'damping ratio [-]'\n"
       << "set xzeroaxis lt -1\nset yrange [-0.2:1]\n";
    emit(1, "plot " + track_plot_clauses(tracks, tracks_file, "1:4", "lines"));
    gp << "set title " << titled("frequency of the modes below " + band.str() + " Hz")
       << "\nset ylabel 'frequency [Hz]'\nset yrange [0:" << max_hz << "]\n";
    emit(2, "plot " + track_plot_clauses(tracks, tracks_file, "1:3", "lines"));
  });
  for (const std::string& f : all) outputs.add(f);
  run_gnuplot(script, outputs.staging_dir(), all);
  return pngs;
}

void write_mode_json(JsonWriter& j, const ModeReport& m) {
  j.field("eigenvalue_real_per_s", m.eigenvalue.real())
      .field("eigenvalue_imag_per_s", m.eigenvalue.imag())
      .field("frequency_Hz", m.frequency_hz)
      .field("damping_ratio", m.damping_ratio)
      .field("residual", m.residual)
      .field("name", m.name);
  j.key("participation").begin_array();
  for (const Participation& p : m.participation)
    j.begin_object()
        .field("body", p.body)
        .field("coordinate", coordinate_word(p.coordinate))
        .field("kinetic_energy_share", p.share)
        .end_object();
  j.end_array();
}

// The Hopf point's criticality (docs/outputs.md): the two headline keys,
// null when not computed, and an object with the reason or the details.
void write_hopf_json(JsonWriter& j, const HopfAssessment* h) {
  if (h && h->computed) {
    j.field("first_lyapunov_coefficient", h->result.first_lyapunov_coefficient)
        .field("hopf_kind", hopf_kind_name(h->result.kind));
  } else {
    j.key("first_lyapunov_coefficient").null().key("hopf_kind").null();
  }
  j.key("hopf").begin_object();
  j.field("computed", h && h->computed);
  if (!h) {
    j.field("not_computed_reason", std::string("not requested"));
  } else if (!h->computed) {
    j.field("not_computed_reason", h->not_computed_reason);
  } else {
    const HopfCriticality& c = h->result;
    j.key("not_computed_reason").null();
    j.field("evaluated_at_m_per_s", c.speed_m_per_s)
        .field("hopf_speed_m_per_s", c.critical_speed_m_per_s)
        .field("eigenvalue_real_speed_derivative_per_m", c.real_part_speed_derivative)
        .field("cycle_side", std::string(c.cycle_side > 0 ? "above" : c.cycle_side < 0 ? "below" : "none"))
        .field("description", describe_hopf(*h));
    if (h->amplitude_state.empty())
      j.key("amplitude_state").null().key("cycle_amplitude_coefficient_m_per_sqrt_m_per_s").null();
    else
      j.field("amplitude_state", h->amplitude_state)
          .field("cycle_amplitude_coefficient_m_per_sqrt_m_per_s",
                 h->amplitude_coefficient_m_per_sqrt_m_per_s);
  }
  j.end_object();
}

void write_json(std::ostream& out, const Model& model, const CriticalSpeedResult& r,
                const RunConditions& conditions, const std::string& solver, double max_hz,
                const HopfAssessment* hopf, const QuasiLinearCriticalSpeed* quasi_linear) {
  {
    JsonWriter j(out);
    j.begin_object().field("scene", model.name).field("scene_file", model.source_path);
    // Where and how (report/run_conditions.hpp): track, cant deficiency at
    // every speed of the grid, contacts, scene hash, version; the solver and
    // the tolerances of the search.
    std::vector<double> speeds;
    for (const StabilityPoint& p : r.grid) speeds.push_back(p.speed_m_per_s);
    write_conditions_json(j, conditions, speeds);
    j.field("eigen_solver", solver)
        .field("hunting_band_Hz", max_hz)
        .field("speed_tolerance_requested_m_per_s", r.requested_tolerance_m_per_s)
        .field("equilibrium_acceleration_tolerance_m_per_s2", EquilibriumOptions{}.acceleration_tolerance);
    j.field("from_m_per_s", r.from_m_per_s).field("to_m_per_s", r.to_m_per_s);
    if (quasi_linear) write_quasi_linear_json(j, *quasi_linear);
    j.field("partial", r.partial);
    if (r.partial)
      j.field("partial_reason", r.partial_reason);
    else
      j.key("partial_reason").null();
    j.field("stable_in_range", r.stable_in_range).field("unstable_at_start", r.unstable_at_start);
    j.field("verdict", verdict_key(stability_verdict(r))).field("verdict_text", verdict_sentence(r));
    if (r.equilibrium_lost_at_m_per_s > 0.0)
      j.field("equilibrium_lost_at_m_per_s", r.equilibrium_lost_at_m_per_s)
          .field("equilibrium_error", r.equilibrium_error);
    if (r.steady_state_fold_m_per_s > 0.0)
      j.field("steady_state_fold_m_per_s", r.steady_state_fold_m_per_s);
    if (r.critical_speed_found) {
      const ModeReport& m = r.at_critical.modes[r.at_critical.least_stable];
      j.field("critical_speed_m_per_s", r.critical_speed_m_per_s)
          .field("critical_speed_tolerance_m_per_s", r.speed_tolerance_m_per_s)
          .field("hunting_frequency_Hz", m.frequency_hz)
          .field("hunting_damping_ratio", m.damping_ratio)
          .field("hunting_mode", m.name)
          .field("hunting_mode_shape_here", m.shape_name);
      j.key("loss_of_stability").begin_object();
      j.field("kind", loss_of_stability_key(r.loss.kind))
          .field("description", describe_loss_of_stability(r.loss))
          .field("stable_side_m_per_s", r.loss.stable_speed_m_per_s)
          .field("unstable_side_m_per_s", r.loss.unstable_speed_m_per_s)
          .field("max_real_part_stable_side_per_s", r.loss.stable_max_real_part_per_s)
          .field("max_real_part_unstable_side_per_s", r.loss.unstable_max_real_part_per_s)
          .field("steady_state_largest_translation_change_m", r.loss.largest_translation_change_m)
          .field("steady_state_grid_translation_change_m", r.loss.grid_translation_change_m)
          .field("steady_state_continuous", r.loss.steady_state_continuous);
      if (r.loss.kind == LossOfStabilityKind::fold)
        j.field("fold_speed_m_per_s", r.loss.fold_speed_m_per_s)
            .field("fold_speed_coarse_m_per_s", r.loss.fold_coarse_speed_m_per_s)
            .field("fold_smooth", r.loss.fold_smooth);
      j.end_object();
      write_hopf_json(j, hopf);
      const std::vector<ModeShape>& shapes = r.shapes_at_critical;
      if (shapes.size() != r.at_critical.modes.size())
        throw std::invalid_argument(
            "critical-speed JSON: the result holds no mode shapes at the critical speed "
            "(CriticalSpeedOptions::mode_shapes_at_critical was off)");
      j.key("mode_shape").begin_object();
      write_mode_json(j, m);
      j.key("shape");
      write_mode_shape_json(j, model, shapes[size_t(r.at_critical.least_stable)]);
      j.end_object();
      // Every oscillatory mode up to the plotted band at the critical speed
      // (r.at_critical), with its shape: what a client compares the hunting
      // mode with.
      j.field("modes_at_critical_speed_m_per_s", r.at_critical.speed_m_per_s);
      j.key("modes_at_critical_speed").begin_array();
      for (size_t i = 0; i < r.at_critical.modes.size(); ++i) {
        const ModeReport& mi = r.at_critical.modes[i];
        if (mi.neutral || mi.eigenvalue.imag() <= 0.0 || mi.frequency_hz > max_hz) continue;
        j.begin_object();
        write_mode_json(j, mi);
        j.key("shape");
        write_mode_shape_json(j, model, shapes[i]);
        j.end_object();
      }
      j.end_array();
    } else {
      j.key("critical_speed_m_per_s").null().key("hunting_frequency_Hz").null().key("hunting_mode").null().key("hunting_mode_shape_here").null();
      write_hopf_json(j, hopf);
    }
    j.field("states", int(r.grid.empty() ? 0 : r.grid.front().linear.states()))
        .field("evaluations", r.evaluations)
        .field("wall_s", r.seconds);
    j.key("removed_cyclic_states").begin_array();
    if (!r.grid.empty())
      for (const std::string& s : r.grid.front().linear.removed_states) j.value(s);
    j.end_array();
    double worst_residual = 0.0;
    for (const StabilityPoint& p : r.grid)
      for (const ModeReport& m : p.modes) worst_residual = std::max(worst_residual, m.residual);
    j.field("max_eigenpair_residual", worst_residual);
    j.key("unstable_modes_above_hunting_band").begin_array();
    for (const StabilityPoint& p : r.grid)
      for (int i : p.unstable_above_band) {
        j.begin_object().field("speed_m_per_s", p.speed_m_per_s);
        write_mode_json(j, p.modes[i]);
        j.end_object();
      }
    j.end_array();
    j.key("damping_ratio_criterion");
    if (r.min_damping_ratio > 0.0) {
      j.begin_object()
          .field("min_damping_ratio", r.min_damping_ratio)
          .field("below_at_start", r.damping_below_at_start)
          .field("found", r.damping_limit_found);
      const StabilityPoint& p = r.at_damping_limit;
      if (r.damping_limit_found)
        j.field("speed_m_per_s", r.damping_limit_speed_m_per_s)
            .field("speed_tolerance_m_per_s", r.speed_tolerance_m_per_s);
      else
        j.key("speed_m_per_s").null();
      if ((r.damping_limit_found || r.damping_below_at_start) && p.least_damped >= 0) {
        j.key("mode").begin_object();
        write_mode_json(j, p.modes[size_t(p.least_damped)]);
        j.end_object();
      }
      j.end_object();
    } else {
      j.null();
    }
    // Ranked by damping ratio (modes/least_damped_mode): a decaying real
    // root (ratio 1) never fills the table; the stability decision itself
    // is the real part (least_stable).
    j.key("least_damped_by_speed").begin_array();
    for (const StabilityPoint& p : r.grid) {
      j.begin_object().field("speed_m_per_s", p.speed_m_per_s);
      if (p.least_damped >= 0) write_mode_json(j, p.modes[size_t(p.least_damped)]);
      j.end_object();
    }
    j.end_array().end_object();
  }
}

void write_markdown(std::ostream& md_out, const Model& model, const CriticalSpeedResult& r,
                    const RunConditions& conditions, const std::string& solver,
                    const StabilityFiles& files, const HopfAssessment* hopf,
                    const QuasiLinearCriticalSpeed* quasi_linear) {
  auto rel = [&](const std::string& f) { return f; };  // names in the same folder
  {
    std::ostream& md = md_out;
    md << std::setprecision(4);
    md << "# Critical speed: " << md_text(model.name) << "\n\n"
       << "Scene `" << md_text(model.source_path) << "`, speeds " << r.from_m_per_s << " to "
       << r.to_m_per_s << " m/s, " << (r.grid.empty() ? 0 : r.grid.front().linear.states())
       << " states after removing " << (r.grid.empty() ? 0 : r.grid.front().linear.removed_states.size())
       << " cyclic coordinates, eigen-solver " << solver << ", speeds bracketed to "
       << r.requested_tolerance_m_per_s << " m/s, steady states to "
       << EquilibriumOptions{}.acceleration_tolerance << " m/s^2.\n\n"
       << conditions_markdown(conditions) << "\n";
    if (quasi_linear) md << quasi_linear_markdown(*quasi_linear) << "\n";
    if (r.partial)
      md << "**Partial result**: the run could not finish what was asked; what it found is "
            "below. Reason: "
         << md_text(r.partial_reason) << "\n\n";
    if (r.equilibrium_lost_at_m_per_s > 0.0)
      md << "No steady state at " << r.equilibrium_lost_at_m_per_s
         << " m/s and above (" << md_text(r.equilibrium_error) << "); the analysis covers the speeds "
         << "below.\n\n";
    md << "Verdict: **" << verdict_sentence(r) << "**";
    if (stability_verdict(r) == StabilityVerdict::unstable_at_start)
      md << ": lower the start speed";
    else if (stability_verdict(r) != StabilityVerdict::critical_speed_found)
      md << " (no non-neutral mode crosses into the right half-plane)";
    md << ".\n\n";
    if (r.min_damping_ratio > 0.0) {
      md << "Damping-ratio criterion " << r.min_damping_ratio << ": ";
      const StabilityPoint& p = r.at_damping_limit;
      if (r.damping_below_at_start)
        md << "already below it at " << r.from_m_per_s << " m/s";
      else if (r.damping_limit_found)
        md << "a mode's damping ratio falls below it at **" << std::fixed << std::setprecision(2)
           << r.damping_limit_speed_m_per_s << " m/s**" << std::defaultfloat << std::setprecision(4);
      else
        md << "met over the whole grid";
      if ((r.damping_below_at_start || r.damping_limit_found) && p.least_damped >= 0)
        md << " (" << md_text(p.modes[size_t(p.least_damped)].name) << ")";
      md << ".\n\n";
    }
    if (r.critical_speed_found) {
      const ModeReport& m = r.at_critical.modes[r.at_critical.least_stable];
      md << "| result | value |\n|---|---|\n"
         << "| critical speed | **" << std::fixed << std::setprecision(2)
         << r.critical_speed_m_per_s << " m/s** (" << r.critical_speed_m_per_s * 3.6
         << " km/h), bracketed to " << r.speed_tolerance_m_per_s << " m/s |\n"
         << std::defaultfloat << std::setprecision(4) << "| hunting frequency | " << m.frequency_hz
         << " Hz |\n| wavelength | "
         << (m.frequency_hz > 0.0 ? r.critical_speed_m_per_s / m.frequency_hz : 0.0)
         << " m |\n"
         << "| damping ratio at " << r.at_critical.speed_m_per_s << " m/s | " << m.damping_ratio
         << " |\n"
         << "| mode | " << md_text(mode_label_here(m)) << " |\n"
         << "| loss of stability | " << md_text(describe_loss_of_stability(r.loss)) << " |\n";
      if (hopf) md << "| Hopf bifurcation | " << md_text(describe_hopf(*hopf)) << " |\n";
      md << "\n";
      if (r.shapes_at_critical.size() == r.at_critical.modes.size())
        write_mode_shape_markdown(md, model,
                                  r.shapes_at_critical[size_t(r.at_critical.least_stable)]);
      md << std::setprecision(4);
    }
    for (const StabilityPoint& p : r.grid)
      if (!p.validity_warning.empty()) {
        md << "- from " << p.speed_m_per_s << " m/s: " << md_text(p.validity_warning) << "\n";
        break;
      }
    for (const StabilityPoint& p : r.grid)
      if (!p.eigen_warning.empty()) {
        md << "- at " << p.speed_m_per_s << " m/s: " << md_text(p.eigen_warning) << "\n";
        break;
      }
    for (const StabilityPoint& p : r.grid)
      if (!p.unstable_above_band.empty()) {
        const ModeReport& m = p.modes[p.unstable_above_band.front()];
        md << "- from " << p.speed_m_per_s << " m/s a mode above the hunting band is unstable: "
           << md_text(m.name) << " at " << m.frequency_hz << " Hz, real part " << m.eigenvalue.real()
           << " 1/s (wheel-rail contact mode; the Hertz contact has no damping)\n";
        break;
      }
    // In a curve, the cant deficiency at each speed (report/run_conditions.hpp).
    const bool curve = !conditions.tangent;
    md << "\nLeast damped mode by speed (smallest damping ratio in the hunting band):\n\n"
          "| speed [m/s] | "
       << (curve ? "cant deficiency [mm] | " : "")
       << "real part [1/s] | frequency [Hz] | damping ratio | mode |\n"
       << (curve ? "|---|---|---|---|---|---|\n" : "|---|---|---|---|---|\n");
    for (const StabilityPoint& p : r.grid) {
      if (p.least_damped < 0) continue;
      const ModeReport& m = p.modes[size_t(p.least_damped)];
      md << "| " << p.speed_m_per_s << " | ";
      if (curve) md << conditions.cant_deficiency_m(p.speed_m_per_s) * 1e3 << " | ";
      md << m.eigenvalue.real() << " | " << m.frequency_hz << " | " << m.damping_ratio << " | "
         << md_text(m.name) << " |\n";
    }
    md << "\n";
    for (const std::string& png : files.plots) md << "![](" << rel(png) << ")\n\n";
    md << "Data: `" << rel(files.csv) << "` (every eigenvalue at every speed, modes tracked "
       << "by eigenvector continuity), `" << rel(files.json) << "`. Wall time " << r.seconds
       << " s for " << r.evaluations << " speed evaluations.\n";
  }
}

}  // namespace

std::vector<std::string> stability_file_names(const std::string& stem) {
  return {stem + "_eigenvalues.csv",       stem + "_tracks.dat",
          stem + "_stability_plots.gp",    stem + "_root_locus.png",
          stem + "_damping_vs_speed.png",  stem + "_frequency_vs_speed.png",
          stem + "_root_locus.svg",        stem + "_damping_vs_speed.svg",
          stem + "_frequency_vs_speed.svg", stem + "_critical_speed.json",
          stem + "_critical_speed.md"};
}

StabilityFiles write_stability_results(const Model& model, const CriticalSpeedResult& result,
                                       OutputSet& outputs, const std::string& stem,
                                       const std::string& eigen_solver_name, bool plots,
                                       double max_plot_frequency_hz, const HopfAssessment* hopf,
                                       const QuasiLinearCriticalSpeed* quasi_linear) {
  for (const std::string& name : stability_file_names(stem)) outputs.replaces(name);
  StabilityFiles files;
  const std::vector<std::vector<int>>& ids = result.mode_tracks;
  if (ids.size() != result.grid.size())
    throw std::invalid_argument("write_stability_results: the result's mode tracks (" +
                                std::to_string(ids.size()) + ") do not cover its grid (" +
                                std::to_string(result.grid.size()) + " speeds)");
  // Where and how, stated alike in the JSON and the Markdown.
  const RunConditions conditions = run_conditions(model);
  files.csv = stem + "_eigenvalues.csv";
  outputs.write(files.csv, [&](std::ostream& out) { write_eigenvalue_csv(out, result, ids); });
  files.json = stem + "_critical_speed.json";
  outputs.write(files.json,
                [&](std::ostream& out) {
                  write_json(out, model, result, conditions, eigen_solver_name,
                             max_plot_frequency_hz, hopf, quasi_linear);
                });
  if (plots)
    files.plots = {stem + "_root_locus.png", stem + "_damping_vs_speed.png",
                   stem + "_frequency_vs_speed.png"};
  files.markdown = stem + "_critical_speed.md";
  outputs.write(files.markdown, [&](std::ostream& out) {
    write_markdown(out, model, result, conditions, eigen_solver_name, files, hopf, quasi_linear);
  });
  if (plots) {
    const std::string tracks = stem + "_tracks.dat";
    std::vector<PlottedTrack> plotted;
    outputs.write(tracks, [&](std::ostream& out) {
      plotted = write_track_blocks(out, result, ids, max_plot_frequency_hz);
    });
    files.plots = plot_stability(outputs, stem, tracks, plotted, result, model.name,
                                 max_plot_frequency_hz);
  }
  return files;
}

void print_critical_speed_summary(std::ostream& out, const Model& model,
                                  const CriticalSpeedResult& r, double hunting_band_hz,
                                  const HopfAssessment* hopf) {
  out << std::setprecision(6);
  if (!r.critical_speed_found) {
    out << model.name << ": " << verdict_sentence(r) << "\n";
  } else {
    const ModeReport& m = r.at_critical.modes[r.at_critical.least_stable];
    out << model.name << ": critical speed " << std::fixed << std::setprecision(2)
        << r.critical_speed_m_per_s << " m/s (" << r.critical_speed_m_per_s * 3.6 << " km/h)"
        << std::defaultfloat << std::setprecision(5) << ", frequency " << m.frequency_hz
        << " Hz, mode " << mode_label_here(m) << "\n";
    if (r.loss.kind != LossOfStabilityKind::oscillatory_crossing)
      out << "loss of stability: " << describe_loss_of_stability(r.loss) << "\n";
    if (hopf) out << "Hopf bifurcation: " << describe_hopf(*hopf) << "\n";
  }
  if (r.damping_limit_found) {
    out << "damping ratio below " << r.min_damping_ratio << " from " << std::fixed
        << std::setprecision(2) << r.damping_limit_speed_m_per_s << " m/s" << std::defaultfloat
        << std::setprecision(6);
    const StabilityPoint& p = r.at_damping_limit;
    if (p.least_damped >= 0) out << " (" << p.modes[size_t(p.least_damped)].name << ")";
    out << "\n";
  }
  else if (r.damping_below_at_start)
    out << "damping ratio already below " << r.min_damping_ratio << " at " << r.from_m_per_s
        << " m/s\n";
  else if (r.min_damping_ratio > 0.0)
    out << "damping ratio at least " << r.min_damping_ratio << " over the whole grid\n";
  if (r.partial)
    out << "partial result: " << r.partial_reason << "\n";
  else if (r.equilibrium_lost_at_m_per_s > 0.0)
    out << "no steady state from " << r.equilibrium_lost_at_m_per_s
        << " m/s: " << r.equilibrium_error << "\n";
  for (const StabilityPoint& p : r.grid)
    if (!p.validity_warning.empty()) {
      out << "warning from " << p.speed_m_per_s << " m/s: " << p.validity_warning << "\n";
      break;
    }
  for (const StabilityPoint& p : r.grid)
    if (!p.eigen_warning.empty()) {
      out << "warning at " << p.speed_m_per_s << " m/s: " << p.eigen_warning << "\n";
      break;
    }
  for (const StabilityPoint& p : r.grid)
    if (!p.unstable_above_band.empty()) {
      const ModeReport& m = p.modes[p.unstable_above_band.front()];
      out << "warning from " << p.speed_m_per_s << " m/s: mode above the hunting band ("
          << hunting_band_hz << " Hz) unstable: " << m.name << " at " << m.frequency_hz
          << " Hz, real part " << m.eigenvalue.real() << " 1/s\n";
      break;
    }
  out << r.evaluations << " speed evaluations in " << r.seconds << " s\n";
}

}  // namespace railstab
