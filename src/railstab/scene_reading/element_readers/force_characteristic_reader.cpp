#include <railstab/scene_reading/element_readers/element_reader.hpp>

#include <railstab/scene_reading/ranged_values.hpp>

#include <string>
#include <vector>

namespace railstab::scene_reading {

ForceCharacteristic<double> read_force_characteristic(const TableReader& t,
                                                      std::string_view linear_key,
                                                      const PhysicalRange& linear_range,
                                                      std::string_view table_key,
                                                      const PhysicalRange& x_range,
                                                      std::string_view scale_key, bool required) {
  const std::string_view linear_unit = linear_range.unit, x_unit = x_range.unit;
  const bool has_linear = t.has(linear_key), has_table = t.has(table_key);
  if (t.has(scale_key) && !has_table)
    t.fail(scale_key,
           "a scale factor beside " + std::string(table_key) + " (a linear characteristic is varied by " +
               std::string(linear_key) + " itself)",
           "no " + std::string(table_key));
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
  ForceCharacteristic<double> table = ForceCharacteristic<double>::table(xs, fs);
  table.scale = ranged(t, scale_key, physical_ranges::table_force_scale, 1.0);
  return table;
}

}  // namespace railstab::scene_reading
