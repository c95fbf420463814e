#pragma once
// The creep law of a contact: the tangential forces from the creepages and
// Kalker's linear coefficients, one type per law (this folder), one variant.
// Adding a law is one file pair here plus one entry in CreepLawTpl; the
// compiler checks every entry against CreepLaw (creep_law_concept.hpp).
#include <railstab/contact/creep/creep_law_concept.hpp>
#include <railstab/contact/creep/linear_kalker_creep.hpp>
#include <railstab/contact/creep/polach_creep.hpp>
#include <railstab/contact/creep/shen_hedrick_elkins_creep.hpp>

#include <type_traits>
#include <variant>

namespace railstab {

template <class S>
using CreepLawTpl = std::variant<LinearKalkerCreep<S>, ShenHedrickElkinsCreep<S>, PolachCreep<S>>;
using CreepLawSpec = CreepLawTpl<double>;
static_assert(assert_creep_laws(std::type_identity<CreepLawTpl<double>>{}));

}  // namespace railstab
