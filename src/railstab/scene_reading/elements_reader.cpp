#include <railstab/scene_reading/elements_reader.hpp>

#include <railstab/scene/physical_ranges.hpp>
#include <railstab/scene_reading/element_kind_readers.hpp>
#include <railstab/scene_reading/ranged_values.hpp>

#include <algorithm>
#include <array>
#include <optional>

namespace railstab::scene_reading {

namespace {

// Keys every element takes; each type adds its own (ElementKindReader::keys).
const std::vector<std::string_view> kCommonElementKeys = {"name",     "type",     "body1",
                                                          "body2",    "point1_m", "point2_m",
                                                          "mirror_lateral"};

// mirror_lateral = true: "<name>_left" as given, "<name>_right" with the y of
// both points negated (and what the kind's reader mirrors, e.g. a bump
// stop's axis).
std::array<ElementSpec, 2> mirrored_pair(const ElementSpec& element,
                                         const ElementKindReader& reader) {
  ElementSpec left = element;
  ElementSpec right = element;
  ends_of(left).name += "_left";
  ElementEnds& r = ends_of(right);
  r.name += "_right";
  r.point1_m.y() = -r.point1_m.y();
  r.point2_m.y() = -r.point2_m.y();
  if (reader.mirror_lateral) reader.mirror_lateral(right);
  return {left, right};
}

}  // namespace

ElementList read_element_tables(const TableReader& owner, std::string_view key) {
  std::vector<std::string_view> all_keys = kCommonElementKeys;
  Choices<size_t> types;
  for (size_t i = 0; i < element_kind_readers().size(); ++i) {
    const ElementKindReader& r = element_kind_readers()[i];
    types.emplace_back(r.type, i);
    all_keys.insert(all_keys.end(), r.keys.begin(), r.keys.end());
  }
  ElementList list;
  for (const TableReader& any : owner.tables_in_array_or_none(key, all_keys)) {
    const ElementKindReader& reader = element_kind_readers()[any.choice("type", types)];
    std::vector<std::string_view> keys = kCommonElementKeys;
    keys.insert(keys.end(), reader.keys.begin(), reader.keys.end());
    // A key of another element type: say which keys this type takes.
    for (const std::string_view key : all_keys)
      if (std::find(keys.begin(), keys.end(), key) == keys.end()) {
        std::string takes;
        for (const std::string_view own : reader.keys)
          takes += (takes.empty() ? "" : ", ") + std::string(own);
        any.reject_if_present(key, "no " + std::string(key) + " on a " + std::string(reader.type) +
                                       " (it takes " + takes + ")");
      }
    const TableReader element = any.with_keys(keys, "a " + std::string(reader.type));
    ElementEnds ends;
    ends.name = element.text("name");
    // Checked here, before mirroring appends "_left" / "_right".
    if (const std::optional<std::string> problem = name_problem(ends.name))
      element.fail("name", name_expectation(), *problem);
    ends.body1_name = element.text("body1");
    ends.body2_name = element.text("body2");
    const std::optional<Eigen::Vector3d> no_point =
        reader.points_required ? std::nullopt : std::optional(Eigen::Vector3d::Zero().eval());
    ends.point1_m = ranged_each(element, "point1_m", physical_ranges::coordinate_m, no_point);
    ends.point2_m = ranged_each(element, "point2_m", physical_ranges::coordinate_m, no_point);
    const ElementSpec spec = reader.read(element, ends);
    if (element.flag_or("mirror_lateral", false)) {
      for (const ElementSpec& half : mirrored_pair(spec, reader)) {
        list.specs.push_back(half);
        list.file_paths.push_back(element.key_path());
      }
    } else {
      list.specs.push_back(spec);
      list.file_paths.push_back(element.key_path());
    }
  }
  return list;
}

ElementList read_elements(const TableReader& top) { return read_element_tables(top, "elements"); }

}  // namespace railstab::scene_reading
