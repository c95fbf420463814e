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

}  // namespace railstab
