#pragma once
// The force elements of a model: one type per kind, one variant. Every
// operation on elements (equations of motion, energy, preloads, static
// deflections, state and parameter names) is a std::visit over this variant
// calling a member of the kind, so adding a kind is its own header plus its
// entry here and its reader beside the other element readers; the compiler
// checks that every kind provides the members (ForceElement,
// elements/force_element_concept.hpp).
#include <railstab/elements/anti_roll_bar.hpp>
#include <railstab/elements/bump_stop.hpp>
#include <railstab/elements/force_element_concept.hpp>
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

static_assert(assert_force_elements<double>(std::type_identity<ElementTpl<double>>{}));
static_assert(assert_force_elements<ParamDual>(std::type_identity<ElementTpl<ParamDual>>{}));

template <class S> const ElementEnds& ends_of(const ElementTpl<S>& e) {
  return std::visit([](const auto& x) -> const ElementEnds& { return x.ends; }, e);
}
template <class S> ElementEnds& ends_of(ElementTpl<S>& e) {
  return std::visit([](auto& x) -> ElementEnds& { return x.ends; }, e);
}
template <class S> int internal_states_of(const ElementTpl<S>& e) {
  return std::visit([](const auto& x) { return std::decay_t<decltype(x)>::kInternalStates; }, e);
}

}  // namespace railstab
