#pragma once
// Kinematics of one body relative to its moving track frame, and the
// Newton-Euler equations that turn applied forces into coordinate
// accelerations. Templated on the scalar (double / AdScalar).
//
// Position (thesis 2.6): r_W = p_WT + A w,   orientation R_WB = A Bz Bx By.
// Velocity of the CM in W:  v_W = A (v_T + w_T x w + dw/dt)
//   (v_T, w_T: velocity and angular velocity of the track frame, in T).
// I = Bz Bx is the intermediate frame (thesis 4.40). Relative angular velocity
// of the body w.r.t. T, in I components, for angles (roll, pitch, yaw):
//   w_rel_I = G(roll) [roll', pitch', yaw']  with  G = [[1,0,0],[0,1,s],[0,0,c]],
//   s = sin roll, c = cos roll;  w_body_I = R_TI^T w_T + w_rel_I.
//
// Equations of motion: Newton-Euler in the moving frame, projected on the free
// coordinates (d'Alembert). This is equivalent to the thesis' Lagrange
// equations (4.36)-(4.38) for the same coordinates: the Lagrange equations are
// the same balance multiplied by the velocity Jacobians (G for rotations,
// A for translations); we solve for accelerations directly because the
// translational mass matrix is diagonal and the rotational one is 3x3.
//  translation (in T):
//    w'' = F_T/m - a_T - 2 w_T x w' - w_T x (w_T x w) - alpha_T x w
//  rotation (in I; J_I = By J By^T, constant for an axisymmetric wheelset):
//    J_I G q_r'' = M_I - w x J_I w + pitch' J_I (y x w)
//                  - J_I (h - w_rel_zx x w_T_I + R_TI^T alpha_T)
//    h = (0, c roll' yaw', -s roll' yaw'), w_rel_zx = G [roll', 0, yaw'].
//  Projection: q_r'' = (G_f^T J_I G_f)^-1 [G_f^T (rhs without M) + G_f^T M_spin
//  + G_frame^T M_frame]; G_frame = G_f except that for a wheelset the spin
//  column is zero (the axle boxes do not spin: their moments do no work on it).
//  For an axisymmetric wheelset nothing depends on the spin angle (pitch),
//  so linearisation sees an exactly zero Jacobian column (ERRATA 11a).
#include <railstab/bodies/body.hpp>
#include <railstab/core/coordinates.hpp>
#include <railstab/core/scalar.hpp>
#include <railstab/frames/rotations.hpp>
#include <railstab/track/track.hpp>

namespace railstab {

template <class T> struct BodyMotion {
  Eigen::Matrix<T, 6, 1> q, qd;  // all six coordinates and rates
  const TrackFrameKinematics* track = nullptr;
  // d/dV of the track frame's velocities and accelerations (its pose does
  // not depend on V at a given arc length), when the model is
  // differentiated in the speed (ModelTpl::differentiated_in_speed): they
  // enter T's Dual direction. Null otherwise.
  const TrackFrameKinematics* track_speed_derivative = nullptr;
  Mat3<T> R_WT, R_TI, R_IB, R_WI;
  Vec3<T> p_W, v_W;             // CM position and velocity in W
  Vec3<T> w_TI_I;               // relative rate of I w.r.t. T, in I (no spin)
  Vec3<T> w_I_I;                // angular velocity of frame I in W, in I
  Vec3<T> w_B_I;                // angular velocity of the body in W, in I
  // Attachment frame F: I for a wheelset (axle boxes do not spin), B otherwise.
  Mat3<T> R_WF;
  Vec3<T> w_F_W;                // angular velocity of F, in W
  // Accumulated applied forces: force in W, moments about the CM in W.
  // moment_W acts on the attachment frame F; for a wheelset that is the
  // non-spinning axle-box frame I, whose bearings pass no torque about the
  // axle, so it does no work on the spin. spinning_moment_W acts on the
  // rotating wheelset itself (wheel-rail contact). For other bodies both act
  // on the body alike.
  Vec3<T> force_W, moment_W, spinning_moment_W;
};

template <class T, class S>
void compute_body_motion(const BodyTpl<S>& body, const TrackFrameKinematics& track,
                         const Eigen::Matrix<T, 6, 1>& q, const Eigen::Matrix<T, 6, 1>& qd,
                         BodyMotion<T>& m, const TrackFrameKinematics* track_speed_derivative = nullptr) {
  using std::cos;
  using std::sin;
  m.q = q;
  m.qd = qd;
  m.track = &track;
  m.track_speed_derivative = track_speed_derivative;
  const TrackFrameKinematics* dV = track_speed_derivative;
  m.R_WT = track.R_WT.template cast<T>();
  const Vec3<T> w_T = seeded_vector<T>(track.w_WT_T, dV ? &dV->w_WT_T : nullptr);
  const Vec3<T> v_T = seeded_vector<T>(track.v_WT_T, dV ? &dV->v_WT_T : nullptr);
  const Vec3<T> w = q.template head<3>();
  const Vec3<T> wd = qd.template head<3>();
  const T roll = q(3), pitch = q(4), yaw = q(5);
  m.R_TI = rot_z(yaw) * rot_x(roll);
  m.R_IB = rot_y(pitch);
  m.R_WI = m.R_WT * m.R_TI;
  m.p_W = to_scalar<T>(track.geometry.p_WT_W) + m.R_WT * w;
  m.v_W = m.R_WT * (v_T + w_T.cross(w) + wd);
  const T s = sin(roll), c = cos(roll);
  m.w_TI_I = Vec3<T>(qd(3), s * qd(5), c * qd(5));
  m.w_I_I = m.R_TI.transpose() * w_T + m.w_TI_I;
  m.w_B_I = m.w_I_I + Vec3<T>(T(0), qd(4), T(0));
  if (attached_in_spinning_frame(body.kind)) {
    m.R_WF = m.R_WI * m.R_IB;
    m.w_F_W = m.R_WI * m.w_B_I;
  } else {
    m.R_WF = m.R_WI;
    m.w_F_W = m.R_WI * m.w_I_I;
  }
  m.force_W.setZero();
  m.moment_W.setZero();
  m.spinning_moment_W.setZero();
}

// Position and velocity (in W) of a point fixed in the body's attachment frame.
template <class T> struct PointMotion {
  Vec3<T> p_W, v_W, arm_W;  // arm: from the CM to the point
};

template <class T>
void apply_force_at(BodyMotion<T>& m, const Vec3<T>& arm_W, const Vec3<T>& force_W) {
  m.force_W += force_W;
  m.moment_W += arm_W.cross(force_W);
}

// Solves the leading n x n block (n = 1, 2, 3) of M x = b by cofactors, so
// every operation propagates AD derivatives.
template <class T> Vec3<T> solve_small_spd(const Mat3<T>& M, const Vec3<T>& b, int n) {
  Vec3<T> x = Vec3<T>::Zero();
  if (n == 1) {
    x(0) = b(0) / M(0, 0);
  } else if (n == 2) {
    const T det = M(0, 0) * M(1, 1) - M(0, 1) * M(1, 0);
    x(0) = (M(1, 1) * b(0) - M(0, 1) * b(1)) / det;
    x(1) = (M(0, 0) * b(1) - M(1, 0) * b(0)) / det;
  } else {
    x = M.inverse() * b;  // fixed-size 3x3: explicit cofactor inverse
  }
  return x;
}

// Accelerations of the six coordinates (entries of frozen coordinates are
// left at zero: their motion is prescribed).
template <class T, class S>
Eigen::Matrix<T, 6, 1> body_accelerations(const BodyTpl<S>& body, const BodyMotion<T>& m) {
  using std::cos;
  using std::sin;
  const TrackFrameKinematics& k = *m.track;
  const TrackFrameKinematics* dV = m.track_speed_derivative;
  const Vec3<T> w_T = seeded_vector<T>(k.w_WT_T, dV ? &dV->w_WT_T : nullptr);
  const Vec3<T> alpha_T = seeded_vector<T>(k.alpha_WT_T, dV ? &dV->alpha_WT_T : nullptr);
  const Vec3<T> a_T = seeded_vector<T>(k.a_WT_T, dV ? &dV->a_WT_T : nullptr);
  const Vec3<T> w = m.q.template head<3>();
  const Vec3<T> wd = m.qd.template head<3>();
  Eigen::Matrix<T, 6, 1> acc = Eigen::Matrix<T, 6, 1>::Zero();

  // Translation, in T.
  const Vec3<T> force_T = m.R_WT.transpose() * m.force_W;
  const Vec3<T> wdd = force_T / lift<T>(body.mass_kg) - a_T - T(2) * w_T.cross(wd) -
                      w_T.cross(w_T.cross(w)) - alpha_T.cross(w);
  for (int i = 0; i < 3; ++i)
    if (body.state_index[i] >= 0) acc(i) = wdd(i);

  // Rotation, in I.
  int n_free_rot = 0;
  std::array<int, 3> free_rot{};
  for (int i = 3; i < 6; ++i)
    if (body.state_index[i] >= 0) free_rot[n_free_rot++] = i;
  if (n_free_rot == 0) return acc;

  const T roll = m.q(3), pitch = m.q(4);
  const T s = sin(roll), c = cos(roll);
  Mat3<T> J_I;
  const Mat3<T> J_B = lift<T>(body.inertia_kg_m2).asDiagonal();
  const bool spinning_attachment = attached_in_spinning_frame(body.kind);
  if (spinning_attachment) {
    const Mat3<T> R_IB = rot_y(pitch);
    J_I = R_IB * J_B * R_IB.transpose();
  } else {
    J_I = J_B;  // wheelset: axisymmetric (validated Jx = Jz), independent of the spin angle
  }
  const Vec3<T> frame_moment_I = m.R_WI.transpose() * m.moment_W;
  const Vec3<T> spinning_moment_I = m.R_WI.transpose() * m.spinning_moment_W;
  const Vec3<T> y_hat(T(0), T(1), T(0));
  const Vec3<T>& wb = m.w_B_I;
  const Vec3<T> w_T_I = m.R_TI.transpose() * w_T;
  const Vec3<T> w_rel_zx(m.qd(3), s * m.qd(5), c * m.qd(5));
  const Vec3<T> h(T(0), c * m.qd(3) * m.qd(5), -s * m.qd(3) * m.qd(5));
  const Vec3<T> rhs_I = spinning_moment_I - wb.cross(J_I * wb) + m.qd(4) * (J_I * y_hat.cross(wb)) -
                        J_I * (h - w_rel_zx.cross(w_T_I) + m.R_TI.transpose() * alpha_T);
  // G columns for roll, pitch, yaw.
  Mat3<T> G;
  G << T(1), T(0), T(0), T(0), T(1), s, T(0), T(0), c;
  // Generalised mass G_f^T J G_f (1x1 .. 3x3) inverted by cofactors. Not an
  // LU solve: Eigen's triangular solver skips dividing an entry whose *value*
  // is zero, which for AutoDiffScalar drops the derivatives' division (the
  // AD Jacobian at an exact equilibrium came out Jz times too large).
  Mat3<T> G_free = Mat3<T>::Zero();
  for (int j = 0; j < n_free_rot; ++j) G_free.col(j) = G.col(free_rot[j] - 3);
  const Mat3<T> mass = G_free.transpose() * J_I * G_free;  // zero outside n x n
  // The frame moment works through the frame's own rotation: for a wheelset
  // the spin column is absent from it.
  Mat3<T> G_frame = G_free;
  if (!spinning_attachment)
    for (int j = 0; j < n_free_rot; ++j)
      if (free_rot[j] == int(CoordinateIndex::pitch)) G_frame.col(j).setZero();
  const Vec3<T> gen_force = G_free.transpose() * rhs_I + G_frame.transpose() * frame_moment_I;
  const Vec3<T> qdd = solve_small_spd(mass, gen_force, n_free_rot);
  for (int j = 0; j < n_free_rot; ++j) acc(free_rot[j]) = qdd(j);
  return acc;
}

}  // namespace railstab
