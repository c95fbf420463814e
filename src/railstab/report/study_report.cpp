#include <railstab/report/study_report.hpp>

#include <railstab/report/parameter_titles.hpp>

#include <railstab/io/csv.hpp>
#include <railstab/io/gnuplot.hpp>
#include <railstab/io/json_writer.hpp>
#include <railstab/study/study_record.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace railstab {

namespace {

std::string plot_name(const std::string& stem, std::size_t k) {
  return stem + "_study_vs_key" + std::to_string(k + 1);
}

void write_csv(std::ostream& out, const StudyDefinition& d, const std::vector<StudyPoint>& points) {
  out << "index";
  for (const VariedKey& v : d.varied) out << "," << csv_field(v.key);
  out << ",status,critical_speed_m_per_s,hunting_frequency_Hz,hunting_mode,message\n";
  for (const StudyPoint& p : points) {
    out << p.index;
    for (size_t k = 0; k < p.values.size(); ++k) out << "," << number_text_exact(p.values[k]);
    out << "," << p.status << ",";
    if (p.critical_speed_found)
      out << csv_number(p.critical_speed_m_per_s, "critical speed of combination " + std::to_string(p.index))
          << "," << csv_number(p.frequency_hz, "hunting frequency of combination " + std::to_string(p.index));
    else
      out << ",";
    out << "," << csv_field(p.mode) << "," << csv_field(p.message) << "\n";
  }
}

void write_json(std::ostream& out, const StudyDefinition& d, const StudyShard& shard,
                const std::vector<StudyPoint>& points) {
  JsonWriter j(out);
  j.begin_object();
  j.key("study").begin_object();
  j.field("scene_file", d.scene_path).field("scene", d.scene_name).field("scene_fnv1a64", d.scene_hash);
  j.key("set").begin_array();
  for (const SceneValueSetting& s : d.fixed) {
    j.begin_object().field("key", s.key);
    if (s.toml_value.empty()) j.field("value", s.value);
    else j.field("toml_value", s.toml_value);
    j.end_object();
  }
  j.end_array();
  j.key("vary").begin_array();
  for (const VariedKey& v : d.varied)
    j.begin_object()
        .field("key", v.key)
        .field("from", v.from)
        .field("to", v.to)
        .field("step", v.step)
        .field("values", int(v.values.size()))
        .end_object();
  j.end_array();
  j.key("analysis").begin_object();
  j.field("from_m_per_s", d.analysis.from_m_per_s)
      .field("to_m_per_s", d.analysis.to_m_per_s)
      .field("grid_step_m_per_s", d.analysis.grid_step_m_per_s)
      .field("eigen_solver", d.analysis.solver)
      .field("hunting_band_Hz", d.analysis.hunting_band_hz);
  j.end_object();
  j.field("combinations", int(d.combinations()));
  if (shard.sharded())
    j.key("shard").begin_object().field("index", int(shard.index)).field("count", int(shard.count)).end_object();
  j.end_object();
  j.key("points").begin_array();
  for (const StudyPoint& p : points) {
    j.begin_object().field("index", int(p.index));
    j.key("values").begin_object();
    for (size_t k = 0; k < p.values.size(); ++k) j.field(d.varied[k].key, p.values[k]);
    j.end_object();
    j.field("status", p.status);
    if (p.critical_speed_found)
      j.field("critical_speed_m_per_s", p.critical_speed_m_per_s)
          .field("hunting_frequency_Hz", p.frequency_hz)
          .field("hunting_mode", p.mode);
    else
      j.key("critical_speed_m_per_s").null();
    if (!p.message.empty()) j.field("message", p.message);
    j.end_object();
  }
  j.end_array();
  j.end_object();
}

// Blocks of the data file: for key k, one block per combination of the
// other keys (blank-line separated, gnuplot `every :::c::c`), rows
// "value_k critical_speed" (NaN where none was found: a gap).
std::size_t write_plot_data(std::ostream& out, const StudyDefinition& d,
                            const std::vector<StudyPoint>& points, std::size_t k) {
  const std::size_t n = d.combinations(), nk = d.varied[k].values.size();
  std::size_t stride = 1;
  for (size_t j = k + 1; j < d.varied.size(); ++j) stride *= d.varied[j].values.size();
  out << "# critical speed [m/s] against " << d.varied[k].key << "\n";
  std::size_t curves = 0;
  for (std::size_t base = 0; base < n; ++base) {
    if ((base / stride) % nk != 0) continue;  // each curve starts at i_k = 0
    for (std::size_t i = 0; i < nk; ++i) {
      const StudyPoint& p = points[base + i * stride];
      out << number_text_exact(p.values[k]) << " ";
      if (p.critical_speed_found) out << std::setprecision(10) << p.critical_speed_m_per_s;
      else out << "NaN";
      // Third column: the first other key's value, the curve's colour.
      out << " " << (d.varied.size() > 1 ? number_text_exact(p.values[k == 0 ? 1 : 0]) : "0") << "\n";
    }
    out << "\n";
    ++curves;
  }
  out << "\n";
  return curves;
}

// What a map cell says: the critical speed, or why there is none.
std::string map_label(const StudyDefinition& d, const StudyPoint& p) {
  std::ostringstream t;
  t << std::fixed << std::setprecision(1);
  if (p.critical_speed_found) t << p.critical_speed_m_per_s;
  else if (p.status == "unstable_at_start") t << "<" << d.analysis.from_m_per_s;
  else if (p.status == "error") t << "failed";
  else t << ">" << d.analysis.to_m_per_s;  // stable over the range searched
  return t.str();
}

std::string other_values_title(const StudyDefinition& d, const StudyPoint& first, std::size_t k) {
  std::string t;
  for (size_t j = 0; j < d.varied.size(); ++j)
    if (j != k) t += (t.empty() ? "" : ", ") + d.varied[j].key + " = " + number_text_exact(first.values[j]);
  return t;
}

std::vector<std::string> plot_study(OutputSet& outputs, const std::string& stem,
                                    const StudyDefinition& d, const std::vector<StudyPoint>& points) {
  const std::string data = stem + "_study.dat", script = stem + "_study_plots.gp";
  std::vector<std::size_t> curves(d.varied.size());
  outputs.write(data, [&](std::ostream& out) {
    for (size_t k = 0; k < d.varied.size(); ++k) curves[k] = write_plot_data(out, d, points, k);
    if (d.varied.size() == 2) {  // the map: x = key 2, y = key 1, one scan per key-1 value
      out << "# stability map: " << d.varied[1].key << " " << d.varied[0].key << " critical speed [m/s] (NaN: none) label\n";
      const std::size_t n2 = d.varied[1].values.size();
      for (std::size_t i = 0; i < points.size(); ++i) {
        const StudyPoint& p = points[i];
        out << number_text_exact(p.values[1]) << " " << number_text_exact(p.values[0]) << " ";
        if (p.critical_speed_found) out << std::setprecision(10) << p.critical_speed_m_per_s;
        else out << "NaN";
        out << " " << map_label(d, p) << "\n";
        if ((i + 1) % n2 == 0) out << "\n";
      }
    }
  });
  const std::string png = "set terminal pngcairo size 1000,650 font 'Sans,10' noenhanced\n";
  const std::string svg = "set terminal svg size 1000,650 dynamic font 'Sans,10' noenhanced\n";
  std::vector<std::string> pngs, all;
  std::ostringstream conditions;
  conditions << " (searched " << d.analysis.from_m_per_s << " - " << d.analysis.to_m_per_s
             << " m/s)";
  outputs.write(script, [&](std::ostream& gp) {
    gp << "# Run from the output folder: gnuplot " << script << "\n"
       << "set datafile separator whitespace\nset grid\n"
       << "# Gaps: no critical speed in the searched range, or the search failed (see the CSV).\n"
       << "set key below vertical Left reverse noenhanced font ',9'\n";
    auto emit = [&](const std::string& name, const std::string& plot) {
      pngs.push_back(name + ".png");
      all.push_back(name + ".png");
      all.push_back(name + ".svg");
      gp << png << "set output " << gnuplot_text(name + ".png") << "\n" << plot << "\n"
         << svg << "set output " << gnuplot_text(name + ".svg") << "\nreplot\nunset output\n";
    };
    for (size_t k = 0; k < d.varied.size(); ++k) {
      const VariedKey& v = d.varied[k];
      gp << "set title " << gnuplot_text(d.scene_name + ": critical speed" + conditions.str())
         << "\nset xlabel " << gnuplot_text(parameter_axis_title(v.key))
         << "\nset ylabel 'critical speed [m/s]'\nset xtics " << gnuplot_value_tics(v.values) << "\n"
         << "set xrange [" << std::setprecision(17) << v.from << ":"
         << (v.to > v.from ? v.to : v.from + std::max(1.0, std::abs(v.from))) << "]\nset yrange [*:*]\n";
      std::string plot = "plot ";
      gp << "unset colorbox\n";
      if (curves[k] <= 8) {
        std::size_t stride = 1;
        for (size_t j = k + 1; j < d.varied.size(); ++j) stride *= d.varied[j].values.size();
        std::size_t c = 0;
        for (std::size_t base = 0; base < points.size(); ++base) {
          if ((base / stride) % v.values.size() != 0) continue;
          const std::string title = d.varied.size() == 1 ? "critical speed" : other_values_title(d, points[base], k);
          plot += (c ? ", " : "") + gnuplot_path(data) + " index " + std::to_string(k) + " every :::" +
                  std::to_string(c) + "::" + std::to_string(c) +
                  " using 1:2 with linespoints pt 7 lw 2 title " + gnuplot_text(title);
          ++c;
        }
      } else if (d.varied.size() == 2) {  // many curves: coloured by the other key's value
        const std::string& other = d.varied[k == 0 ? 1 : 0].key;
        gp << "set colorbox\nset cblabel " << gnuplot_text(parameter_axis_title(other))
           << "\nset palette defined " << kViridisPalette << "\n";
        plot += gnuplot_path(data) + " index " + std::to_string(k) +
                " using 1:2:3 with linespoints pt 7 ps 0.6 lc palette title " +
                gnuplot_text("one curve per value of " + other);
      } else {
        plot += gnuplot_path(data) + " index " + std::to_string(k) +
                " using 1:2 with linespoints pt 7 ps 0.5 lc rgb 'steelblue' title " +
                gnuplot_text(std::to_string(curves[k]) + " curves, one per combination of the other keys");
      }
      emit(plot_name(stem, k), plot);
    }
    if (d.varied.size() == 2 && d.varied[0].values.size() > 1 && d.varied[1].values.size() > 1) {
      gp << "set colorbox\nset title " << gnuplot_text(d.scene_name + ": stability map, critical speed [m/s]" + conditions.str())
         << "\nset xlabel " << gnuplot_text(parameter_axis_title(d.varied[1].key))
         << "\nset ylabel " << gnuplot_text(parameter_axis_title(d.varied[0].key))
         << "\nset xtics " << gnuplot_value_tics(d.varied[1].values)
         << "\nset ytics " << gnuplot_value_tics(d.varied[0].values)
         << "\nset cblabel 'critical speed [m/s]'\nset palette defined " << kViridisPalette
         << "\nset xrange [*:*]\n"
         << "set yrange [*:*]\nset autoscale xfix\nset autoscale yfix\nunset key\n"
         // The cell values on a white box: readable on dark and light cells alike.
         << "set style textbox opaque fc rgb 'white' noborder margins 1,1\n";
      // The values written in the cells while they fit (up to 15 x 15).
      const bool labels = d.varied[0].values.size() <= 15 && d.varied[1].values.size() <= 15;
      emit(stem + "_study_map",
           "plot " + gnuplot_path(data) + " index 2 using 1:2:3 with image" +
               (labels ? ", " + gnuplot_path(data) +
                             " index 2 using 1:2:4 with labels boxed "
                             "font ',8' tc 'black'"
                       : std::string()));
    }
  });
  for (const std::string& f : all) outputs.add(f);
  run_gnuplot(script, outputs.staging_dir(), all);
  return pngs;
}

}  // namespace

std::vector<std::string> study_file_names(const std::string& stem, std::size_t keys) {
  std::vector<std::string> names = {stem + "_study.csv", stem + "_study.json",
                                    stem + "_study_record.toml", stem + "_study.dat",
                                    stem + "_study_plots.gp", stem + "_study_map.png",
                                    stem + "_study_map.svg"};
  for (std::size_t k = 0; k < std::max<std::size_t>(keys, 1); ++k) {
    names.push_back(plot_name(stem, k) + ".png");
    names.push_back(plot_name(stem, k) + ".svg");
  }
  return names;
}

std::vector<std::string> write_study_results(const StudyDefinition& d, const StudyShard& shard,
                                             const std::vector<StudyPoint>& points,
                                             OutputSet& outputs, const std::string& stem, bool plots) {
  for (const std::string& name : study_file_names(stem, d.varied.size())) outputs.replaces(name);
  std::vector<std::string> written = {stem + "_study.csv", stem + "_study.json", stem + "_study_record.toml"};
  outputs.write(written[0], [&](std::ostream& out) { write_csv(out, d, points); });
  outputs.write(written[1], [&](std::ostream& out) { write_json(out, d, shard, points); });
  outputs.write(written[2], [&](std::ostream& out) { write_study_record(out, d, shard, points); });
  if (plots && !shard.sharded() && points.size() == d.combinations()) {
    for (const std::string& p : plot_study(outputs, stem, d, points)) written.push_back(p);
  }
  return written;
}

void print_study_summary(std::ostream& out, const StudyDefinition& d, const std::vector<StudyPoint>& points) {
  std::size_t found = 0, failed = 0, stable = 0, unstable = 0;
  const StudyPoint *lowest = nullptr, *highest = nullptr;
  for (const StudyPoint& p : points) {
    if (p.critical_speed_found) {
      ++found;
      if (!lowest || p.critical_speed_m_per_s < lowest->critical_speed_m_per_s) lowest = &p;
      if (!highest || p.critical_speed_m_per_s > highest->critical_speed_m_per_s) highest = &p;
    } else if (p.status == "error") {
      ++failed;
    } else if (p.status == "unstable_at_start") {
      ++unstable;
    } else {
      ++stable;
    }
  }
  auto where = [&](const StudyPoint& p) {
    std::string s;
    for (size_t k = 0; k < p.values.size(); ++k)
      s += (k ? ", " : "") + d.varied[k].key + " = " + number_text_exact(p.values[k]);
    return s;
  };
  out << d.scene_name << ": " << points.size() << " combinations: " << found
      << " with a critical speed, " << stable << " stable up to " << d.analysis.to_m_per_s
      << " m/s, " << unstable << " unstable from " << d.analysis.from_m_per_s << " m/s, " << failed
      << " failed\n";
  out << std::fixed << std::setprecision(2);
  if (lowest) out << "lowest critical speed " << lowest->critical_speed_m_per_s << " m/s at " << where(*lowest) << "\n";
  if (highest) out << "highest critical speed " << highest->critical_speed_m_per_s << " m/s at " << where(*highest) << "\n";
  out << std::defaultfloat;
  for (const StudyPoint& p : points)
    if (p.status == "error") {
      out << "first failure: #" << p.index << " (" << where(p) << "): " << p.message << "\n";
      break;
    }
}

}  // namespace railstab
