#include <railstab/scene_reading/ranged_values.hpp>

namespace railstab::scene_reading {

double ranged(const TableReader& t, std::string_view key, const PhysicalRange& range,
              std::optional<double> fallback) {
  const double v = fallback && !t.has(key) ? *fallback : t.number(key, range.unit);
  if (!range.contains(v)) t.fail(key, range_text(range), format_number(v));
  return v;
}

Eigen::Vector3d ranged_each(const TableReader& t, std::string_view key, const PhysicalRange& range,
                            std::optional<Eigen::Vector3d> fallback) {
  const Eigen::Vector3d v = fallback && !t.has(key) ? *fallback : t.vector3(key, range.unit);
  for (Eigen::Index i = 0; i < 3; ++i)
    if (!range.contains(v(i)))
      fail_expectation(t.source(), indexed_path(t.path_of(key), size_t(i)), range_text(range),
                       format_number(v(i)));
  return v;
}

}  // namespace railstab::scene_reading
