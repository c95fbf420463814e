#include <railstab/contact/creep/linear_kalker_creep.hpp>

#include <railstab/core/nested_dual.hpp>

namespace railstab {

template <class S> void LinearKalkerCreep<S>::validate() const {
  const double r = value_of(kalker_reduction_factor);
  creep_detail::require_parameter(r > 0.0 && r <= 1.0, "LinearKalkerCreep",
                                  "kalker_reduction_factor", r, "a value in (0, 1]");
}

template <class S>
template <class T>
CreepForces<T> LinearKalkerCreep<S>::forces(const CreepInput<T>& in) const {
  validate();
  creep_detail::require_valid_input(in, "LinearKalkerCreep");
  return creep_detail::linear_kalker_forces(in, lift<T>(kalker_reduction_factor));
}

template struct LinearKalkerCreep<double>;
template struct LinearKalkerCreep<AdScalar>;
template CreepForces<ParamDual> LinearKalkerCreep<double>::forces(const CreepInput<ParamDual>&) const;
template CreepForces<ParamAdScalar> LinearKalkerCreep<double>::forces(
    const CreepInput<ParamAdScalar>&) const;
template CreepForces<double> LinearKalkerCreep<double>::forces(const CreepInput<double>&) const;
template CreepForces<AdScalar> LinearKalkerCreep<double>::forces(
    const CreepInput<AdScalar>&) const;
template CreepForces<AdScalar> LinearKalkerCreep<AdScalar>::forces(
    const CreepInput<AdScalar>&) const;

// Parameters as AD variables (sensitivity): the model cast to ParamDual.
template CreepForces<ParamDual> LinearKalkerCreep<ParamDual>::forces(const CreepInput<ParamDual>&) const;
template CreepForces<ParamAdScalar> LinearKalkerCreep<ParamDual>::forces(const CreepInput<ParamAdScalar>&) const;

// Exact second and third state derivatives (nonlinear/multilinear_forms.hpp).
template CreepForces<Dual3> LinearKalkerCreep<double>::forces(const CreepInput<Dual3>&) const;

}  // namespace railstab
