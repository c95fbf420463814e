#pragma once
// What a creep law must provide, checked by the compiler for every law in the
// creep-law variant (creep_law.hpp CreepLawTpl): a law that lacks a
// member fails to compile there, with the member named.
//   kName                 its creep_law name in scene files and reports
//   validate()            std::invalid_argument naming the bad field
//   forces<T>(input)      tangential forces from creepages (T: every state scalar)
//   for_each_parameter    f(scene key, -1, value&) (sensitivity keys)
//   cast<S2>()            the same law on another parameter scalar
#include <railstab/contact/creep/creep_input.hpp>

#include <concepts>
#include <type_traits>
#include <variant>

namespace railstab {

struct CreepParameterProbe {
  template <class P> void operator()(const char*, int, P&) const {}
};

template <class L>
concept CreepLaw = requires(L law, const L claw, const CreepInput<double>& in) {
  { L::kName } -> std::convertible_to<const char*>;
  claw.validate();
  { claw.template forces<double>(in) } -> std::same_as<CreepForces<double>>;
  law.for_each_parameter(CreepParameterProbe{});
  { claw.template cast<double>() };
};

template <class L> constexpr bool assert_creep_law() {
  static_assert(CreepLaw<L>,
                "a creep law lacks a member that CreepLaw requires "
                "(contact/creep/creep_law_concept.hpp)");
  return true;
}
template <class... L> constexpr bool assert_creep_laws(std::type_identity<std::variant<L...>>) {
  return (assert_creep_law<L>() && ...);
}

}  // namespace railstab
