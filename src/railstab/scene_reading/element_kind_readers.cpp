#include <railstab/scene_reading/element_kind_readers.hpp>

// One reader per element kind, each in its own file beside the others
// (element_readers/, named after the kind's header in elements/).
#include <railstab/scene_reading/element_readers/anti_roll_bar_reader.hpp>
#include <railstab/scene_reading/element_readers/bump_stop_reader.hpp>
#include <railstab/scene_reading/element_readers/line_spring_damper_reader.hpp>
#include <railstab/scene_reading/element_readers/rotational_spring_damper_reader.hpp>
#include <railstab/scene_reading/element_readers/series_spring_damper_reader.hpp>
#include <railstab/scene_reading/element_readers/spring_damper_3d_reader.hpp>
#include <railstab/scene_reading/element_readers/traction_rod_reader.hpp>

#include <type_traits>
#include <variant>

namespace railstab::scene_reading {

namespace {

template <class Kind> ElementKindReader reader_of() {
  static_assert(ElementKindHasReader<Kind>,
                "an element kind of ElementTpl has no scene reader: add "
                "scene_reading/element_readers/<kind>_reader.hpp with ElementReader<Kind> "
                "(see element_readers/element_reader.hpp) and include it above");
  using Reader = ElementReader<Kind>;
  ElementKindReader r;
  r.type = Kind::kType;
  r.keys.assign(Reader::kKeys.begin(), Reader::kKeys.end());
  r.points_required = Reader::kPointsRequired;
  r.read = [](const TableReader& t, const ElementEnds& ends) -> ElementSpec {
    Kind e = Reader::read(t);
    e.ends = ends;
    return e;
  };
  if constexpr (requires(Kind& e) { Reader::mirror_lateral(e); })
    r.mirror_lateral = [](ElementSpec& spec) { Reader::mirror_lateral(std::get<Kind>(spec)); };
  return r;
}

// Every kind of the variant, in the variant's order.
template <class... Kinds>
std::vector<ElementKindReader> readers_of(std::type_identity<std::variant<Kinds...>>) {
  return {reader_of<Kinds>()...};
}

}  // namespace

const std::vector<ElementKindReader>& element_kind_readers() {
  static const std::vector<ElementKindReader> readers =
      readers_of(std::type_identity<ElementSpec>{});
  return readers;
}

}  // namespace railstab::scene_reading
