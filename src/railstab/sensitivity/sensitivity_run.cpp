#include <railstab/sensitivity/sensitivity_run.hpp>

#include <railstab/sensitivity/parameter_derivative.hpp>

#include <algorithm>
#include <stdexcept>

namespace railstab {

SensitivityRun run_sensitivity(const PreparedScene& s, const SensitivityRunOptions& o) {
  const std::vector<std::string> known = parameter_keys(s.spec);
  for (const std::string& k : o.keys)
    if (std::find(known.begin(), known.end(), k) == known.end())
      throw std::invalid_argument(o.keys_name + " " + k + ": no such parameter of " + s.spec.name +
                                  " (`railstab sensitivity SCENE` without --key lists them all)");
  CriticalSpeedOptions opt;
  opt.from_m_per_s = o.from_m_per_s;
  opt.to_m_per_s = o.to_m_per_s;
  opt.grid_step_m_per_s = o.grid_step_m_per_s;
  opt.tolerance_m_per_s = 1e-6;
  opt.stability.max_frequency_hz = o.hunting_band_hz;
  opt.progress = o.progress;
  SensitivityRun run;
  run.search = find_critical_speed(s.model, s.equilibrium.state, s.speed_m_per_s, opt);
  const CriticalSpeedResult& r = run.search;
  if (!r.critical_speed_found || r.at_critical.least_stable < 0)
    throw std::runtime_error(s.spec.source_path + ": no critical speed between " +
                             std::to_string(o.from_m_per_s) + " and " + std::to_string(o.to_m_per_s) +
                             " m/s (" + o.range_name +
                             "): there is no stability boundary to differentiate");
  if (r.loss.kind != LossOfStabilityKind::oscillatory_crossing)
    throw std::runtime_error(
        s.spec.source_path + ": at " + std::to_string(r.critical_speed_m_per_s) +
        " m/s the stability is lost by " + describe_loss_of_stability(r.loss) +
        "; dVc/dp (implicit function theorem on Re lambda(Vc, p) = 0 for an oscillatory mode) "
        "is only defined for an oscillatory crossing");
  run.mode = r.at_critical.modes[size_t(r.at_critical.least_stable)];
  CriticalSpeedSensitivityOptions so;
  so.max_frequency_hz = o.hunting_band_hz;
  run.sensitivities =
      critical_speed_sensitivities(s.spec, r.critical_speed_m_per_s, run.mode.frequency_hz, o.keys, so);
  return run;
}

}  // namespace railstab
