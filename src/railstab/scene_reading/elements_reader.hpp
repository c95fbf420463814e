#pragma once
// [[elements]]: the force elements between bodies (or between a body and
// the track, body1 = "track"). Every element takes name, type, body1,
// body2, point1_m, point2_m (in each body's frame) and mirror_lateral (a
// "<name>_left" as given and a "<name>_right" mirrored in y); each type adds
// its own keys (element_readers/, one file per type) and rejects any other.
#include <railstab/scene/scene_spec.hpp>
#include <railstab/scene_reading/table_reader.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace railstab::scene_reading {

// Elements as read, and for each the key path of the table it came from (a
// mirrored table gives two elements with the same path), for the checker's
// messages.
struct ElementList {
  std::vector<ElementSpec> specs;
  std::vector<std::string> file_paths;
};

// The element tables of the array `key` of `owner` ([[elements]], and
// [[train.couplers]] which are elements too); none if the key is absent.
ElementList read_element_tables(const TableReader& owner, std::string_view key);

// The [[elements]] of the document `top`.
ElementList read_elements(const TableReader& top);

}  // namespace railstab::scene_reading
