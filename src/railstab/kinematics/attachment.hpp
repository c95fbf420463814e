#pragma once
// Where a force element is attached: a body's attachment frame or a track
// frame (which moves along the track at V and takes no reaction).
#include <railstab/kinematics/body_motion.hpp>

namespace railstab {

template <class T> struct Attachment {
  BodyMotion<T>* body = nullptr;  // nullptr: a track frame
  Mat3<T> R_WF;                   // orientation of the attachment frame
  Vec3<T> origin_W, origin_v_W, w_W;  // origin position/velocity, angular velocity

  PointMotion<T> point(const Eigen::Vector3d& point_F) const {
    PointMotion<T> pm;
    pm.arm_W = R_WF * to_scalar<T>(point_F);
    pm.p_W = origin_W + pm.arm_W;
    pm.v_W = origin_v_W + w_W.cross(pm.arm_W);
    return pm;
  }
  void apply_force(const Vec3<T>& arm_W, const Vec3<T>& force_W) const {
    if (body) apply_force_at(*body, arm_W, force_W);
  }
  void apply_moment(const Vec3<T>& moment_W) const {
    if (body) body->moment_W += moment_W;
  }
};

template <class T> Attachment<T> attachment_of(BodyMotion<T>& m) {
  return Attachment<T>{&m, m.R_WF, m.p_W, m.v_W, m.w_F_W};
}

// `dV`: d/dV of the frame's rates (BodyMotion::track_speed_derivative), or null.
template <class T>
Attachment<T> attachment_of(const TrackFrameKinematics& k, const TrackFrameKinematics* dV = nullptr) {
  Attachment<T> a;
  a.body = nullptr;
  a.R_WF = k.R_WT.template cast<T>();
  a.origin_W = to_scalar<T>(k.geometry.p_WT_W);
  const Eigen::Vector3d dv_W = dV ? Eigen::Vector3d(k.R_WT * dV->v_WT_T) : Eigen::Vector3d::Zero();
  const Eigen::Vector3d dw_W = dV ? Eigen::Vector3d(k.R_WT * dV->w_WT_T) : Eigen::Vector3d::Zero();
  a.origin_v_W = seeded_vector<T>(Eigen::Vector3d(k.R_WT * k.v_WT_T), dV ? &dv_W : nullptr);
  a.w_W = seeded_vector<T>(Eigen::Vector3d(k.R_WT * k.w_WT_T), dV ? &dw_W : nullptr);
  return a;
}

}  // namespace railstab
