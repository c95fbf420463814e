#pragma once
// The names of an enumeration in scene files, messages and reports, written
// once, beside the enumeration:
//   inline constexpr NameTable<TrackSegmentKind, 3> kTrackSegmentKindNames = {{
//       {"tangent", TrackSegmentKind::tangent}, ...}};
// The scene reader takes its choices (and the names its messages list) from
// the table, the writers and messages the name of a value (name_in).
#include <array>
#include <cstddef>
#include <string_view>
#include <utility>

namespace railstab {

template <class Enum, std::size_t N>
using NameTable = std::array<std::pair<std::string_view, Enum>, N>;

// The name of `value` in `table`; "unknown" for a value the table lacks.
template <class Enum, std::size_t N>
constexpr std::string_view name_in(const NameTable<Enum, N>& table, Enum value) {
  for (const auto& [name, v] : table)
    if (v == value) return name;
  return "unknown";
}

}  // namespace railstab
