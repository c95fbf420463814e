#include "model/equations_of_motion.hpp"

#include "elements/spring_damper.hpp"

#include <sstream>
#include <stdexcept>

namespace railstab {

std::vector<TrackFrameKinematics> track_frames_at(const Model& model, double t_s) {
  std::vector<TrackFrameKinematics> frames;
  frames.reserve(model.bodies.size());
  for (size_t b = 0; b < model.bodies.size(); ++b)
    frames.push_back(model.track.frame_at(model.arc_length_of(int(b), t_s), model.speed_m_per_s));
  return frames;
}

template <class T>
void compute_all_body_motions(const Model& model, double t_s,
                              const std::vector<TrackFrameKinematics>& frames, const VecX<T>& x,
                              std::vector<BodyMotion<T>>& motions) {
  const int n = model.n_coordinates;
  motions.resize(model.bodies.size());
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    const ModelBody& body = model.bodies[b];
    Eigen::Matrix<T, 6, 1> q, qd;
    for (int i = 0; i < 6; ++i) {
      const int k = body.state_index[i];
      if (k >= 0) {
        q(i) = x(k);
        qd(i) = x(n + k);
      } else {  // prescribed: q0 + rate t
        q(i) = T(body.initial_q(i) + body.initial_rate(i) * t_s);
        qd(i) = T(body.initial_rate(i));
      }
    }
    compute_body_motion(body, frames[b], q, qd, motions[b]);
  }
}

template <class T>
void evaluate_rhs(const Model& model, double t_s, const std::vector<TrackFrameKinematics>& frames,
                  const VecX<T>& x, VecX<T>& xdot, EvaluationDetails* details) {
  const int n = model.n_coordinates;
  std::vector<BodyMotion<T>> motions;
  compute_all_body_motions(model, t_s, frames, x, motions);

  // Gravity (W: -z).
  for (size_t b = 0; b < model.bodies.size(); ++b)
    motions[b].force_W.z() -= T(model.bodies[b].mass_kg * model.gravity_m_per_s2);

  // Force elements.
  for (const ModelElement& e : model.elements) {
    const Attachment<T> a1 = e.body1 == kTrackBody ? attachment_of<T>(frames[e.body2])
                                                   : attachment_of(motions[e.body1]);
    const Attachment<T> a2 = attachment_of(motions[e.body2]);
    if (e.kind == ElementKind::spring_damper_3d)
      apply_spring_damper_3d(e, a1, a2);
    else
      apply_rotational_spring_damper(e, a1, a2);
  }

  // Wheel-rail contact.
  if (details) details->contacts.clear();
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    const ModelBody& body = model.bodies[b];
    if (body.contact < 0) continue;
    BodyMotion<T>& m = motions[b];
    for (int side : {1, -1}) {
      const WheelContact<T> wc =
          evaluate_wheel_contact(model.contacts[body.contact], m, side, model.speed_m_per_s);
      m.force_W += m.R_WI * wc.force_I;
      m.spinning_moment_W += m.R_WI * wc.moment_I;
      if constexpr (std::is_same_v<T, double>) {
        if (details) details->contacts.push_back({int(b), wc});
      }
    }
  }

  xdot.resize(2 * n);
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    const ModelBody& body = model.bodies[b];
    const Eigen::Matrix<T, 6, 1> acc = body_accelerations(body, motions[b]);
    for (int i = 0; i < 6; ++i) {
      const int k = body.state_index[i];
      if (k < 0) continue;
      xdot(k) = x(n + k);
      xdot(n + k) = acc(i);
    }
  }
}

Eigen::VectorXd rhs(const Model& model, double t_s, const Eigen::VectorXd& x,
                    EvaluationDetails* details) {
  const auto frames = track_frames_at(model, t_s);
  Eigen::VectorXd xdot;
  evaluate_rhs<double>(model, t_s, frames, x, xdot, details);
  for (int i = 0; i < xdot.size(); ++i) {
    if (!std::isfinite(xdot(i))) {
      std::ostringstream msg;
      msg << "non-finite derivative of state " << model.state_name(i) << " at t = " << t_s
          << " s (state value " << x(i) << ")";
      throw std::runtime_error(msg.str());
    }
  }
  return xdot;
}

template void evaluate_rhs<double>(const Model&, double, const std::vector<TrackFrameKinematics>&,
                                   const VecX<double>&, VecX<double>&, EvaluationDetails*);
template void evaluate_rhs<AdScalar>(const Model&, double,
                                     const std::vector<TrackFrameKinematics>&,
                                     const VecX<AdScalar>&, VecX<AdScalar>&, EvaluationDetails*);
template void compute_all_body_motions<double>(const Model&, double,
                                               const std::vector<TrackFrameKinematics>&,
                                               const VecX<double>&,
                                               std::vector<BodyMotion<double>>&);
template void compute_all_body_motions<AdScalar>(const Model&, double,
                                                 const std::vector<TrackFrameKinematics>&,
                                                 const VecX<AdScalar>&,
                                                 std::vector<BodyMotion<AdScalar>>&);

}  // namespace railstab
