#include <railstab/report/speed_ramp_report.hpp>

#include <railstab/integrate/work_precision.hpp>
#include <railstab/io/csv.hpp>
#include <railstab/io/json_writer.hpp>

#include <algorithm>
#include <sstream>

namespace railstab {

const char* const kRampRateDependenceNote =
    "The hunting end speed of a ramp depends on the ramp rate and on the start: the amplitude "
    "lags the branch of limit cycles it follows, and below a supercritical Hopf point it decays "
    "only at the slowly growing rate -Re(lambda), so a faster ramp loses its hunting at a lower "
    "speed. Quote it with its rate; the spread between two rates shows how far it is from the "
    "slow-ramp limit.";

std::optional<double> hunting_end_speed_spread(const std::vector<SpeedRampResult>& ramps) {
  std::vector<double> v;
  for (const SpeedRampResult& r : ramps)
    if (r.vanished) v.push_back(r.hunting_end_speed_m_per_s);
  if (v.size() < 2) return std::nullopt;
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  return *hi - *lo;
}

namespace {

std::string start_text(const RunStart& start) {
  std::ostringstream s;
  if (start.on_mode) {
    s << "mode '" << start.mode_name << "', " << start.leading_wheelset << " lateral "
      << start.amplitude_m << " m";
  } else {
    s << "the scene's initial offsets";
    for (const std::string& o : start.offset_settings) s << ", --offset " << o;
  }
  return s.str();
}

}  // namespace

std::string speed_ramp_json(const Model& model, const std::vector<SpeedRampResult>& ramps,
                            const RunStart& start) {
  std::ostringstream out;
  JsonWriter j(out);
  const SpeedRampResult& first = ramps.front();
  j.begin_object()
      .field("scene", model.name)
      .field("start_speed_m_per_s", first.options.start_speed_m_per_s)
      .field("amplitude_threshold_m", first.options.amplitude_threshold_m)
      .field("signal", first.signal)
      .field("start", start_text(start))
      .field("integrator", IntegratorVariant{first.options.integration.kind,
                                             first.options.integration.order}.label())
      .field("relative_tolerance", first.options.integration.relative_tolerance)
      .field("absolute_tolerance", first.options.integration.absolute_tolerance)
      .field("note", kRampRateDependenceNote);
  j.key("hunting_end_speed_spread_m_per_s");
  if (const std::optional<double> spread = hunting_end_speed_spread(ramps)) j.value(*spread);
  else j.null();
  j.key("ramps").begin_array();
  for (const SpeedRampResult& r : ramps) {
    j.begin_object()
        .field("ramp_rate_m_per_s2", r.options.ramp_rate_m_per_s2)
        .field("hunting_seen", r.hunting_seen)
        .field("vanished", r.vanished);
    j.key("hunting_end_speed_m_per_s");
    if (r.vanished) j.value(r.hunting_end_speed_m_per_s);
    else j.null();
    j.key("hunting_end_time_s");
    if (r.vanished) j.value(r.hunting_end_time_s);
    else j.null();
    j.field("largest_peak_to_peak_m", r.largest_peak_to_peak_m)
        .field("final_speed_m_per_s", r.final_speed_m_per_s)
        .field("ramp_end_speed_m_per_s", r.options.ramp_rate_m_per_s2 > 0.0
                                             ? r.options.end_speed_m_per_s
                                             : r.options.start_speed_m_per_s)
        .field("outcome", r.outcome)
        .field("stopped_early", r.trajectory.stopped_early)
        .field("simulated_s", r.trajectory.times_s.back())
        .field("steps", int(r.trajectory.stats.steps))
        .field("wall_s", r.trajectory.stats.wall_seconds)
        .field("cpu_s", r.trajectory.stats.cpu_seconds)
        .end_object();
  }
  j.end_array().end_object();
  return out.str();
}

void write_speed_ramp_envelope_csv(std::ostream& out, const std::vector<SpeedRampResult>& ramps) {
  out << "ramp_rate_m_per_s2,time_s,speed_m_per_s,peak_to_peak_m\n";
  for (const SpeedRampResult& r : ramps)
    for (const RampEnvelopePoint& p : r.envelope)
      out << csv_number(r.options.ramp_rate_m_per_s2, "ramp_rate_m_per_s2") << ','
          << csv_number(p.time_s, "time_s") << ',' << csv_number(p.speed_m_per_s, "speed_m_per_s")
          << ',' << csv_number(p.peak_to_peak_m, "peak_to_peak_m") << '\n';
}

std::string speed_ramp_markdown(const Model& model, const std::vector<SpeedRampResult>& ramps,
                                const RunStart& start) {
  std::ostringstream md;
  const SpeedRampResult& first = ramps.front();
  md << "# Speed ramp: " << model.name << "\n\n"
     << "From " << first.options.start_speed_m_per_s << " m/s, start: " << start_text(start)
     << "; hunting = peak-to-peak of " << first.signal << " over one period at or above "
     << first.options.amplitude_threshold_m << " m.\n\n"
     << "| ramp rate (m/s^2) | hunting end speed (m/s) | at t (s) | largest peak-to-peak (m) | "
        "simulated (s) | CPU (s) | outcome |\n|---|---|---|---|---|---|---|\n";
  for (const SpeedRampResult& r : ramps) {
    md << "| " << r.options.ramp_rate_m_per_s2 << " | ";
    if (r.vanished) md << r.hunting_end_speed_m_per_s << " | " << r.hunting_end_time_s;
    else md << "- | -";
    md << " | " << r.largest_peak_to_peak_m << " | " << r.trajectory.times_s.back() << " | "
       << r.trajectory.stats.cpu_seconds << " | " << r.outcome << " |\n";
  }
  if (const std::optional<double> spread = hunting_end_speed_spread(ramps))
    md << "\nSpread between the rates: " << *spread << " m/s.\n";
  md << "\n" << kRampRateDependenceNote << "\n";
  return md.str();
}

void print_speed_ramp_summary(std::ostream& out, const std::vector<SpeedRampResult>& ramps) {
  for (const SpeedRampResult& r : ramps)
    out << "ramp " << r.options.ramp_rate_m_per_s2 << " m/s^2 from "
        << r.options.start_speed_m_per_s << " m/s: " << r.outcome << " (" << r.trajectory.stats.steps
        << " steps, CPU " << r.trajectory.stats.cpu_seconds << " s)\n";
  if (const std::optional<double> spread = hunting_end_speed_spread(ramps))
    out << "hunting end speeds of the rates differ by " << *spread << " m/s\n";
  out << "note: " << kRampRateDependenceNote << "\n";
}

}  // namespace railstab
