#include "model_warnings.hpp"

#include <railstab/check/model_check.hpp>

#include <exception>

namespace railstab::python {

std::vector<std::string> model_warnings(const PreparedScene& s) {
  ModelCheckOptions options;
  options.natural_frequencies = false;
  std::vector<std::string> lines;
  try {
    const ModelCheckReport r = check_model(s.spec, s.model, s.speed_m_per_s, s.equilibrium, options);
    for (const ModelWarning& w : r.warnings) lines.push_back(w.message);
    for (const std::string& e : r.errors) lines.push_back("model check: " + e);
  } catch (const std::exception& e) {
    lines.push_back(std::string("model check skipped: ") + e.what());
  }
  return lines;
}

}  // namespace railstab::python
