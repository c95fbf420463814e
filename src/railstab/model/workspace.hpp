#pragma once
// The workspace of model evaluations (Pinocchio's "Data"): everything one
// right-hand-side evaluation writes, sized once for a model and reused, so
// an evaluation does not allocate. One workspace per thread and scalar type.
#include <railstab/kinematics/body_motion.hpp>
#include <railstab/model/model.hpp>

#include <cmath>
#include <vector>

namespace railstab {

template <class T> struct Workspace {
  // Track frames of every body at (t, V0): they depend on time and speed only
  // (and the model's speed rate, fixed for a model),
  // so they are recomputed when those change.
  std::vector<TrackFrameKinematics> frames;
  // d/dV of `frames` when the model is differentiated in the speed
  // (ModelTpl::differentiated_in_speed), else empty. At constant speed the
  // frame's velocities are V times their values at unit speed and its
  // accelerations V^2 times theirs (Track::frame_at), so
  //   d(v, w)/dV = (v, w)(V = 1),   d(a, alpha)/dV = 2 V (a, alpha)(V = 1).
  std::vector<TrackFrameKinematics> frames_speed_derivative;
  double frames_time_s = NAN, frames_speed_m_per_s = NAN;
  std::vector<BodyMotion<T>> motions;

  Workspace() = default;
  template <class S> explicit Workspace(const ModelTpl<S>& model) { resize(model); }
  template <class S> void resize(const ModelTpl<S>& model) {
    frames.resize(model.bodies.size());
    motions.resize(model.bodies.size());
    frames_time_s = NAN;
  }
  template <class S> void update_frames(const ModelTpl<S>& model, double t_s, double speed_m_per_s) {
    if (frames.size() != model.bodies.size()) resize(model);
    if (t_s == frames_time_s && speed_m_per_s == frames_speed_m_per_s &&
        frames_speed_derivative.size() == (model.differentiated_in_speed ? frames.size() : 0))
      return;
    for (size_t b = 0; b < model.bodies.size(); ++b)
      frames[b] = model.track.frame_at(model.arc_length_of(int(b), t_s, speed_m_per_s),
                                       model.speed_at(t_s, speed_m_per_s),
                                       model.speed_rate_m_per_s2);
    frames_speed_derivative.clear();
    if (model.differentiated_in_speed) {
      frames_speed_derivative.resize(frames.size());
      for (size_t b = 0; b < model.bodies.size(); ++b) {
        const double s = model.arc_length_of(int(b), t_s, speed_m_per_s);
        const TrackFrameKinematics unit = model.track.frame_at(s, 1.0, 0.0);
        TrackFrameKinematics& d = frames_speed_derivative[b];
        d.v_WT_T = unit.v_WT_T;
        d.w_WT_T = unit.w_WT_T;
        d.a_WT_T = 2.0 * speed_m_per_s * unit.a_WT_T;
        d.alpha_WT_T = 2.0 * speed_m_per_s * unit.alpha_WT_T;
      }
    }
    frames_time_s = t_s;
    frames_speed_m_per_s = speed_m_per_s;
  }
};

}  // namespace railstab
