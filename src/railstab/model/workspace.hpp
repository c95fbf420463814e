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
    if (t_s == frames_time_s && speed_m_per_s == frames_speed_m_per_s) return;
    for (size_t b = 0; b < model.bodies.size(); ++b)
      frames[b] = model.track.frame_at(model.arc_length_of(int(b), t_s, speed_m_per_s),
                                       model.speed_at(t_s, speed_m_per_s),
                                       model.speed_rate_m_per_s2);
    frames_time_s = t_s;
    frames_speed_m_per_s = speed_m_per_s;
  }
};

}  // namespace railstab
