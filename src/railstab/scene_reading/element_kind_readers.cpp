#include <railstab/scene_reading/element_kind_readers.hpp>

#include <railstab/scene/physical_ranges.hpp>
#include <railstab/scene_reading/ranged_values.hpp>

#include <string>

namespace railstab::scene_reading {

namespace {

// A force characteristic: `linear_key` (a coefficient) or `table_key`
// ([[x, F], ...] with x strictly increasing), exactly one of them.
ForceCharacteristic<double> characteristic(const TableReader& t, std::string_view linear_key,
                                           const PhysicalRange& linear_range,
                                           std::string_view table_key, const PhysicalRange& x_range,
                                           bool required = true) {
  const std::string_view linear_unit = linear_range.unit, x_unit = x_range.unit;
  const bool has_linear = t.has(linear_key), has_table = t.has(table_key);
  if (has_linear && has_table)
    t.fail(table_key, "either " + std::string(linear_key) + " or " + std::string(table_key),
           "both");
  if (has_linear) return ForceCharacteristic<double>::linear(ranged(t, linear_key, linear_range));
  if (!has_table) {
    if (required)
      t.fail_missing(linear_key, "a number" + unit_suffix(linear_unit) + " (or " +
                                     std::string(table_key) + ")");
    return ForceCharacteristic<double>::linear(0.0);
  }
  const std::string expected = "an array of at least 2 [x, F] pairs (x in " +
                               std::string(x_unit) + ", F in N) with x strictly increasing";
  const toml::array& rows = t.array(table_key, expected);
  std::vector<double> xs, fs;
  for (size_t i = 0; i < rows.size(); ++i) {
    const toml::array* row = rows.get(i)->as_array();
    const std::string row_path = indexed_path(t.path_of(table_key), i);
    if (!row || row->size() != 2)
      fail_expectation(t.source(), row_path, "a pair [x, F]", describe_found(*rows.get(i)));
    xs.push_back(number_from(*row->get(0), t.source(), indexed_path(row_path, 0), x_unit));
    fs.push_back(number_from(*row->get(1), t.source(), indexed_path(row_path, 1), "N"));
    if (!x_range.contains(xs.back()))
      fail_expectation(t.source(), indexed_path(row_path, 0), range_text(x_range),
                       format_number(xs.back()));
    if (!physical_ranges::table_force_N.contains(fs.back()))
      fail_expectation(t.source(), indexed_path(row_path, 1),
                       range_text(physical_ranges::table_force_N), format_number(fs.back()));
    if (i > 0 && !(xs[i] > xs[i - 1]))
      fail_expectation(t.source(), indexed_path(row_path, 0),
                       "x greater than the previous row's " + format_number(xs[i - 1]),
                       format_number(xs[i]));
  }
  if (xs.size() < 2) t.fail(table_key, expected, std::to_string(xs.size()) + " rows");
  return ForceCharacteristic<double>::table(xs, fs);
}

template <class Element> ElementSpec with_ends(Element e, const ElementEnds& ends) {
  e.ends = ends;
  return e;
}

}  // namespace

const std::vector<ElementKindReader>& element_kind_readers() {
  static const std::vector<ElementKindReader> readers = {
      {SpringDamper3d<double>::kType,
       {"stiffness_N_per_m", "damping_N_s_per_m", "actuator_force_N"},
       true,
       [](const TableReader& t, const ElementEnds& ends) -> ElementSpec {
         SpringDamper3d<double> e;
         e.stiffness_N_per_m = ranged_each(t, "stiffness_N_per_m", physical_ranges::stiffness_N_per_m);
         e.damping_N_s_per_m = ranged_each(t, "damping_N_s_per_m", physical_ranges::damping_N_s_per_m);
         e.actuator_force_N = ranged_each(t, "actuator_force_N", physical_ranges::actuator_force_N,
                                          Eigen::Vector3d::Zero());
         return with_ends(e, ends);
       }},
      {RotationalSpringDamper<double>::kType,
       {"stiffness_N_m_per_rad", "damping_N_m_s_per_rad", "actuator_moment_N_m"},
       false,
       [](const TableReader& t, const ElementEnds& ends) -> ElementSpec {
         RotationalSpringDamper<double> e;
         e.stiffness_N_m_per_rad =
             ranged_each(t, "stiffness_N_m_per_rad", physical_ranges::stiffness_N_m_per_rad);
         e.damping_N_m_s_per_rad =
             ranged_each(t, "damping_N_m_s_per_rad", physical_ranges::damping_N_m_s_per_rad);
         e.actuator_moment_N_m = ranged_each(t, "actuator_moment_N_m",
                                             physical_ranges::actuator_moment_N_m,
                                             Eigen::Vector3d::Zero());
         return with_ends(e, ends);
       }},
      {SeriesSpringDamper<double>::kType,
       {"series_stiffness_N_per_m", "damping_N_s_per_m", "damper_force_velocity_table"},
       true,
       [](const TableReader& t, const ElementEnds& ends) -> ElementSpec {
         SeriesSpringDamper<double> e;
         e.series_stiffness_N_per_m =
             ranged(t, "series_stiffness_N_per_m", physical_ranges::positive_stiffness_N_per_m);
         const ForceCharacteristic<double> damper =
             characteristic(t, "damping_N_s_per_m", physical_ranges::damping_N_s_per_m,
                            "damper_force_velocity_table", physical_ranges::table_velocity_m_per_s);
         if (!damper.strictly_increasing())
           t.fail(damper.is_table ? "damper_force_velocity_table" : "damping_N_s_per_m",
                  "a damper whose force strictly increases with velocity (the series element "
                  "needs its velocity as a function of force)",
                  damper.is_table ? "a table with a flat or falling step" : "zero damping");
         e.set_damper(damper);
         return with_ends(e, ends);
       }},
      {LineSpringDamper<double>::kType,
       {"stiffness_N_per_m", "spring_force_deflection_table", "damping_N_s_per_m",
        "damper_force_velocity_table"},
       true,
       [](const TableReader& t, const ElementEnds& ends) -> ElementSpec {
         LineSpringDamper<double> e;
         e.spring = characteristic(t, "stiffness_N_per_m", physical_ranges::stiffness_N_per_m,
                                   "spring_force_deflection_table",
                                   physical_ranges::table_deflection_m, false);
         e.damper = characteristic(t, "damping_N_s_per_m", physical_ranges::damping_N_s_per_m,
                                   "damper_force_velocity_table",
                                   physical_ranges::table_velocity_m_per_s, false);
         return with_ends(e, ends);
       }},
      {BumpStop<double>::kType,
       {"axis", "clearance_m", "stiffness_N_per_m", "progressive_stiffness_N_per_m3",
        "contact_smoothing_m"},
       true,
       [](const TableReader& t, const ElementEnds& ends) -> ElementSpec {
         BumpStop<double> e;
         const Eigen::Vector3d axis = t.vector3("axis", "");
         if (!(axis.norm() > 0.0) || !axis.allFinite())
           t.fail("axis", "a non-zero direction in body 1's frame", format_vector(axis));
         e.axis = axis.normalized();
         e.clearance_m = ranged(t, "clearance_m", physical_ranges::clearance_m);
         e.stiffness_N_per_m =
             ranged(t, "stiffness_N_per_m", physical_ranges::positive_stiffness_N_per_m);
         e.progressive_stiffness_N_per_m3 = ranged(
             t, "progressive_stiffness_N_per_m3", physical_ranges::progressive_stiffness_N_per_m3, 0.0);
         e.contact_smoothing_m =
             ranged(t, "contact_smoothing_m", physical_ranges::smoothing_length_m, 5e-4);
         return with_ends(e, ends);
       }},
      {TractionRod<double>::kType,
       {"stiffness_N_per_m", "damping_N_s_per_m"},
       true,
       [](const TableReader& t, const ElementEnds& ends) -> ElementSpec {
         TractionRod<double> e;
         e.stiffness_N_per_m =
             ranged(t, "stiffness_N_per_m", physical_ranges::positive_stiffness_N_per_m);
         e.damping_N_s_per_m =
             ranged(t, "damping_N_s_per_m", physical_ranges::damping_N_s_per_m, 0.0);
         return with_ends(e, ends);
       }},
      {AntiRollBar<double>::kType,
       {"roll_stiffness_N_m_per_rad", "link_half_spacing_m"},
       true,
       [](const TableReader& t, const ElementEnds& ends) -> ElementSpec {
         AntiRollBar<double> e;
         e.roll_stiffness_N_m_per_rad = ranged(t, "roll_stiffness_N_m_per_rad",
                                               physical_ranges::positive_stiffness_N_m_per_rad);
         e.link_half_spacing_m =
             ranged(t, "link_half_spacing_m", physical_ranges::link_half_spacing_m);
         return with_ends(e, ends);
       }},
  };
  return readers;
}

}  // namespace railstab::scene_reading
