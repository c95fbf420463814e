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

SimulationSpec read_simulation(const TableReader& top) {
  const std::optional<TableReader> simulation = top.optional_table(
      "simulation", {"t_end_s", "output_interval_s", "integrator", "integrator_order",
                     "relative_tolerance", "absolute_tolerance"});
  SimulationSpec spec;
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
  const std::optional<TableReader> assessment = top.optional_table("assessment", {"prudhomme_factor"});
  AssessmentSpec spec;
  if (!assessment) return spec;
  spec.prudhomme_factor = assessment->number_or("prudhomme_factor", "", spec.prudhomme_factor);
  return spec;
}

}  // namespace railstab::scene_reading
