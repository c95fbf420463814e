#pragma once
// The reader of one element kind's own scene keys: a specialisation
// ElementReader<Kind<double>> in this folder, one file per kind, named after
// the kind's header in elements/ (spring_damper_3d.hpp ->
// spring_damper_3d_reader.hpp). It provides
//   kKeys            the kind's own keys (besides name, type, body1, body2,
//                    point1_m, point2_m and mirror_lateral, which
//                    elements_reader.cpp reads for every kind);
//   kPointsRequired  whether point1_m and point2_m must be given (else 0);
//   read(t)          the kind with its own keys read from the table t
//                    (its ends are set by the caller);
// and optionally
//   mirror_lateral(e) what mirror_lateral = true changes besides the two
//                    points' y (e.g. a bump stop's axis).
// element_kind_readers.cpp builds the table of readers from the variant
// ElementTpl (elements/element.hpp): a kind in the variant without a reader
// here does not compile (ElementKindHasReader below).
#include <railstab/elements/force_characteristic.hpp>
#include <railstab/scene/physical_ranges.hpp>
#include <railstab/scene_reading/table_reader.hpp>

#include <concepts>
#include <string_view>

namespace railstab::scene_reading {

// No reader: the primary template is empty, so ElementKindHasReader fails.
template <class Kind> struct ElementReader {};

template <class Kind>
concept ElementKindHasReader = requires(const TableReader& t) {
  { ElementReader<Kind>::read(t) } -> std::same_as<Kind>;
  { ElementReader<Kind>::kPointsRequired } -> std::convertible_to<bool>;
  ElementReader<Kind>::kKeys.begin();
};

// A force characteristic: `linear_key` (a coefficient) or `table_key`
// ([[x, F], ...] with x strictly increasing), exactly one of them; neither
// gives a zero coefficient when not `required`. A table has the scale
// factor `scale_key` (F = scale P(x), default 1, in
// physical_ranges::table_force_scale): the parameter that varies it in
// --set, study and sensitivity as the coefficient varies a linear one; the
// key beside a coefficient (or nothing) is refused.
ForceCharacteristic<double> read_force_characteristic(const TableReader& t,
                                                      std::string_view linear_key,
                                                      const PhysicalRange& linear_range,
                                                      std::string_view table_key,
                                                      const PhysicalRange& x_range,
                                                      std::string_view scale_key,
                                                      bool required = true);

}  // namespace railstab::scene_reading
