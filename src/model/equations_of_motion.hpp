#pragma once
// The right-hand side of the model, dx/dt = f(t, x), one templated code path
// for simulation (double) and linearisation (AdScalar). Instantiated for both
// in equations_of_motion.cpp only (other files see the extern declarations).
#include "contact/wheel_rail.hpp"
#include "model/model.hpp"

#include <vector>

namespace railstab {

// Per-wheel contact results of one evaluation (double), for reports.
struct ContactSnapshot {
  int body = 0;
  WheelContact<double> wheel;
};

// Optional outputs of one evaluation.
struct EvaluationDetails {
  std::vector<ContactSnapshot> contacts;
};

// Track frames of every body at time t (double: they depend on t only).
std::vector<TrackFrameKinematics> track_frames_at(const Model& model, double t_s);

// dx/dt at time t. `frames` must come from track_frames_at(model, t_s).
template <class T>
void evaluate_rhs(const Model& model, double t_s, const std::vector<TrackFrameKinematics>& frames,
                  const VecX<T>& x, VecX<T>& xdot, EvaluationDetails* details = nullptr);

// Convenience: computes the frames and checks the result is finite; throws
// std::runtime_error naming the first non-finite state derivative.
Eigen::VectorXd rhs(const Model& model, double t_s, const Eigen::VectorXd& x,
                    EvaluationDetails* details = nullptr);

// Body motions of every body (for energy, output and tests).
template <class T>
void compute_all_body_motions(const Model& model, double t_s,
                              const std::vector<TrackFrameKinematics>& frames, const VecX<T>& x,
                              std::vector<BodyMotion<T>>& motions);

extern template void evaluate_rhs<double>(const Model&, double,
                                          const std::vector<TrackFrameKinematics>&,
                                          const VecX<double>&, VecX<double>&,
                                          EvaluationDetails*);
extern template void evaluate_rhs<AdScalar>(const Model&, double,
                                            const std::vector<TrackFrameKinematics>&,
                                            const VecX<AdScalar>&, VecX<AdScalar>&,
                                            EvaluationDetails*);
extern template void compute_all_body_motions<double>(const Model&, double,
                                                      const std::vector<TrackFrameKinematics>&,
                                                      const VecX<double>&,
                                                      std::vector<BodyMotion<double>>&);

}  // namespace railstab
