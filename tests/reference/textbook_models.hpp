#pragma once
// Closed-form (textbook) linear lateral dynamics of a wheelset and of a
// two-axle bogie, as oracles for railstab's general nonlinear model. Nothing
// here uses railstab's model code: only the scene data (scene/scene_spec.hpp)
// is read, and Eigen does the linear algebra.
//
// Form: Wickens, Fundamentals of Rail Vehicle Dynamics: Guidance and
// Stability (2003), ch. 2 (the wheelset: Klingel's kinematic oscillation, the
// wheelset with lateral and yaw restraint and its critical speed) and ch. 3
// (the two-axle bogie with primary lateral and yaw stiffness); the same
// models in Iwnicki (ed.), Handbook of Railway Vehicle Dynamics, chapter on
// stability (Klingel / Wickens wheelset, rigid bogie with primary springs).
// As there: tangent track, constant speed V, linear creep (f11 longitudinal,
// f22 lateral, no spin creep), linear conicity, no gravitational stiffness,
// no flange contact. The derivation below is self-contained.
//
// 1. Wheelset (mass m, yaw inertia Jz), free in lateral y and yaw psi; x,
//    bounce, roll frozen; spin prescribed at Omega = V/r0. Wheel s = +1 left,
//    -1 right. Contact point in the non-spinning frame I (rotated by psi):
//    rho_s = (0, s e0, -r_s), r_s = r0 + s lambda y. Centre velocity in I:
//    (V cos psi + y' sin psi, -V sin psi + y' cos psi, 0); angular velocity
//    (0, Omega, psi'). Slip v + w x rho along l = x_I and t = y_I:
//      v_x,s = V cos psi + y' sin psi - Omega r_s - s e0 psi'
//            = -s (V lambda y / r0 + e0 psi')              + O(2)
//      v_y   = y' cos psi - V sin psi = y' - V psi          + O(2)
//    xi_x,s = -s (lambda y / r0 + e0 psi'/V),  xi_y = y'/V - psi.
//    Forces on wheel s: Fx,s = -f11 xi_x,s, Fy,s = -f22 xi_y, N along the track
//    normal (no lateral component: no gravitational stiffness; its moment
//    s e0 N is about x only). Resultants to first order (sum_s Fx,s = 0, so
//    its lateral projection psi sum Fx,s is second order):
//      lateral  Fy = -2 f22 (y'/V - psi)
//      yaw      Mz = sum_s (rho_s x F_s).z = sum_s (-s e0 Fx,s)
//                  = -2 f11 e0 lambda y / r0 - 2 f11 e0^2 psi' / V.
//    The spin's gyroscopic moment Omega psi' (Jy - Jz) acts about x (roll is
//    frozen) and the yaw equation is Jz psi'' = Mz + suspension.
//
// 2. Springs (spring_damper_3d; kx, ky along body 1's axes; the two points
//    coincide at the nominal position, so no free-length preload). A body
//    point (px, py) (longitudinal from the CM, lateral) moves by
//    (-py psi, y + px psi); the deflection d = p2 - p1 is first order, so the
//    rotation of its components into body 1's axes and the extra moment d x f
//    on body 1 are second order. Body 1 receives +K d at point 1, body 2 -K d
//    at point 2; a force F at (px, py) is the generalised force
//    (Fy, px Fy - py Fx) on (y, psi).
//    - To the track at (0, +-b): Fy = -ky y, Mz = -kx b^2 psi per spring, so
//      K_y = sum ky = 2 ky, K_psi = sum kx b^2 = 2 kx b^2.
//    - Primary, wheelset i at (0, +-b) to the frame at (a_i, +-b), a_i the
//      wheelset's longitudinal position from the frame CM:
//      u_i = y_f + a_i psi_f - y_i, theta_i = psi_i - psi_f;
//      on wheelset i  Fy =  K_y,i u_i,  Mz = -K_psi,i theta_i,
//      on the frame   Fy = -K_y,i u_i,  Mz = -a_i K_y,i u_i + K_psi,i theta_i,
//      K_y,i = sum ky, K_psi,i = sum kx b^2 (dampers alike: C_y,i, C_psi,i).
//
// 3. Restrained wheelset, q = [y, psi]:  M q'' + C q' + K q = 0 with
//      M = diag(m, Jz),  C = diag(2 f22 / V + C_y, 2 f11 e0^2 / V + C_psi),
//      K = [ K_y                   -2 f22 ]
//          [ 2 f11 lambda e0 / r0   K_psi ]
//    (m y'' + 2f22/V y' + K_y y - 2 f22 psi = 0,
//     Jz psi'' + 2 f11 e0^2/V psi' + K_psi psi + 2 f11 lambda e0/r0 y = 0.)
//    With K_y = K_psi = 0 this is Klingel's kinematic wheelset (wavelength
//    2 pi sqrt(r0 e0 / lambda) in the creep-dominated limit).
//
// 4. Characteristic polynomial and critical speed (undamped suspension):
//    det(M s^2 + C s + K) = a4 s^4 + a3 s^3 + a2 s^2 + a1 s + a0 with
//      Cy = 2 f22, Cp = 2 f11 e0^2, kc = 2 f11 lambda e0 / r0,
//      a4 = m Jz,  a3 = alpha / V,  a2 = beta + gamma / V^2,  a1 = delta / V,
//      a0 = eps,
//      alpha = m Cp + Jz Cy,  beta = m K_psi + Jz K_y,  gamma = Cy Cp,
//      delta = Cy K_psi + Cp K_y,  eps = K_y K_psi + 2 f22 kc.
//    All a_k > 0; Routh-Hurwitz for a quartic leaves
//      Delta3 = a3 a2 a1 - a4 a1^2 - a3^2 a0 > 0, i.e. (times V^2)
//      alpha delta gamma / V^2 > alpha^2 eps + a4 delta^2 - alpha beta delta
//                              = 2 f22 kc alpha^2 - gamma (m K_psi - Jz K_y)^2 =: D
//    (the identity follows from expanding with p = m Cp, q = Jz Cy: the
//    uncoupled part is -p q (m K_psi - Jz K_y)^2 / (m Jz)). Hence
//      V_crit^2 = alpha delta gamma / D        (stable for all V if D <= 0),
//    and at the crossing s = i w: Im = -a3 w^3 + a1 w = 0, so
//      w_crit^2 = a1 / a3 = delta / alpha
//              = (Cy K_psi + Cp K_y) / (m Cp + Jz Cy)   (independent of V);
//    Re = a4 w^4 - a2 w^2 + a0 = 0 is then equivalent to Delta3 = 0.
//
// 5. Bogie: wheelsets 1, 2 and frame f (mass m_f, yaw inertia J_f), each
//    free in y and yaw, primary springs as in 2, frame otherwise free.
//    q = [y1, psi1, y2, psi2, y_f, psi_f]:
//      M = diag(m, Jz, m, Jz, m_f, J_f),
//      C = (1/V) diag(Cy, Cp, Cy, Cp, 0, 0) + C_susp,
//      K = K_creep + K_susp, K_creep[y_i, psi_i] = -2 f22,
//          K_creep[psi_i, y_i] = kc (non-symmetric: circulatory),
//      K_susp = sum_i Du_i^T K_y,i Du_i + Dt_i^T K_psi,i Dt_i
//          with u_i = Du_i q, theta_i = Dt_i q (section 2), i.e.
//          [y_i, y_i] = K_y,i, [y_i, y_f] = -K_y,i, [y_i, psi_f] = -a_i K_y,i,
//          [psi_i, psi_i] = K_psi,i, [psi_i, psi_f] = -K_psi,i,
//          [y_f, y_f] = sum K_y,i, [y_f, psi_f] = sum a_i K_y,i,
//          [psi_f, psi_f] = sum (a_i^2 K_y,i + K_psi,i), symmetric;
//      C_susp the same with C_y,i, C_psi,i.
//    Characteristic polynomial P(s, V) = det(M s^2 + C(V) s + K) (degree 12);
//    its roots are the eigenvalues of the first-order matrix
//      A(V) = [[0, I], [-M^-1 K, -M^-1 C(V)]],  x = [q; q'],
//    and V_crit is the first V where the largest real part of the roots
//    crosses zero (found by bisection: no closed form for degree 12). With
//    C = C~ / V, a crossing root s = i w satisfies det(K - w^2 M + i (w/V) C~) = 0.
//
// Shipped scenes: textbook_wheelset V_crit = 73.10524 m/s, w = 39.49116 rad/s
// (6.28521 Hz); textbook_bogie V_crit = 102.45983 m/s, w = 32.60823 rad/s
// (5.18976 Hz).
#include <railstab/scene/scene_spec.hpp>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <functional>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace railstab::textbook {

// One wheelset with the textbook contact.
struct CreepWheelset {
  std::string body;  // scene body name
  double mass_kg = 0.0;
  double yaw_inertia_kg_m2 = 0.0;  // Jz
  double conicity = 0.0;           // lambda
  double e0_m = 0.0;               // half contact distance
  double r0_m = 0.0;               // nominal rolling radius
  double f11_N = 0.0, f22_N = 0.0;
  double creep_lateral_damping() const { return 2.0 * f22_N; }         // Cy (x 1/V)
  double creep_yaw_damping() const { return 2.0 * f11_N * e0_m * e0_m; }  // Cp (x 1/V)
  double creep_yaw_coupling() const { return 2.0 * f11_N * conicity * e0_m / r0_m; }  // kc
};

// Lateral and yaw restraint (totals over the springs of one link).
struct Restraint {
  double ky_N_per_m = 0.0, kpsi_N_m_per_rad = 0.0;
  double cy_N_s_per_m = 0.0, cpsi_N_m_s_per_rad = 0.0;
};

struct RestrainedWheelset {
  CreepWheelset ws;
  Restraint to_track;
};

struct Bogie {
  std::array<CreepWheelset, 2> ws;
  std::array<Restraint, 2> primary;
  std::array<double, 2> a_m{};  // wheelset position ahead of the frame CM
  std::string frame_body;
  double frame_mass_kg = 0.0, frame_yaw_inertia_kg_m2 = 0.0;
};

struct SecondOrderModel {
  Eigen::MatrixXd M, C, K;
};

// A = [[0, I], [-M^-1 K, -M^-1 C]] for x = [q; q'].
inline Eigen::MatrixXd first_order_state_matrix(const SecondOrderModel& s) {
  const Eigen::Index n = s.M.rows();
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  A.topRightCorner(n, n).setIdentity();
  const Eigen::MatrixXd Minv = s.M.inverse();  // diagonal here
  A.bottomLeftCorner(n, n) = -Minv * s.K;
  A.bottomRightCorner(n, n) = -Minv * s.C;
  return A;
}

// --- Restrained wheelset (sections 3-4) -----------------------------------------
inline SecondOrderModel restrained_wheelset_matrices(const RestrainedWheelset& p, double V) {
  const CreepWheelset& w = p.ws;
  SecondOrderModel s;
  s.M = Eigen::Vector2d(w.mass_kg, w.yaw_inertia_kg_m2).asDiagonal();
  s.C = Eigen::Vector2d(w.creep_lateral_damping() / V + p.to_track.cy_N_s_per_m,
                        w.creep_yaw_damping() / V + p.to_track.cpsi_N_m_s_per_rad)
            .asDiagonal();
  s.K.resize(2, 2);
  s.K << p.to_track.ky_N_per_m, -2.0 * w.f22_N, w.creep_yaw_coupling(),
      p.to_track.kpsi_N_m_per_rad;
  return s;
}

inline Eigen::MatrixXd restrained_wheelset_state_matrix(const RestrainedWheelset& p, double V) {
  return first_order_state_matrix(restrained_wheelset_matrices(p, V));
}

struct WheelsetPolynomialTerms {
  double alpha, beta, gamma, delta, eps, a4;
};

inline WheelsetPolynomialTerms wheelset_polynomial_terms(const RestrainedWheelset& p) {
  if (p.to_track.cy_N_s_per_m != 0.0 || p.to_track.cpsi_N_m_s_per_rad != 0.0)
    throw std::invalid_argument("closed-form wheelset critical speed: suspension damping not 0");
  const CreepWheelset& w = p.ws;
  const double m = w.mass_kg, J = w.yaw_inertia_kg_m2;
  const double Cy = w.creep_lateral_damping(), Cp = w.creep_yaw_damping();
  const double Ky = p.to_track.ky_N_per_m, Kp = p.to_track.kpsi_N_m_per_rad;
  WheelsetPolynomialTerms t;
  t.a4 = m * J;
  t.alpha = m * Cp + J * Cy;
  t.beta = m * Kp + J * Ky;
  t.gamma = Cy * Cp;
  t.delta = Cy * Kp + Cp * Ky;
  t.eps = Ky * Kp + 2.0 * w.f22_N * w.creep_yaw_coupling();
  return t;
}

// Coefficients a4, a3, a2, a1, a0 of det(M s^2 + C s + K) (section 4).
inline std::array<double, 5> restrained_wheelset_characteristic_polynomial(
    const RestrainedWheelset& p, double V) {
  const WheelsetPolynomialTerms t = wheelset_polynomial_terms(p);
  return {t.a4, t.alpha / V, t.beta + t.gamma / (V * V), t.delta / V, t.eps};
}

struct HuntingOnset {
  double speed_m_per_s = 0.0;
  double angular_frequency_rad_per_s = 0.0;
  double frequency_Hz() const {
    return angular_frequency_rad_per_s / (2.0 * std::numbers::pi);
  }
};

// V_crit^2 = alpha delta gamma / (2 f22 kc alpha^2 - gamma (m K_psi - Jz K_y)^2),
// w_crit^2 = delta / alpha. nullopt: stable at every speed.
inline std::optional<HuntingOnset> restrained_wheelset_critical(const RestrainedWheelset& p) {
  const WheelsetPolynomialTerms t = wheelset_polynomial_terms(p);
  const CreepWheelset& w = p.ws;
  const double mismatch =
      w.mass_kg * p.to_track.kpsi_N_m_per_rad - w.yaw_inertia_kg_m2 * p.to_track.ky_N_per_m;
  const double D =
      2.0 * w.f22_N * w.creep_yaw_coupling() * t.alpha * t.alpha - t.gamma * mismatch * mismatch;
  if (!(D > 0.0) || !(t.delta > 0.0)) return std::nullopt;
  HuntingOnset h;
  h.speed_m_per_s = std::sqrt(t.alpha * t.delta * t.gamma / D);
  h.angular_frequency_rad_per_s = std::sqrt(t.delta / t.alpha);
  return h;
}

// --- Bogie (section 5) ----------------------------------------------------------
// q = [y1, psi1, y2, psi2, y_f, psi_f].
inline SecondOrderModel bogie_matrices(const Bogie& p, double V) {
  SecondOrderModel s;
  s.M = Eigen::MatrixXd::Zero(6, 6);
  s.C = Eigen::MatrixXd::Zero(6, 6);
  s.K = Eigen::MatrixXd::Zero(6, 6);
  const int yf = 4, pf = 5;
  s.M(yf, yf) = p.frame_mass_kg;
  s.M(pf, pf) = p.frame_yaw_inertia_kg_m2;
  for (int i = 0; i < 2; ++i) {
    const CreepWheelset& w = p.ws[i];
    const int yi = 2 * i, pi = 2 * i + 1;
    s.M(yi, yi) = w.mass_kg;
    s.M(pi, pi) = w.yaw_inertia_kg_m2;
    s.C(yi, yi) += w.creep_lateral_damping() / V;
    s.C(pi, pi) += w.creep_yaw_damping() / V;
    s.K(yi, pi) += -2.0 * w.f22_N;
    s.K(pi, yi) += w.creep_yaw_coupling();
    // u_i = y_f + a_i psi_f - y_i, theta_i = psi_i - psi_f.
    Eigen::Matrix<double, 1, 6> Du = Eigen::Matrix<double, 1, 6>::Zero();
    Eigen::Matrix<double, 1, 6> Dt = Eigen::Matrix<double, 1, 6>::Zero();
    Du(yf) = 1.0;
    Du(pf) = p.a_m[i];
    Du(yi) = -1.0;
    Dt(pi) = 1.0;
    Dt(pf) = -1.0;
    const Restraint& r = p.primary[i];
    s.K += r.ky_N_per_m * Du.transpose() * Du + r.kpsi_N_m_per_rad * Dt.transpose() * Dt;
    s.C += r.cy_N_s_per_m * Du.transpose() * Du + r.cpsi_N_m_s_per_rad * Dt.transpose() * Dt;
  }
  return s;
}

inline Eigen::MatrixXd bogie_state_matrix(const Bogie& p, double V) {
  return first_order_state_matrix(bogie_matrices(p, V));
}

// P(s, V) = det(M s^2 + C(V) s + K): the characteristic polynomial evaluated.
inline std::complex<double> bogie_characteristic_value(const Bogie& p, double V,
                                                       std::complex<double> s) {
  const SecondOrderModel m = bogie_matrices(p, V);
  const Eigen::MatrixXcd P = m.M.cast<std::complex<double>>() * (s * s) +
                             m.C.cast<std::complex<double>>() * s +
                             m.K.cast<std::complex<double>>();
  return P.determinant();
}

// --- Spectra and critical speeds ------------------------------------------------
// Eigenvalue with the largest real part, ignoring exact (round-off) zeros:
// |lambda| <= 1e-12 of the spectral radius.
inline std::complex<double> dominant_eigenvalue(const Eigen::MatrixXd& A) {
  const Eigen::VectorXcd ev = Eigen::EigenSolver<Eigen::MatrixXd>(A, false).eigenvalues();
  const double radius = ev.cwiseAbs().maxCoeff();
  std::complex<double> best(-std::numeric_limits<double>::infinity(), 0.0);
  for (Eigen::Index i = 0; i < ev.size(); ++i) {
    if (std::abs(ev(i)) <= 1e-12 * radius) continue;
    if (ev(i).real() > best.real() ||
        (ev(i).real() == best.real() && ev(i).imag() > best.imag()))
      best = ev(i);
  }
  return best;
}

// First speed in [v_lo, v_hi] where max Re(eig A(V)) turns positive: scan in
// `steps`, then bisect to `tol`. nullopt: no crossing in the range. The lower
// end must be stable.
inline std::optional<double> first_unstable_speed(
    const std::function<double(double)>& max_real_part, double v_lo, double v_hi,
    double tol = 1e-10, int steps = 300) {
  if (max_real_part(v_lo) >= 0.0)
    throw std::invalid_argument("first_unstable_speed: lower end not stable");
  double a = v_lo, b = v_lo;
  bool found = false;
  for (int k = 1; k <= steps; ++k) {
    b = v_lo + (v_hi - v_lo) * k / steps;
    if (max_real_part(b) >= 0.0) {
      found = true;
      break;
    }
    a = b;
  }
  if (!found) return std::nullopt;
  while (b - a > tol) {
    const double mid = 0.5 * (a + b);
    if (mid <= a || mid >= b) break;
    (max_real_part(mid) < 0.0 ? a : b) = mid;
  }
  return 0.5 * (a + b);
}

// --- Parameters from a scene ------------------------------------------------------
// Throw std::invalid_argument when the scene is outside the textbook model.
namespace detail {

inline void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("scene outside the textbook model: " + what);
}

inline const BodySpec& body_named(const SceneSpec& s, const std::string& name) {
  for (const BodySpec& b : s.bodies)
    if (b.name == name) return b;
  throw std::invalid_argument("no body '" + name + "'");
}

inline void require_free_y_yaw(const BodySpec& b) {
  const std::array<bool, 6> want = {false, true, false, false, false, true};
  require(b.free == want, b.name + " must be free in y and yaw only");
}

inline CreepWheelset creep_wheelset(const SceneSpec& s, const BodySpec& b) {
  require(b.is_wheelset, b.name + " is not a wheelset");
  require_free_y_yaw(b);
  require(b.inertia_kg_m2.x() == b.inertia_kg_m2.z(), b.name + " not axisymmetric");
  require(b.position_m.y() == 0.0, b.name + " centred laterally");
  const ContactSpec* c = nullptr;
  for (const ContactSpec& cs : s.contacts)
    if (cs.name == b.contact) c = &cs;
  require(c != nullptr, "contact of " + b.name);
  require(c->geometry == ContactGeometryKind::linear_conicity, "linear_conicity geometry");
  require(c->tangential == TangentialForceKind::constant, "constant creep coefficients");
  require(!c->spin_creepage || (c->f23_N_m == 0.0 && c->f33_N_m2 == 0.0), "no spin creep");
  require(c->normal == NormalForceKind::prescribed && c->prescribed_wheel_load_N > 0.0,
          "prescribed wheel load");
  CreepWheelset w;
  w.body = b.name;
  w.mass_kg = b.mass_kg;
  w.yaw_inertia_kg_m2 = b.inertia_kg_m2.z();
  w.conicity = c->conicity;
  w.e0_m = c->half_contact_distance_m;
  w.r0_m = c->nominal_rolling_radius_m;
  w.f11_N = c->f11_N;
  w.f22_N = c->f22_N;
  return w;
}

inline void require_tangent_track(const SceneSpec& s) {
  require(s.track.start_curvature_per_m == 0.0 && s.track.start_cant_m == 0.0,
          "straight level track");
  for (const TrackSegmentSpec& g : s.track.segments)
    require(g.kind == TrackSegmentKind::tangent && g.end_cant_m == 0.0, "tangent track only");
}

inline double longitudinal_position(const BodySpec& b) {
  return b.track_offset_m + b.position_m.x();
}

// Adds one spring between a body ("inner": wheelset, point on its axle) and
// an outer attachment at longitudinal arm `a` from the outer CM.
inline void add_link(Restraint& r, const ElementSpec& element, const Eigen::Vector3d& inner_point,
                     const Eigen::Vector3d& outer_point, double a) {
  const std::string& name = ends_of(element).name;
  const auto* spring = std::get_if<SpringDamper3d<double>>(&element);
  require(spring != nullptr, name + " is not a spring_damper_3d");
  const SpringDamper3d<double>& e = *spring;
  // z is frozen and the points may differ in height only: kz, cz and a
  // vertical free length do not enter the lateral/yaw equations.
  require(inner_point.x() == 0.0, name + ": point on the wheelset must lie on the axle (x = 0)");
  require(outer_point.x() == a, name + ": points must coincide longitudinally");
  require(outer_point.y() == inner_point.y(), name + ": points must coincide laterally");
  require(e.actuator_force_N.isZero(), name + ": no actuator force");
  const double b = inner_point.y();
  r.ky_N_per_m += e.stiffness_N_per_m.y();
  r.kpsi_N_m_per_rad += e.stiffness_N_per_m.x() * b * b;
  r.cy_N_s_per_m += e.damping_N_s_per_m.y();
  r.cpsi_N_m_s_per_rad += e.damping_N_s_per_m.x() * b * b;
}

}  // namespace detail

// Scene: one wheelset on springs to its track frame.
inline RestrainedWheelset restrained_wheelset_from_scene(const SceneSpec& s) {
  detail::require_tangent_track(s);
  detail::require(s.bodies.size() == 1, "one body");
  RestrainedWheelset p;
  p.ws = detail::creep_wheelset(s, s.bodies[0]);
  for (const ElementSpec& element : s.elements) {
    const ElementEnds& e = ends_of(element);
    detail::require(e.body1_name == kTrackBodyName || e.body2_name == kTrackBodyName,
                    e.name + " must connect the wheelset to the track");
    const bool ws_is_2 = e.body1_name == kTrackBodyName;
    detail::add_link(p.to_track, element, ws_is_2 ? e.point2_m : e.point1_m,
                     ws_is_2 ? e.point1_m : e.point2_m, s.bodies[0].position_m.x());
  }
  return p;
}

// Scene: two wheelsets and a frame, primary springs wheelset-frame only.
inline Bogie bogie_from_scene(const SceneSpec& s) {
  detail::require_tangent_track(s);
  detail::require(s.bodies.size() == 3, "three bodies");
  Bogie p;
  std::vector<const BodySpec*> wheelsets;
  const BodySpec* frame = nullptr;
  for (const BodySpec& b : s.bodies) {
    if (b.is_wheelset)
      wheelsets.push_back(&b);
    else
      frame = &b;
  }
  detail::require(wheelsets.size() == 2 && frame != nullptr, "two wheelsets and a frame");
  detail::require_free_y_yaw(*frame);
  detail::require(frame->position_m.y() == 0.0, frame->name + " centred laterally");
  p.frame_body = frame->name;
  p.frame_mass_kg = frame->mass_kg;
  p.frame_yaw_inertia_kg_m2 = frame->inertia_kg_m2.z();
  for (int i = 0; i < 2; ++i) {
    p.ws[i] = detail::creep_wheelset(s, *wheelsets[i]);
    p.a_m[i] = detail::longitudinal_position(*wheelsets[i]) - detail::longitudinal_position(*frame);
  }
  for (const ElementSpec& element : s.elements) {
    const ElementEnds& e = ends_of(element);
    int i = -1;
    bool ws_is_1 = true;
    for (int k = 0; k < 2; ++k) {
      if (e.body1_name == p.ws[k].body && e.body2_name == frame->name) i = k, ws_is_1 = true;
      if (e.body2_name == p.ws[k].body && e.body1_name == frame->name) i = k, ws_is_1 = false;
    }
    detail::require(i >= 0, e.name + " must connect a wheelset to the frame");
    const Eigen::Vector3d ws_point = ws_is_1 ? e.point1_m : e.point2_m;
    const Eigen::Vector3d frame_point = ws_is_1 ? e.point2_m : e.point1_m;
    detail::require(wheelsets[i]->position_m.x() == 0.0 && frame->position_m.x() == 0.0,
                    "CMs at their track frames' origins (x = 0)");
    detail::add_link(p.primary[i], element, ws_point, frame_point, p.a_m[i]);
  }
  return p;
}

}  // namespace railstab::textbook
