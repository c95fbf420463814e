#pragma once
// The readers of the element kinds of [[elements]] (and [[train.couplers]]),
// one per kind of the variant ElementTpl, built from the kinds' readers in
// element_readers/ (one file per kind: its own keys and how it reads them;
// element_readers/element_reader.hpp). A kind without a reader does not
// compile. The keys every element takes (name, type, body1, body2, points,
// mirror_lateral) are read by elements_reader.cpp before the kind's reader
// is called.
#include <railstab/scene/scene_spec.hpp>
#include <railstab/scene_reading/table_reader.hpp>

#include <functional>
#include <string_view>
#include <vector>

namespace railstab::scene_reading {

struct ElementKindReader {
  std::string_view type;               // the scene file's `type = "..."`
  std::vector<std::string_view> keys;  // besides the keys every element takes
  bool points_required;                // point1_m and point2_m (else both 0)
  std::function<ElementSpec(const TableReader&, const ElementEnds&)> read;
  // What mirror_lateral = true changes besides the points' y (empty: nothing).
  std::function<void(ElementSpec&)> mirror_lateral;
};

// One per element kind, in the variant's order (the order their keys are
// offered in messages).
const std::vector<ElementKindReader>& element_kind_readers();

}  // namespace railstab::scene_reading
