#include <railstab/contact/creep/shen_hedrick_elkins_creep.hpp>

#include <railstab/core/nested_dual.hpp>

#include <railstab/contact/creep/smooth_functions.hpp>

namespace railstab {

template <class S> void ShenHedrickElkinsCreep<S>::validate() const {
  const char* law = "ShenHedrickElkinsCreep";
  const double mu = value_of(friction_coefficient);
  const double r = value_of(kalker_reduction_factor);
  creep_detail::require_parameter(mu > 0.0 && std::isfinite(mu), law, "friction_coefficient",
                                  mu, "a finite value > 0");
  creep_detail::require_parameter(r > 0.0 && r <= 1.0, law, "kalker_reduction_factor", r,
                                  "a value in (0, 1]");
}

template <class S>
template <class T>
CreepForces<T> ShenHedrickElkinsCreep<S>::forces(const CreepInput<T>& in) const {
  validate();
  creep_detail::require_valid_input(in, "ShenHedrickElkinsCreep");
  if (value_of(in.normal_force_N) <= 0.0) return creep_detail::zero_forces<T>();
  const CreepForces<T> lin =
      creep_detail::linear_kalker_forces(in, lift<T>(kalker_reduction_factor));
  const T mu_N = lift<T>(friction_coefficient) * in.normal_force_N;
  const T fx = lin.force_x_N / mu_N, fy = lin.force_y_N / mu_N;
  const T u = creep_detail::regularised_norm(T(fx * fx + fy * fy), kResultantRegularisation);
  // e(u) = g(u)/u
  const T e = value_of(u) < 3.0 ? T(1.0 - u / 3.0 + u * u / 27.0) : T(1.0 / u);
  return CreepForces<T>{T(e * lin.force_x_N), T(e * lin.force_y_N), T(e * lin.spin_moment_N_m)};
}

template struct ShenHedrickElkinsCreep<double>;
template struct ShenHedrickElkinsCreep<AdScalar>;
template CreepForces<ParamDual> ShenHedrickElkinsCreep<double>::forces(const CreepInput<ParamDual>&) const;
template CreepForces<ParamAdScalar> ShenHedrickElkinsCreep<double>::forces(
    const CreepInput<ParamAdScalar>&) const;
template CreepForces<double> ShenHedrickElkinsCreep<double>::forces(
    const CreepInput<double>&) const;
template CreepForces<AdScalar> ShenHedrickElkinsCreep<double>::forces(
    const CreepInput<AdScalar>&) const;
template CreepForces<AdScalar> ShenHedrickElkinsCreep<AdScalar>::forces(
    const CreepInput<AdScalar>&) const;

// Parameters as AD variables (sensitivity): the model cast to ParamDual.
template CreepForces<ParamDual> ShenHedrickElkinsCreep<ParamDual>::forces(const CreepInput<ParamDual>&) const;
template CreepForces<ParamAdScalar> ShenHedrickElkinsCreep<ParamDual>::forces(const CreepInput<ParamAdScalar>&) const;

// Exact second and third state derivatives (nonlinear/multilinear_forms.hpp).
template CreepForces<Dual3> ShenHedrickElkinsCreep<double>::forces(const CreepInput<Dual3>&) const;

}  // namespace railstab
