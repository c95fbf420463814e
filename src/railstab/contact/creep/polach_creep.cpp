#include <railstab/contact/creep/polach_creep.hpp>

#include <railstab/core/nested_dual.hpp>

#include <railstab/contact/creep/smooth_functions.hpp>

#include <numbers>

namespace railstab {

template <class S> void PolachCreep<S>::validate() const {
  const char* law = "PolachCreep";
  using creep_detail::require_parameter;
  const double mu0 = value_of(friction_coefficient);
  const double A = value_of(limit_friction_ratio);
  const double B = value_of(friction_decrease_rate_s_per_m);
  const double kA = value_of(adhesion_reduction_factor);
  const double kS = value_of(slip_reduction_factor);
  const double r = value_of(kalker_reduction_factor);
  require_parameter(mu0 > 0.0 && std::isfinite(mu0), law, "friction_coefficient", mu0,
                    "a finite value > 0");
  require_parameter(A > 0.0 && A <= 1.0, law, "limit_friction_ratio", A, "a value in (0, 1]");
  require_parameter(B >= 0.0 && std::isfinite(B), law, "friction_decrease_rate_s_per_m", B,
                    "a finite value >= 0 (s/m)");
  require_parameter(kA > 0.0 && kA <= 1.0, law, "adhesion_reduction_factor", kA,
                    "a value in (0, 1]");
  require_parameter(kS > 0.0 && kS <= kA, law, "slip_reduction_factor", kS,
                    "a value in (0, adhesion_reduction_factor]");
  require_parameter(r > 0.0 && r <= 1.0, law, "kalker_reduction_factor", r, "a value in (0, 1]");
}

template <class S>
template <class T>
CreepForces<T> PolachCreep<S>::forces(const CreepInput<T>& in) const {
  using std::exp;
  validate();
  creep_detail::require_valid_input(in, "PolachCreep");
  if (value_of(in.normal_force_N) <= 0.0) return creep_detail::zero_forces<T>();
  if (!(value_of(in.semi_axis_a_m) > 0.0) || !(value_of(in.semi_axis_b_m) > 0.0)) {
    std::ostringstream msg;
    msg << "PolachCreep: input semi_axis_a_m and semi_axis_b_m must be > 0 under load, got a = "
        << value_of(in.semi_axis_a_m) << " m, b = " << value_of(in.semi_axis_b_m) << " m";
    throw std::domain_error(msg.str());
  }
  constexpr double pi = std::numbers::pi;
  const T r = lift<T>(kalker_reduction_factor);
  const T kA = lift<T>(adhesion_reduction_factor), kS = lift<T>(slip_reduction_factor);
  const T f11 = r * in.f11_N, f22 = r * in.f22_N, f23 = r * in.f23_N_m, f33 = r * in.f33_N_m2;
  const T& sx = in.creep_x;
  const T& sy = in.creep_y;
  const T& phi = in.creep_spin_per_m;
  const T& a = in.semi_axis_a_m;

  // Spin-corrected lateral creepage and resultant (squares only).
  const T sy_spin = sy + phi * a;
  const T syC2 = creep_detail::smooth_max(T(sy * sy), T(sy_spin * sy_spin), kSpinSwitchWidth);
  const T sC2 = sx * sx + syC2;

  // Friction at the slip velocity w = V s_C.
  const T V = in.speed_m_per_s;
  const T w = creep_detail::regularised_norm(T(V * V * sC2), kSlipVelocityRegularisation_m_per_s);
  const T A = lift<T>(limit_friction_ratio);
  const T mu = lift<T>(friction_coefficient) *
               ((1.0 - A) * exp(T(-lift<T>(friction_decrease_rate_s_per_m) * w)) + A);
  const T mu_N = mu * in.normal_force_N;

  // eps^2 and the saturation ratio R(eps^2).
  const T scale = pi / 4.0 / mu_N;
  const T ex = scale * f11 * sx;
  const T eps2 = ex * ex + scale * scale * f22 * f22 * syC2;
  const T R = 0.5 * (kA / (1.0 + kA * kA * eps2) +
                     kS * creep_detail::atan_root_over_root(T(kS * kS * eps2)));
  const T R0 = 0.5 * (kA + kS);

  // Spin: eps_M^2 and F_yS = -f23 phi / (1 + eps_M^2)^2.
  const T K_S = 1.0 + 6.3 * (1.0 - exp(T(-a / in.semi_axis_b_m)));
  const T cM = (8.0 / 3.0) * f23 / (a * mu_N * K_S);
  const T epsM2 = cM * cM * sC2;
  const T spin_decay = 1.0 / (1.0 + epsM2);
  const T F_yS = -f23 * phi * spin_decay * spin_decay;

  CreepForces<T> out;
  out.force_x_N = -f11 * sx * R;
  out.force_y_N = -f22 * sy * R + F_yS;
  out.spin_moment_N_m = (f23 * sy - f33 * phi) * (R / R0);
  return out;
}

template struct PolachCreep<double>;
template struct PolachCreep<AdScalar>;
template CreepForces<ParamDual> PolachCreep<double>::forces(const CreepInput<ParamDual>&) const;
template CreepForces<ParamAdScalar> PolachCreep<double>::forces(
    const CreepInput<ParamAdScalar>&) const;
template CreepForces<double> PolachCreep<double>::forces(const CreepInput<double>&) const;
template CreepForces<AdScalar> PolachCreep<double>::forces(const CreepInput<AdScalar>&) const;
template CreepForces<AdScalar> PolachCreep<AdScalar>::forces(const CreepInput<AdScalar>&) const;

// Parameters as AD variables (sensitivity): the model cast to ParamDual.
template CreepForces<ParamDual> PolachCreep<ParamDual>::forces(const CreepInput<ParamDual>&) const;
template CreepForces<ParamAdScalar> PolachCreep<ParamDual>::forces(const CreepInput<ParamAdScalar>&) const;

// Exact second and third state derivatives (nonlinear/multilinear_forms.hpp).
template CreepForces<Dual3> PolachCreep<double>::forces(const CreepInput<Dual3>&) const;

}  // namespace railstab
