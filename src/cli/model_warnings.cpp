#include "cli/model_warnings.hpp"

#include <railstab/check/model_check.hpp>
#include <railstab/report/model_check_report.hpp>

#include <exception>
#include <iostream>

namespace railstab {

void print_model_warnings_to_stderr(const PreparedScene& scene) {
  ModelCheckOptions options;
  options.natural_frequencies = false;
  try {
    const ModelCheckReport r =
        check_model(scene.spec, scene.model, scene.speed_m_per_s, scene.equilibrium, options);
    print_model_warnings(std::cerr, r);
  } catch (const std::exception& e) {
    std::cerr << "model check skipped: " << e.what() << "\n";
  }
}

void print_speed_range_warnings_to_stderr(const PreparedScene& scene, const CriticalSpeedResult& r,
                                          double to_m_per_s) {
  std::vector<SpeedSteadyState> speeds;
  for (const StabilityPoint& p : r.grid) speeds.push_back({p.speed_m_per_s, &p.equilibrium.state});
  if (speeds.empty() || speeds.back().speed_m_per_s < to_m_per_s)
    speeds.push_back({to_m_per_s, nullptr});  // no steady state there: the cant alone
  try {
    for (const ModelWarning& w : check_speed_range(scene.model, speeds))
      std::cerr << "warning: " << w.message << "\n";
  } catch (const std::exception& e) {
    std::cerr << "speed-range check skipped: " << e.what() << "\n";
  }
}

}  // namespace railstab
