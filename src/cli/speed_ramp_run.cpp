#include "cli/speed_ramp_run.hpp"

#include "cli/numeric_flags.hpp"
#include "cli/scene_command.hpp"
#include <railstab/io/file_names.hpp>
#include <railstab/io/output_set.hpp>
#include <railstab/nonlinear/speed_ramp.hpp>
#include <railstab/report/speed_ramp_report.hpp>

#include <iostream>
#include <sstream>
#include <stdexcept>

namespace railstab {

void add_ramp_flags(CLI::App* cmd, RampFlags& ramp) {
  cmd->add_option("--ramp-rate", ramp.rates_m_per_s2,
                  "decelerate from --speed at this rate (m/s^2) and report the speed where the "
                  "hunting dies away, instead of a run at one speed; repeat for a second rate "
                  "(the answer depends on the rate)")
      ->check(finite_in(flag_ranges::ramp_rate_m_per_s2));
  cmd->add_option("--ramp-to", ramp.end_speed_m_per_s,
                  "speed (m/s) where a ramp ends (default half the start speed)")
      ->check(finite_in(flag_ranges::speed_m_per_s));
  cmd->add_option("--hunting-threshold", ramp.hunting_threshold_m,
                  "peak-to-peak lateral motion (m) of the leading wheelset over one period below "
                  "which a ramp counts the hunting as gone")
      ->capture_default_str()
      ->check(finite_in(flag_ranges::hunting_threshold_m));
}

void run_speed_ramps(const PreparedScene& scene, const std::string& scene_path,
                     const Eigen::VectorXd& x0, const RunStart& start,
                     const IntegrationOptions& integration, const RampFlags& flags,
                     const std::string& out_dir) {
  const double V0 = scene.speed_m_per_s;
  const double end = flags.end_speed_m_per_s.value_or(kDefaultRampEndSpeedShare * V0);
  if (!(end < V0)) {
    std::ostringstream msg;
    msg << "--ramp-to " << end << ": expected a speed below the start speed " << V0 << " m/s";
    throw std::invalid_argument(msg.str());
  }
  std::vector<SpeedRampResult> ramps;
  for (size_t i = 0; i < flags.rates_m_per_s2.size(); ++i) {
    SpeedRampOptions o;
    o.start_speed_m_per_s = V0;
    o.ramp_rate_m_per_s2 = flags.rates_m_per_s2[i];
    o.end_speed_m_per_s = end;
    o.amplitude_threshold_m = flags.hunting_threshold_m;
    o.integration = integration;
    o.integration.t_start_s = 0.0;
    const double a = o.ramp_rate_m_per_s2;
    std::cerr << "ramp " << i + 1 << "/" << flags.rates_m_per_s2.size() << ": " << V0 << " -> "
              << end << " m/s at " << a << " m/s^2 (" << (V0 - end) / a << " s)\n";
    o.integration.progress = [V0, a](double t) {
      std::cerr << "  t = " << t << " s, V = " << V0 - a * t << " m/s\n";
    };
    ramps.push_back(run_speed_ramp(scene.model, x0, o));
  }
  const std::string stem = scene_file_stem(scene_path) + "_" + speed_file_tag(V0);
  OutputSet outputs(out_dir);
  const std::string json = speed_ramp_json(scene.model, ramps, start);
  outputs.write(stem + "_ramp.json", [&](std::ostream& out) { out << json; });
  outputs.write(stem + "_ramp_envelope.csv",
                [&](std::ostream& out) { write_speed_ramp_envelope_csv(out, ramps); });
  const std::string md = speed_ramp_markdown(scene.model, ramps, start);
  outputs.write(stem + "_ramp.md", [&](std::ostream& out) { out << md; });
  const std::vector<std::string> written = outputs.commit();
  print_speed_ramp_summary(std::cout, ramps);
  list_written(written, std::cout);
}

}  // namespace railstab
