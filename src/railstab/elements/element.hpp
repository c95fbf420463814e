#pragma once
// The force elements of a model: one type per kind, one variant. Every
// operation on elements (equations of motion, energy, preloads, state names)
// is a std::visit over this variant, so adding a kind is its own header plus
// its entry here and its reader in io/element_readers.cpp; the compiler
// then checks that the kind provides everything those visits call:
//   kType, kInternalStates, kInGravitySag, ends, set_nominal, elastic_load, set_preload,
//   apply<T>, potential, internal_state_name, for_each_parameter, cast<S2>.
#include <railstab/elements/anti_roll_bar.hpp>
#include <railstab/elements/bump_stop.hpp>
#include <railstab/elements/line_spring_damper.hpp>
#include <railstab/elements/rotational_spring_damper.hpp>
#include <railstab/elements/series_spring_damper.hpp>
#include <railstab/elements/spring_damper_3d.hpp>
#include <railstab/elements/traction_rod.hpp>

#include <variant>

namespace railstab {

template <class S>
using ElementTpl = std::variant<SpringDamper3d<S>, RotationalSpringDamper<S>, SeriesSpringDamper<S>,
                                LineSpringDamper<S>, BumpStop<S>, TractionRod<S>,
                                AntiRollBar<S>>;

template <class S> const ElementEnds& ends_of(const ElementTpl<S>& e) {
  return std::visit([](const auto& x) -> const ElementEnds& { return x.ends; }, e);
}
template <class S> ElementEnds& ends_of(ElementTpl<S>& e) {
  return std::visit([](auto& x) -> ElementEnds& { return x.ends; }, e);
}
template <class S> const char* type_of(const ElementTpl<S>& e) {
  return std::visit([](const auto& x) { return std::decay_t<decltype(x)>::kType; }, e);
}
template <class S> int internal_states_of(const ElementTpl<S>& e) {
  return std::visit([](const auto& x) { return std::decay_t<decltype(x)>::kInternalStates; }, e);
}

}  // namespace railstab
