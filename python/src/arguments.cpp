#include "arguments.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace railstab::python {

void check_in(const char* keyword, double v, const FlagRange& r) {
  const bool above_low = r.low_open ? v > r.low : v >= r.low;
  const bool below_high = r.high_open ? v < r.high : v <= r.high;
  if (std::isfinite(v) && above_low && below_high) return;
  std::ostringstream msg;
  msg << keyword << ": expected a finite number in " << range_text(r) << ", got " << v;
  throw std::invalid_argument(msg.str());
}

void check_in(const char* keyword, const std::optional<double>& v, const FlagRange& r) {
  if (v) check_in(keyword, *v, r);
}

void check_speed_grid(double from, double to, double step) {
  check_in("from_", from, flag_ranges::speed_m_per_s);
  check_in("to", to, flag_ranges::speed_m_per_s);
  check_in("step", step, flag_ranges::speed_step_m_per_s);
  railstab::check_speed_grid(from, to, step, {"from_", "to", "step"});
}

SceneOverrides scene_overrides(const std::vector<std::string>& settings,
                               const std::optional<double>& speed_m_per_s,
                               const std::optional<double>& arc_length_m,
                               const std::vector<std::string>& offsets) {
  check_in("speed", speed_m_per_s, flag_ranges::speed_m_per_s);
  check_in("arc_length", arc_length_m, flag_ranges::arc_length_m);
  SceneOverrides o;
  for (const std::string& text : settings) {
    try {
      o.values.push_back(parse_scene_value_setting(text));
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("set: " + std::string(e.what()));
    }
  }
  for (const std::string& text : offsets) {
    try {
      o.offsets.push_back(parse_offset_setting(text));
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("offset: " + std::string(e.what()));
    }
  }
  o.speed_m_per_s = speed_m_per_s;
  o.reference_arc_length_m = arc_length_m;
  return o;
}

EigenSolverKind solver_named(const std::string& name) {
  try {
    return eigen_solver_from_name(name);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("solver: " + std::string(e.what()));
  }
}

}  // namespace railstab::python
