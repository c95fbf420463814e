#include <railstab/scene_reading/simulation_reader.hpp>

#include <railstab/scene/integrator_kind.hpp>

#include <cmath>
#include <optional>

namespace railstab::scene_reading {

namespace {

// The integrator names of scene/integrator_kind.hpp, as choices.
const Choices<IntegratorKind>& integrator_choices() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (IntegratorKind k : all_integrator_kinds()) n.push_back(integrator_name(k));
    return n;
  }();
  static const Choices<IntegratorKind> choices = [] {
    Choices<IntegratorKind> c;
    for (size_t i = 0; i < names.size(); ++i) c.emplace_back(names[i], all_integrator_kinds()[i]);
    return c;
  }();
  return choices;
}

}  // namespace

SimulationSpec read_simulation(const TableReader& top, bool contact_table) {
  const std::optional<TableReader> simulation = top.optional_table(
      "simulation", {"t_end_s", "output_interval_s", "integrator", "integrator_order",
                     "relative_tolerance", "absolute_tolerance"});
  SimulationSpec spec = contact_table ? profile_contact_simulation_defaults() : SimulationSpec{};
  if (!simulation) return spec;
  spec.t_end_s = simulation->number_or("t_end_s", "s", spec.t_end_s);
  spec.output_interval_s = simulation->number_or("output_interval_s", "s", spec.output_interval_s);
  spec.integrator = simulation->choice_or("integrator", integrator_choices(), spec.integrator);
  const double order = simulation->number_or("integrator_order", "", spec.integrator_order);
  if (!(order == std::floor(order) && order >= 0.0 && order <= 12.0) ||
      !order_available(spec.integrator, int(order)))
    simulation->fail("integrator_order",
                     "0 (the method's default) or an order " + integrator_name(spec.integrator) +
                         " offers: " + available_orders_text(spec.integrator),
                     format_number(order));
  spec.integrator_order = int(order);
  spec.relative_tolerance =
      simulation->number_or("relative_tolerance", "", spec.relative_tolerance);
  spec.absolute_tolerance =
      simulation->number_or("absolute_tolerance", "", spec.absolute_tolerance);
  return spec;
}

AssessmentSpec read_assessment(const TableReader& top) {
  const std::optional<TableReader> assessment = top.optional_table(
      "assessment", {"prudhomme_factor", "y_over_q_limit", "stability_window_m", "stability_window_step_m",
                     "stability_band_half_width_Hz", "stability_filter_order"});
  AssessmentSpec spec;
  if (!assessment) return spec;
  const TableReader& a = *assessment;
  spec.prudhomme_factor = a.number_or("prudhomme_factor", "", spec.prudhomme_factor);
  spec.y_over_q_limit = a.number_or("y_over_q_limit", "", spec.y_over_q_limit);
  spec.stability_window_m = a.number_or("stability_window_m", "m", spec.stability_window_m);
  spec.stability_window_step_m = a.number_or("stability_window_step_m", "m", spec.stability_window_step_m);
  spec.stability_band_half_width_Hz =
      a.number_or("stability_band_half_width_Hz", "Hz", spec.stability_band_half_width_Hz);
  spec.stability_filter_order = int(a.whole_number_or("stability_filter_order", 1.0, 10.0,
                                                      spec.stability_filter_order, "a whole number in [1, 10]"));
  if (!(spec.y_over_q_limit > 0.0 && spec.y_over_q_limit <= 5.0))
    a.fail("y_over_q_limit", "(0, 5]", format_number(spec.y_over_q_limit));
  if (!(spec.stability_window_m >= 1.0 && spec.stability_window_m <= 1e4))
    a.fail("stability_window_m", "[1, 1e4] m", format_number(spec.stability_window_m));
  if (!(spec.stability_window_step_m > 0.0 && spec.stability_window_step_m <= spec.stability_window_m))
    a.fail("stability_window_step_m", "(0, stability_window_m]", format_number(spec.stability_window_step_m));
  if (!(spec.stability_band_half_width_Hz >= 0.1 && spec.stability_band_half_width_Hz <= 20.0))
    a.fail("stability_band_half_width_Hz", "[0.1, 20] Hz", format_number(spec.stability_band_half_width_Hz));
  return spec;
}

}  // namespace railstab::scene_reading
