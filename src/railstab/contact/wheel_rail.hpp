#pragma once
// Wheel-rail contact of one wheel: geometry, normal force, creepages and
// Kalker creep forces (thesis 4.6-4.7 and 5.2-5.7, with ERRATA 6-10).
//
// Everything is computed in the wheelset's non-spinning frame I (thesis
// 4.40), so the spin angle never enters (ERRATA 11a).
//
// Track irregularities displace each rail (TrackFrameKinematics::rails,
// translations dy, dz in the track frame at the wheelset's arc length): every
// geometry measures the wheel from its own displaced rail. The rails do not
// move in time, so the slip velocities below (the wheel material's absolute
// velocity) need no irregularity term.
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
// profiles (and table, the same read from a file): the contact table of
// the profile pair (contact_geometry/
// contact_tables.hpp) gives, per slot (tread, flange, ...; each its own
// contact), the vertical gap g, the contact angle gamma in the rail frame,
// the wheel profile coordinate u, the rolling radius r and the Hertz
// curvatures A, B, from the wheelset's lateral shift y, height z and roll
// phi in its track frame (yaw neglected in the geometry: the contact stays
// in the plane x_I = 0, as the knife edge). In I (side s, D the wheel
// profile origin's distance from the centre, wheelset_pose.hpp):
//   point  (0, s (D + u), -r),  normal nu = (0, -s sin(gamma - s phi), cos(gamma - s phi)),
//   delta = -g cos(gamma) (the gap along the common normal),
// and, as for the cone, forces act at the middle of the overlap. A slot
// whose lowest point sits on its border (not a true contact: its overlap is
// its neighbour's) is faded out by its interpolated on_border weight.
//
// Shared overlap (near-conformal treads: S1002 on UIC60 has two tread slots
// whose overlaps join). Where the lowest points of neighbouring slots k and
// j = k +- 1 both overlap and the highest gap between them, the saddle b
// (barrier_to_next_gap0_m + vertical), is below zero, the overlap region is
// connected and its common depth s = -b would be counted twice. Each slot
// keeps its own lobe below the saddle, e = d - s (d = -g its overlap), and
// the two share s in proportion to their lobes squared:
//   d_eff,k = d_k - w_j s e_j^2 / (e_k^2 + e_j^2)   (e clipped at 0, +1e-12 m
//                                                    each; s <= min(d_k, d_j))
// (w_j the neighbour's interior weight), so a lobe born at the saddle
// (e_j = 0) adds nothing, and the pair's effective overlaps sum to
// e_k + e_j + s: the deeper one's depth plus the shallower lobe. With
// separate overlaps (b >= 0) each slot keeps its own d. The penetration is
// d_eff cos(gamma). Without this, the force doubled within one table cell
// where a second tread slot's lowest point left its border while
// overlapping (docs/model.md, section 6.1).
//
// Contact frame: l = x_I (rolling direction), nu = normal from the rail into
// the wheel, t = nu x l (lateral, in the contact plane). Creepages (ERRATA 10,
// normalised by V > 0): xi_x = v_slip.l / V, xi_y = v_slip.t / V,
// xi_sp = w_wheel.nu / V (the rail does not rotate). Forces on the wheel:
//   Fx = -f11 xi_x,  Fy = -f22 xi_y - f23 xi_sp,  Mz = f23 xi_y - f33 xi_sp.
// The creep law (linear Kalker as the thesis, or saturating) is the
// contact's (contact/creep/).
//
// Regularisation at the edges of the theories (both C-infinity, AD-safe):
// - Hertz needs B > 0; a profile contact's B -> 0 where a contact point is
//   born or vanishes (conformal contact), so B enters Hertz as
//   smooth_max(B, kMinimumTransverseCurvature, width) (equivalent transverse
//   radius at most ~17 m; no effect for B > 0.06 1/m).
// - Kalker's table covers 0.1 <= a/b <= 10; the flange's narrow ellipse
//   (a/b ~ 15) and a near-conformal tread's wide one lie outside, so the
//   coefficients are taken at a/b softly clamped into [0.112, 8.9] (same
//   area ab); the creep law still sees the Hertz a and b.
#include <algorithm>

#include <railstab/contact/creep/smooth_functions.hpp>
#include <railstab/contact/hertz.hpp>
#include <railstab/contact/kalker.hpp>
#include <railstab/contact/model_contact.hpp>
#include <railstab/contact/creep/creep_input.hpp>
#include <railstab/contact_geometry/profile_contact_geometry.hpp>
#include <railstab/kinematics/body_motion.hpp>

namespace railstab {

template <class T> struct WheelContact {
  int side = 1;           // +1 left (+y), -1 right
  int slot = 0;           // contact point of the wheel (profiles: table slot)
  T penetration_m{};      // delta (<= 0: no contact, zero force)
  T normal_force_N{};
  T elastic_normal_force_N{};  // the Hertz (or prescribed) part, without damping
  // In contact: Hertz plus damping before clipping at zero (negative when
  // the damper would pull: the wheel is unloading faster than it can).
  T unclipped_normal_force_N{};
  T rolling_radius_m{};
  T contact_angle_rad{};  // of the normal to the wheel's axle (in I): 0 on a flat tread
  T semi_axis_a_m{}, semi_axis_b_m{};
  T creep_x{}, creep_y{}, creep_spin_per_m{};
  T creep_force_x_N{}, creep_force_y_N{}, spin_moment_N_m{};  // in the contact frame
  Vec3<T> force_I, moment_I;  // on the wheelset, about its CM, in I
  Vec3<T> point_I;            // contact point from the wheelset CM, in I
};

// Where and how one contact point touches (the geometry's output, the force
// laws' input).
template <class T> struct ContactPointGeometry {
  Vec3<T> point_I;       // from the wheelset CM, in I, at the middle of the overlap
  Vec3<T> nu_I;          // unit normal from the rail into the wheel, in I
  T rolling_radius_m, penetration_m;
  T A_per_m, B_per_m;    // Hertz relative curvatures (rolling, transverse)
  T weight;              // 1; a profile slot's fade at its border (0..1)
  T contact_angle_rad;   // of nu from the wheel's radial direction (0: flat tread; flange ~1.2)
};

inline constexpr double kMinimumTransverseCurvature_per_m = 0.03;
inline constexpr double kTransverseCurvatureFloorWidth_per_m = 0.02;
inline constexpr double kKalkerRatioClampWidth = 0.1;  // in ln(a/b)

namespace wheel_rail_detail {

// Kalker's table range for a/b, softly: ln(a/b) through a smooth max with
// ln(0.1) + 0.11 and a smooth min with ln(10) - 0.11 (width 0.1: each moves
// its argument by at most 0.05, so the result stays inside [0.1, 10]).
template <class T> T kalker_ratio_in_table(const T& a_over_b) {
  using std::exp;
  using std::log;
  const double w = kKalkerRatioClampWidth;
  const T x = log(a_over_b);
  const T lo = creep_detail::smooth_max(x, T(std::log(0.1) + 0.11), w);
  const T hi = -creep_detail::smooth_max(T(-lo), T(-(std::log(10.0) - 0.11)), w);
  return exp(hi);
}

template <class T, class S>
ContactPointGeometry<T> knife_edge_geometry(const ModelContactTpl<S>& contact,
                                            const BodyMotion<T>& ws, int side) {
  using std::tan;
  using std::cos;
  using std::sin;
  const ContactSpec& spec = contact.spec;
  const double e0 = spec.half_contact_distance_m;
  const double r0 = spec.nominal_rolling_radius_m;
  const T sd = T(double(side));
  const Vec3<T> w = ws.q.template head<3>();
  const Mat3<T> R_IT = ws.R_TI.transpose();
  ContactPointGeometry<T> g;
  // In the parameter scalar S, then lifted: no state derivatives to carry.
  const S& angle = contact.cone_angle_rad;
  const T tg = lift<T>(S(tan(angle))), cg = lift<T>(S(cos(angle))), sg = lift<T>(S(sin(angle)));
  // Wire point in the plane x_I = 0: x_I of (lambda, side e0 + dy, dz) - w
  // vanishes (dy, dz: the rail's displacement by the track irregularities).
  const RailDisplacement& rail = ws.track->rail(side);
  const double wire_y = side * e0 + rail.lateral_m;
  const T yaw = ws.q(5);
  const T lambda = w.x() - tan(yaw) * (T(wire_y) - w.y());
  const Vec3<T> P_T(lambda, T(wire_y), T(rail.vertical_m));
  const Vec3<T> wire_I = R_IT * (P_T - w);
  const T eta = wire_I.y();
  const T rho = -wire_I.z();
  g.rolling_radius_m = T(r0) + tg * (T(e0) - sd * eta);
  g.penetration_m = (g.rolling_radius_m - rho) * cg;
  g.nu_I = Vec3<T>(T(0), -sd * sg, cg);
  // The contact point is the middle of the overlap (wheel and rail share
  // the approach), half-way from the wire point to the wheel surface.
  g.point_I = wire_I - T(0.5) * g.penetration_m * g.nu_I;
  g.A_per_m = T(0.5) / g.rolling_radius_m;
  g.B_per_m = T(contact.rail_curvature_B_per_m);
  g.weight = T(1);
  g.contact_angle_rad = lift<T>(angle);
  return g;
}

template <class T, class S>
ContactPointGeometry<T> linear_conicity_geometry(const ModelContactTpl<S>& contact,
                                                 const BodyMotion<T>& ws, int side) {
  const ContactSpec& spec = contact.spec;
  const T sd = T(double(side));
  const Vec3<T> w = ws.q.template head<3>();
  // Measured from this wheel's rail (displaced by the track irregularities).
  const RailDisplacement& rail = ws.track->rail(side);
  ContactPointGeometry<T> g;
  g.rolling_radius_m = T(spec.nominal_rolling_radius_m) +
                       sd * lift<T>(contact.conicity) * (w.y() - T(rail.lateral_m));
  g.point_I = Vec3<T>(T(0), sd * spec.half_contact_distance_m, -g.rolling_radius_m);
  const Vec3<T> point_T = w + ws.R_TI * g.point_I;
  g.penetration_m = T(rail.vertical_m) - point_T.z();
  g.nu_I = ws.R_TI.transpose() * Vec3<T>(T(0), T(0), T(1));
  g.A_per_m = T(0.5) / g.rolling_radius_m;
  g.B_per_m = T(contact.rail_curvature_B_per_m);
  g.weight = T(1);
  g.contact_angle_rad = T(0);
  return g;
}

// The part of slot `slot`'s vertical overlap -gap that a neighbouring slot
// carries (header comment, "Shared overlap"); 0 where no neighbour's
// overlap joins it.
template <class T>
T shared_overlap_m(const ContactTable& table, const WheelPoseOf<T>& pose, int slot, const T& gap) {
  constexpr double kLobeFloor_m = 1e-12;
  T shared = T(0);
  for (const int j : {slot - 1, slot + 1}) {
    if (j < 0 || j >= table.slots()) continue;
    const ContactTable::Neighbour<T> n = table.neighbour<T>(slot, j, pose);
    if (!n.overlaps) continue;
    const T& gap_j = n.vertical_gap_m;
    const T& barrier = n.saddle_gap_m;
    if (value_of(barrier) >= 0.0) continue;  // separate overlaps
    const T& w_j = n.interior_weight;
    if (value_of(w_j) <= 0.0) continue;
    // The saddle lies between the two lowest points, so it is no deeper than
    // the shallower of them; the interpolated tables can disagree by their
    // resolution error (a few um), which must not remove both contacts.
    T saddle = -barrier;
    if (value_of(saddle) > -value_of(gap)) saddle = -gap;
    if (value_of(saddle) > -value_of(gap_j)) saddle = -gap_j;
    const auto clipped = [](const T& x) { return value_of(x) > 0.0 ? x : T(0); };
    const T lobe = clipped(T(-gap - saddle)) + kLobeFloor_m;
    const T lobe_j = clipped(T(-gap_j - saddle)) + kLobeFloor_m;
    shared += w_j * saddle * lobe_j * lobe_j / (lobe * lobe + lobe_j * lobe_j);
  }
  return shared;
}

// Slot `slot` of a profile contact; the full geometry only where the slot
// overlaps (vertical gap < 0) and is not wholly a border contact.
template <class T, class S>
ContactPointGeometry<T> profile_slot_geometry(const ModelContactTpl<S>& contact,
                                              const BodyMotion<T>& ws, int side, int slot) {
  using std::cos;
  using std::sin;
  const ProfileContactGeometry& pg = *contact.spec.profile_geometry;
  const double s = side > 0 ? 1.0 : -1.0;
  // The wheelset relative to this wheel's rail: a rail displaced by the
  // track irregularities is the wheelset displaced the other way.
  const RailDisplacement& rail = ws.track->rail(side);
  // Each wheel on its own pair and table (an asymmetric wheelset: the right
  // wheel's profile, radius and rail; ProfileContactGeometry::pair_for).
  const ProfilePair& pair = pg.pair_for(side);
  const WheelPoseOf<T> pose = wheel_pose_in_rail_frame<T>(pair, side, T(ws.q(1) - rail.lateral_m),
                                                          T(ws.q(2) - rail.vertical_m), ws.q(3));
  ContactPointGeometry<T> g;
  g.point_I.setZero();
  g.nu_I = Vec3<T>(T(0), T(0), T(1));
  g.rolling_radius_m = g.A_per_m = g.B_per_m = g.contact_angle_rad = T(0);
  const ContactTable& table = pg.table_for(side);
  g.weight = T(0);
  if (slot >= table.slots()) {  // the other wheel's table has more slots: no contact here
    g.penetration_m = T(-1);
    return g;
  }
  const T gap = table.vertical_gap<T>(slot, pose);
  g.penetration_m = -gap;  // (the vertical overlap: its sign is all that is used out of contact)
  if (value_of(gap) >= 0.0) return g;
  const TableContact<T> c = table.evaluate<T>(slot, pose);
  g.weight = c.interior_weight;
  if (value_of(g.weight) <= 0.0) return g;
  const T shared = shared_overlap_m(table, pose, slot, gap);
  if (value_of(shared) >= -value_of(gap)) {  // wholly the neighbour's
    g.weight = T(0);
    return g;
  }
  const T alpha = c.wheel_slope_rad;  // gamma - s phi: the normal's angle in I
  g.nu_I = Vec3<T>(T(0), T(-s) * sin(alpha), cos(alpha));
  g.penetration_m = -(gap + shared) * cos(c.contact_angle_rad);
  g.rolling_radius_m = c.rolling_radius_m;
  const T eta = s * (pair.wheel_offset_y_m + c.wheel_u_m);
  g.point_I = Vec3<T>(T(0), eta, -c.rolling_radius_m) - T(0.5) * g.penetration_m * g.nu_I;
  g.A_per_m = c.A_per_m;
  g.B_per_m = c.B_per_m;
  g.contact_angle_rad = alpha;
  return g;
}

}  // namespace wheel_rail_detail

// Normal and creep forces at one contact point of the wheel on `side`.
template <class T, class S>
WheelContact<T> contact_point_forces(const ModelContactTpl<S>& contact, const BodyMotion<T>& ws,
                                     int side, int slot, double speed_m_per_s,
                                     const ContactPointGeometry<T>& g) {
  using std::pow;
  const ContactSpec& spec = contact.spec;
  WheelContact<T> out;
  out.side = side;
  out.slot = slot;
  out.penetration_m = g.penetration_m;
  out.force_I.setZero();
  out.moment_I.setZero();
  out.point_I.setZero();
  T& elastic_N = out.elastic_normal_force_N;
  elastic_N = T(0);  // (an AutoDiffScalar's T{} leaves the value unset)
  out.normal_force_N = T(0);
  out.unclipped_normal_force_N = T(0);
  out.rolling_radius_m = g.rolling_radius_m;
  out.contact_angle_rad = g.contact_angle_rad;
  out.point_I = g.point_I;
  const bool in_contact = value_of(g.penetration_m) > 0.0 && value_of(g.weight) > 0.0;
  if (spec.normal != NormalForceKind::prescribed && !in_contact) return out;
  const Vec3<T>& nu_I = g.nu_I;
  const Vec3<T> l_I(T(1), T(0), T(0));
  const Vec3<T> t_I = nu_I.cross(l_I);

  // Normal force and contact ellipse.
  const bool needs_hertz = spec.normal == NormalForceKind::hertz ||
                           spec.tangential == TangentialForceKind::kalker_hertz;
  HertzShape<T> shape{};
  if (needs_hertz) {
    const T B = uses_contact_table(spec.geometry)
                    ? creep_detail::smooth_max(g.B_per_m, T(kMinimumTransverseCurvature_per_m),
                                               kTransverseCurvatureFloorWidth_per_m)
                    : g.B_per_m;
    shape = hertz_shape(g.A_per_m, B, contact.materials.effective_modulus_Pa);
  }
  // Velocity of the wheel material at P (the rail is at rest): the slip
  // velocity of the creepages, and along -nu the penetration rate. Only
  // when creep or contact damping needs it.
  Vec3<T> v_slip_I = Vec3<T>::Zero();
  if (spec.tangential != TangentialForceKind::none || spec.normal_damping_N_s_per_m > 0.0) {
    const Mat3<T> R_IT = ws.R_TI.transpose();
    const Vec3<T> w = ws.q.template head<3>();
    const TrackFrameKinematics* dV = ws.track_speed_derivative;  // null unless differentiated in V
    const Vec3<T> w_T = seeded_vector<T>(ws.track->w_WT_T, dV ? &dV->w_WT_T : nullptr);
    const Vec3<T> v_T = seeded_vector<T>(ws.track->v_WT_T, dV ? &dV->v_WT_T : nullptr);
    const Vec3<T> v_centre_I = R_IT * (v_T + w_T.cross(w) + ws.qd.template head<3>());
    v_slip_I = v_centre_I + ws.w_B_I.cross(g.point_I);
  }
  // The normal load (Hertz plus damping, never pulling) sizes the contact
  // ellipse, so the creep coefficients go to zero with it, continuously,
  // whether the wheel lifts off or the damper unloads it. The elastic part
  // alone is kept for the contact's potential energy.
  if (spec.normal == NormalForceKind::prescribed) {
    elastic_N = T(spec.prescribed_wheel_load_N);
    out.normal_force_N = elastic_N;
  } else {
    elastic_N = g.weight * shape.stiffness * pow(g.penetration_m, 1.5);
    out.normal_force_N = elastic_N;
    out.unclipped_normal_force_N = elastic_N;
    if (spec.normal_damping_N_s_per_m > 0.0) {
      const T penetration_rate = -v_slip_I.dot(nu_I);
      out.normal_force_N += g.weight * T(spec.normal_damping_N_s_per_m) * penetration_rate;
      out.unclipped_normal_force_N = out.normal_force_N;
      if (value_of(out.normal_force_N) < 0.0) out.normal_force_N = T(0);  // never pulls
    }
  }
  out.force_I = out.normal_force_N * nu_I;
  out.moment_I = out.point_I.cross(out.force_I);
  if (spec.tangential == TangentialForceKind::none || value_of(out.normal_force_N) <= 0.0)
    return out;

  // Creepages.
  // Seeded dV/dV = 1 when the model is differentiated in the speed (the
  // body's track frame then carries its derivative).
  const T V = ws.track_speed_derivative ? seeded_scalar<T>(speed_m_per_s, 1.0) : T(speed_m_per_s);
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
    if (uses_contact_table(spec.geometry)) {
      // Kalker's coefficients at a/b inside table B.1, the same area ab.
      using std::sqrt;
      const T ab = out.semi_axis_a_m * out.semi_axis_b_m;
      const T ratio = wheel_rail_detail::kalker_ratio_in_table(
          T(out.semi_axis_a_m / out.semi_axis_b_m));
      f = kalker_coefficients(T(sqrt(T(ab * ratio))), T(sqrt(T(ab / ratio))),
                              contact.materials.shear_modulus_Pa, contact.materials.poisson_ratio);
    } else {
      f = kalker_coefficients(out.semi_axis_a_m, out.semi_axis_b_m,
                              contact.materials.shear_modulus_Pa, contact.materials.poisson_ratio);
    }
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
  out.creep_force_x_N = F.force_x_N;
  out.creep_force_y_N = F.force_y_N;
  out.spin_moment_N_m = F.spin_moment_N_m;
  const Vec3<T> tangential_I = F.force_x_N * l_I + F.force_y_N * t_I;
  out.force_I += tangential_I;
  out.moment_I += out.point_I.cross(tangential_I) + F.spin_moment_N_m * nu_I;
  return out;
}

// Contact points a wheel of this contact has: 1 for the flangeless
// geometries, the table's slots for profiles.
template <class S> int contact_points_per_wheel(const ModelContactTpl<S>& contact) {
  if (!uses_contact_table(contact.spec.geometry)) return 1;
  const ProfileContactGeometry& pg = *contact.spec.profile_geometry;
  return std::max(pg.table_for(+1).slots(), pg.table_for(-1).slots());
}

// Lowest vertical gap of the left wheel of a centred, unrolled wheelset whose
// centre is at height z_m (profiles: over the table's slots; > 0: the wheel
// floats). The flangeless geometries touch at z = r0: r0 - z_m. An
// asymmetric wheelset: the larger of its two wheels' gaps (the smaller
// wheel floats by the radius difference; lowering by it puts both wheels on
// their rails, so an equilibrium solve starts with both in contact).
inline double centred_wheel_gap_m(const ModelContact& contact, double z_m) {
  if (!uses_contact_table(contact.spec.geometry))
    return z_m - contact.spec.nominal_rolling_radius_m;
  const ProfileContactGeometry& pg = *contact.spec.profile_geometry;
  auto gap = [&](int side) {
    const WheelPoseOf<double> pose =
        wheel_pose_in_rail_frame<double>(pg.pair_for(side), side, 0.0, z_m, 0.0);
    return pg.table_for(side).lowest_vertical_gap(pose);
  };
  return pg.asymmetric() ? std::max(gap(+1), gap(-1)) : gap(+1);
}

// Contact point `slot` of the wheel on `side`: geometry, then forces. Out of
// contact the forces are zero and penetration_m <= 0 (profiles: minus the
// vertical gap).
template <class T, class S>
WheelContact<T> evaluate_wheel_contact(const ModelContactTpl<S>& contact, const BodyMotion<T>& ws,
                                       int side, double speed_m_per_s, int slot = 0) {
  ContactPointGeometry<T> g;
  switch (contact.spec.geometry) {
    case ContactGeometryKind::knife_edge_cone:
      g = wheel_rail_detail::knife_edge_geometry(contact, ws, side);
      break;
    case ContactGeometryKind::linear_conicity:
      g = wheel_rail_detail::linear_conicity_geometry(contact, ws, side);
      break;
    case ContactGeometryKind::profiles:
    case ContactGeometryKind::table:
      g = wheel_rail_detail::profile_slot_geometry(contact, ws, side, slot);
      break;
  }
  return contact_point_forces(contact, ws, side, slot, speed_m_per_s, g);
}

}  // namespace railstab
