#pragma once
// Wheel-rail contact of one wheel: geometry, normal force, creepages and
// Kalker creep forces (thesis 4.6-4.7 and 5.2-5.7, with ERRATA 6-10).
//
// Everything is computed in the wheelset's non-spinning frame I (thesis
// 4.40), so the spin angle never enters (ERRATA 11a).
//
// knife_edge_cone: the rail is a wire along the track at lateral side*e0 in the
// track plane; the wheel a cone of half-angle gamma whose radius at axial
// coordinate eta (in I) is r(eta) = r0 + tan(gamma) (e0 - side*eta). The
// contact point P is where the wire crosses the wheelset's vertical plane
// x_I = 0 (so a yawed wheelset's contact does not move longitudinally: the
// knife-edge approximation). The penetration along the cone normal is
//   delta = (r(eta) - rho) cos(gamma),  rho = distance of P from the axle,
// and forces act, and slip is measured, at the middle of the overlap.
// linear_conicity: rolling radius r0 + side*lambda*y, contact point
// (0, side*e0, -r) in I, normal along the track normal, no gravitational
// stiffness; delta = depth of that point below the track plane.
//
// Contact frame: l = x_I (rolling direction), nu = normal from the rail into
// the wheel, t = nu x l (lateral, in the contact plane). Creepages (ERRATA 10,
// normalised by V > 0): xi_x = v_slip.l / V, xi_y = v_slip.t / V,
// xi_sp = w_wheel.nu / V (the rail does not rotate). Forces on the wheel:
//   Fx = -f11 xi_x,  Fy = -f22 xi_y - f23 xi_sp,  Mz = f23 xi_y - f33 xi_sp.
// Linear creep (no saturation), as the thesis.
#include "contact/hertz.hpp"
#include "contact/kalker.hpp"
#include "contact/model_contact.hpp"
#include "contact/creep/creep_input.hpp"
#include "kinematics/body_motion.hpp"

namespace railstab {

template <class T> struct WheelContact {
  int side = 1;           // +1 left (+y), -1 right
  T penetration_m{};      // delta (<= 0: no contact, zero force)
  T normal_force_N{};
  T elastic_normal_force_N{};  // the Hertz (or prescribed) part, without damping
  // In contact: Hertz plus damping before clipping at zero (negative when
  // the damper would pull: the wheel is unloading faster than it can).
  T unclipped_normal_force_N{};
  T rolling_radius_m{};
  T semi_axis_a_m{}, semi_axis_b_m{};
  T creep_x{}, creep_y{}, creep_spin_per_m{};
  T creep_force_x_N{}, creep_force_y_N{}, spin_moment_N_m{};  // in the contact frame
  Vec3<T> force_I, moment_I;  // on the wheelset, about its CM, in I
  Vec3<T> point_I;            // contact point from the wheelset CM, in I
};

// S: the model's parameter scalar (ParameterScalar<T>: double, or ParamDual
// when T carries parameter derivatives).
template <class T, class S>
WheelContact<T> evaluate_wheel_contact(const ModelContactTpl<S>& contact, const BodyMotion<T>& ws,
                                       int side, double speed_m_per_s) {
  using std::cos;
  using std::pow;
  using std::sin;
  using std::sqrt;
  using std::tan;
  const ContactSpec& spec = contact.spec;
  const double e0 = spec.half_contact_distance_m;
  const double r0 = spec.nominal_rolling_radius_m;
  const T sd = T(double(side));
  WheelContact<T> out;
  out.side = side;
  const Vec3<T> w = ws.q.template head<3>();
  const Mat3<T> R_IT = ws.R_TI.transpose();

  Vec3<T> nu_I;  // from the rail into the wheel
  if (spec.geometry == ContactGeometryKind::knife_edge_cone) {
    // In the parameter scalar S, then lifted: no state derivatives to carry.
    const S& g = contact.cone_angle_rad;
    const T tg = lift<T>(S(tan(g))), cg = lift<T>(S(cos(g))), sg = lift<T>(S(sin(g)));
    // Wire point in the plane x_I = 0: x_I of (lambda, side e0, 0) - w vanishes.
    const T yaw = ws.q(5);
    const T lambda = w.x() - tan(yaw) * (sd * e0 - w.y());
    const Vec3<T> P_T(lambda, sd * e0, T(0));
    const Vec3<T> wire_I = R_IT * (P_T - w);
    const T eta = wire_I.y();
    const T rho = -wire_I.z();
    out.rolling_radius_m = T(r0) + tg * (T(e0) - sd * eta);
    out.penetration_m = (out.rolling_radius_m - rho) * cg;
    nu_I = Vec3<T>(T(0), -sd * sg, T(cg));
    // The contact point is the middle of the overlap (wheel and rail share
    // the approach), half-way from the wire point to the wheel surface.
    out.point_I = wire_I - T(0.5) * out.penetration_m * nu_I;
  } else {
    out.rolling_radius_m = T(r0) + sd * lift<T>(contact.conicity) * w.y();
    out.point_I = Vec3<T>(T(0), sd * e0, -out.rolling_radius_m);
    const Vec3<T> point_T = w + ws.R_TI * out.point_I;
    out.penetration_m = -point_T.z();
    nu_I = R_IT * Vec3<T>(T(0), T(0), T(1));
  }
  const Vec3<T> l_I(T(1), T(0), T(0));
  const Vec3<T> t_I = nu_I.cross(l_I);

  // Normal force and contact ellipse.
  const bool in_contact = value_of(out.penetration_m) > 0.0;
  const bool needs_hertz = spec.normal == NormalForceKind::hertz ||
                           spec.tangential == TangentialForceKind::kalker_hertz;
  HertzShape<T> shape{};
  if (needs_hertz) {
    const T A = T(0.5) / out.rolling_radius_m;
    shape = hertz_shape(A, T(contact.rail_curvature_B_per_m),
                        contact.materials.effective_modulus_Pa);
  }
  // Velocity of the wheel material at P (the rail is at rest): the slip
  // velocity of the creepages, and along -nu the penetration rate. Only
  // when creep or contact damping needs it.
  Vec3<T> v_slip_I = Vec3<T>::Zero();
  if (spec.tangential != TangentialForceKind::none || spec.normal_damping_N_s_per_m > 0.0) {
    const Vec3<T> w_T = to_scalar<T>(ws.track->w_WT_T);
    const Vec3<T> v_T = to_scalar<T>(ws.track->v_WT_T);
    const Vec3<T> v_centre_I = R_IT * (v_T + w_T.cross(w) + ws.qd.template head<3>());
    v_slip_I = v_centre_I + ws.w_B_I.cross(out.point_I);
  }
  // The normal load (Hertz plus damping, never pulling) sizes the contact
  // ellipse, so the creep coefficients go to zero with it, continuously,
  // whether the wheel lifts off or the damper unloads it. The elastic part
  // alone is kept for the contact's potential energy.
  T& elastic_N = out.elastic_normal_force_N;
  elastic_N = T(0);  // (an AutoDiffScalar's T{} leaves the value unset)
  out.normal_force_N = T(0);
  out.unclipped_normal_force_N = T(0);
  if (spec.normal == NormalForceKind::prescribed) {
    elastic_N = T(spec.prescribed_wheel_load_N);
    out.normal_force_N = elastic_N;
  } else if (in_contact) {
    elastic_N = T(shape.stiffness * pow(out.penetration_m, 1.5));
    out.normal_force_N = elastic_N;
    out.unclipped_normal_force_N = elastic_N;
    if (spec.normal_damping_N_s_per_m > 0.0) {
      const T penetration_rate = -v_slip_I.dot(nu_I);
      out.normal_force_N += T(spec.normal_damping_N_s_per_m) * penetration_rate;
      out.unclipped_normal_force_N = out.normal_force_N;
      if (value_of(out.normal_force_N) < 0.0) out.normal_force_N = T(0);  // never pulls
    }
  }
  out.force_I = out.normal_force_N * nu_I;
  out.moment_I = out.point_I.cross(out.force_I);
  if (spec.tangential == TangentialForceKind::none || value_of(out.normal_force_N) <= 0.0)
    return out;

  // Creepages.
  const T V = T(speed_m_per_s);
  out.creep_x = v_slip_I.dot(l_I) / V;
  out.creep_y = v_slip_I.dot(t_I) / V;
  out.creep_spin_per_m = spec.spin_creepage ? T(ws.w_B_I.dot(nu_I) / V) : T(0);

  CreepCoefficients<T> f;
  if (spec.tangential == TangentialForceKind::constant) {
    f = {T(spec.f11_N), T(spec.f22_N), T(spec.f23_N_m), T(spec.f33_N_m2)};
  } else {
    const T cube_root_N = pow(out.normal_force_N, 1.0 / 3.0);
    out.semi_axis_a_m = shape.semi_axis_a_per_force_13 * cube_root_N;
    out.semi_axis_b_m = shape.semi_axis_b_per_force_13 * cube_root_N;
    f = kalker_coefficients(out.semi_axis_a_m, out.semi_axis_b_m,
                            contact.materials.shear_modulus_Pa, contact.materials.poisson_ratio);
  }
  // The creep law (linear Kalker, or saturating at mu N), dispatched once.
  CreepInput<T> creep;
  creep.creep_x = out.creep_x;
  creep.creep_y = out.creep_y;
  creep.creep_spin_per_m = out.creep_spin_per_m;
  creep.normal_force_N = out.normal_force_N;
  creep.semi_axis_a_m = out.semi_axis_a_m;
  creep.semi_axis_b_m = out.semi_axis_b_m;
  creep.f11_N = f.f11_N;
  creep.f22_N = f.f22_N;
  creep.f23_N_m = f.f23_N_m;
  creep.f33_N_m2 = f.f33_N_m2;
  creep.speed_m_per_s = V;
  const CreepForces<T> F = std::visit(
      [&](const auto& law) { return law.template forces<T>(creep); }, contact.creep_law);
  const T Fx = F.force_x_N;
  const T Fy = F.force_y_N;
  const T Mz = F.spin_moment_N_m;
  out.creep_force_x_N = Fx;
  out.creep_force_y_N = Fy;
  out.spin_moment_N_m = Mz;
  const Vec3<T> tangential_I = Fx * l_I + Fy * t_I;
  out.force_I += tangential_I;
  out.moment_I += out.point_I.cross(tangential_I) + Mz * nu_I;
  return out;
}

}  // namespace railstab
