#pragma once
// The right-hand side of the model, dx/dt = f(t, x; V), one templated code
// path for simulation (double) and linearisation (AdScalar). Instantiated for
// every scalar in equations_of_motion.cpp only (other files see the extern
// declarations).
//
// x = [q; u; z] (model/model.hpp): dq/dt = u; du/dt from Newton-Euler of each
// body (kinematics/body_motion.hpp) under gravity, the force elements
// (elements/) and the wheel-rail contact (contact/); dz/dt from the elements
// that own internal states.
#include <railstab/contact/wheel_rail.hpp>
#include <railstab/model/model.hpp>
#include <railstab/model/workspace.hpp>

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

// Which forces an evaluation includes. The IMEX integrator splits the model
// into a stiff implicit part (dq/dt = u, contact and inertial terms) and the
// rest (force elements and gravity): integrate/model_callbacks.hpp.
enum class ForceSelection { all, contact_and_inertia };

template <class T>
void evaluate_rhs(const ModelTpl<ParameterScalar<T>>& model, Workspace<T>& ws, double t_s,
                  double speed_m_per_s, const VecXConstRef<T>& x, VecX<T>& xdot,
                  EvaluationDetails* details = nullptr,
                  ForceSelection forces = ForceSelection::all);

// Convenience (allocates a workspace): checks the result is finite; throws
// std::runtime_error naming the first non-finite state derivative.
Eigen::VectorXd rhs(const Model& model, double speed_m_per_s, double t_s,
                    const Eigen::VectorXd& x, EvaluationDetails* details = nullptr,
                    ForceSelection forces = ForceSelection::all);

// Body motions of every body into ws.motions (for energy, output and tests).
template <class T>
void compute_all_body_motions(const ModelTpl<ParameterScalar<T>>& model, Workspace<T>& ws,
                              double t_s, double speed_m_per_s,
                              const VecXConstRef<T>& x);

// The two attachments of element e (body 1 may be the track frame of body 2).
template <class T>
std::pair<Attachment<T>, Attachment<T>> element_attachments(const ElementEnds& ends,
                                                            Workspace<T>& ws) {
  Attachment<T> a1 =
      ends.body1 == kTrackBody
          ? attachment_of<T>(ws.frames[ends.body2],
                             ws.frames_speed_derivative.empty() ? nullptr : &ws.frames_speed_derivative[ends.body2])
          : attachment_of(ws.motions[ends.body1]);
  return {a1, attachment_of(ws.motions[ends.body2])};
}

#define RAILSTAB_DECLARE_RHS(T)                                                              \
  extern template void evaluate_rhs<T>(const ModelTpl<ParameterScalar<T>>&, Workspace<T>&,   \
                                       double, double, const VecXConstRef<T>&,     \
                                       VecX<T>&,                                             \
                                       EvaluationDetails*, ForceSelection);                  \
  extern template void compute_all_body_motions<T>(const ModelTpl<ParameterScalar<T>>&,      \
                                                   Workspace<T>&, double, double,            \
                                                   const VecXConstRef<T>&);
RAILSTAB_DECLARE_RHS(double)
RAILSTAB_DECLARE_RHS(AdScalar)
RAILSTAB_DECLARE_RHS(ParamDual)
RAILSTAB_DECLARE_RHS(ParamAdScalar)
#undef RAILSTAB_DECLARE_RHS

}  // namespace railstab
