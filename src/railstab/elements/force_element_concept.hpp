#pragma once
// What a force element kind must provide, checked by the compiler for every
// kind in the element variant (elements/element.hpp). A kind that lacks a
// member fails to compile here, with the member named, not in some visit
// elsewhere (tests/compile_fail/ proves it).
//
// S is the element's parameter scalar (double, or ParamDual for parameter
// derivatives); apply<T> runs for every state scalar T of the right-hand side.
#include <railstab/core/scalar.hpp>
#include <railstab/elements/element_ends.hpp>
#include <railstab/kinematics/attachment.hpp>

#include <concepts>
#include <string>
#include <type_traits>
#include <variant>

namespace railstab {

// A callable the generic members are called with in the concept's check.
struct ParameterVisitorProbe {
  template <class P> void operator()(const char*, int, P&) const {}
};
struct PreloadedAxisProbe {
  void operator()(const char*, const char*, double, double) const {}
};

template <class E, class S>
concept ForceElement = requires(E e, const E ce, const Attachment<double>& a, const Vec3<S>& load,
                                const double* z, double* zdot) {
  // The kind's name in scene files and reports, its internal states (e.g. a
  // series damper's node) and whether gravity sags it in the preload solve.
  { E::kType } -> std::convertible_to<const char*>;
  { E::kInternalStates } -> std::convertible_to<int>;
  { E::kInGravitySag } -> std::convertible_to<bool>;
  { ce.ends } -> std::convertible_to<const ElementEnds&>;
  // Geometry at the nominal configuration, the elastic load there (the
  // preload solve), and the preload it solves for.
  e.set_nominal(a, a);
  { ce.template elastic_load<double>(a, a) } -> std::same_as<Vec3<double>>;
  e.set_preload(load);
  ce.for_each_preloaded_axis(PreloadedAxisProbe{});
  // The equations of motion (forces on both attachments, internal state
  // rates), the potential energy (energy tests), state and parameter names.
  ce.template apply<double>(a, a, z, zdot);
  { ce.potential(a, a, z) } -> std::convertible_to<double>;
  { ce.internal_state_name(0) } -> std::convertible_to<std::string>;
  e.for_each_parameter(ParameterVisitorProbe{});
  // The same element on another parameter scalar (model.cast<S2>()).
  { ce.template cast<double>() };
};

// Asserts ForceElement for one kind (the compiler names the kind and the
// requirement it misses) and for every kind of a variant.
template <class E, class S> constexpr bool assert_force_element() {
  static_assert(ForceElement<E, S>,
                "a force element kind lacks a member that ForceElement requires "
                "(elements/force_element_concept.hpp)");
  return true;
}
template <class S, class... E>
constexpr bool assert_force_elements(std::type_identity<std::variant<E...>>) {
  return (assert_force_element<E, S>() && ...);
}

}  // namespace railstab
