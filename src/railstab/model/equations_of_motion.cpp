#include <railstab/model/equations_of_motion.hpp>

#include <railstab/core/nested_dual.hpp>

#include <sstream>
#include <stdexcept>

namespace railstab {

template <class T>
void compute_all_body_motions(const ModelTpl<ParameterScalar<T>>& model, Workspace<T>& ws,
                              double t_s, double speed_m_per_s,
                              const VecXConstRef<T>& x) {
  ws.update_frames(model, t_s, speed_m_per_s);
  const int n = model.n_coordinates;
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    const auto& body = model.bodies[b];
    Eigen::Matrix<T, 6, 1> q, qd;
    for (int i = 0; i < 6; ++i) {
      const int k = body.state_index[i];
      if (k >= 0) {
        q(i) = x(k);
        qd(i) = x(n + k);
      } else if (model.differentiated_in_speed) {
        // q = nominal + offset + (initial rate + steady rate(V)) t, the
        // steady rate linear in V: d/dV = steady_rate(1) (t for the value).
        const double d_rate = body.steady_rate(i, 1.0);
        q(i) = seeded_scalar<T>(body.prescribed_value(i, t_s, speed_m_per_s, model.speed_rate_m_per_s2),
                                d_rate * t_s);
        qd(i) = seeded_scalar<T>(body.prescribed_rate(i, model.speed_at(t_s, speed_m_per_s)), d_rate);
      } else {  // prescribed: nominal + offset + rate t
        q(i) = T(body.prescribed_value(i, t_s, speed_m_per_s, model.speed_rate_m_per_s2));
        qd(i) = T(body.prescribed_rate(i, model.speed_at(t_s, speed_m_per_s)));
      }
    }
    compute_body_motion(body, ws.frames[b], q, qd, ws.motions[b],
                        ws.frames_speed_derivative.empty() ? nullptr : &ws.frames_speed_derivative[b]);
  }
}

template <class T>
void evaluate_rhs(const ModelTpl<ParameterScalar<T>>& model, Workspace<T>& ws, double t_s,
                  double speed_m_per_s, const VecXConstRef<T>& x, VecX<T>& xdot,
                  EvaluationDetails* details, ForceSelection forces) {
  const int n = model.n_coordinates;
  const int z0 = model.internal_state_offset();
  compute_all_body_motions(model, ws, t_s, speed_m_per_s, x);
  xdot.resize(model.state_size());

  if (forces == ForceSelection::all) {
    // Gravity (W: -z).
    for (size_t b = 0; b < model.bodies.size(); ++b)
      ws.motions[b].force_W.z() -= lift<T>(model.bodies[b].mass_kg) * T(model.gravity_m_per_s2);

    // Force elements, and the rates of their internal states.
    for (size_t i = 0; i < model.elements.size(); ++i) {
      const int first = model.element_first_state[i];
      const T* z = first >= 0 ? x.data() + z0 + first : nullptr;
      T* zdot = first >= 0 ? &xdot(z0 + first) : nullptr;
      std::visit(
          [&](const auto& e) {
            const auto [a1, a2] = element_attachments(e.ends, ws);
            e.apply(a1, a2, z, zdot);
          },
          model.elements[i]);
    }
  } else {
    for (int k = 0; k < model.n_internal_states; ++k) xdot(z0 + k) = T(0);
  }

  // Wheel-rail contact, at the speed of this instant (creepages are slip
  // velocities over V(t)).
  const double speed_now_m_per_s = model.speed_at(t_s, speed_m_per_s);
  if (details) details->contacts.clear();
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    const WheelsetKind* wheelset = model.bodies[b].wheelset();
    if (!wheelset) continue;
    BodyMotion<T>& m = ws.motions[b];
    const auto& contact = model.contacts[wheelset->contact];
    const int points = contact_points_per_wheel(contact);
    for (int side : {1, -1})
      for (int slot = 0; slot < points; ++slot) {
        const WheelContact<T> wc = evaluate_wheel_contact(contact, m, side, speed_now_m_per_s, slot);
        // Profiles: a slot out of contact has no force (Hertz only) and is
        // left out of the reports.
        if (points > 1 && value_of(wc.normal_force_N) <= 0.0) continue;
        m.force_W += m.R_WI * wc.force_I;
        m.spinning_moment_W += m.R_WI * wc.moment_I;
        if constexpr (std::is_same_v<T, double>) {
          if (details) details->contacts.push_back({int(b), wc});
        }
      }
  }

  for (size_t b = 0; b < model.bodies.size(); ++b) {
    const auto& body = model.bodies[b];
    const Eigen::Matrix<T, 6, 1> acc = body_accelerations(body, ws.motions[b]);
    for (int i = 0; i < 6; ++i) {
      const int k = body.state_index[i];
      if (k < 0) continue;
      xdot(k) = x(n + k);
      xdot(n + k) = acc(i);
    }
  }
}

Eigen::VectorXd rhs(const Model& model, double speed_m_per_s, double t_s,
                    const Eigen::VectorXd& x, EvaluationDetails* details,
                    ForceSelection forces) {
  Workspace<double> ws(model);
  Eigen::VectorXd xdot;
  evaluate_rhs<double>(model, ws, t_s, speed_m_per_s, x, xdot, details, forces);
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

#define RAILSTAB_DEFINE_RHS(T)                                                               \
  template void evaluate_rhs<T>(const ModelTpl<ParameterScalar<T>>&, Workspace<T>&, double,  \
                                double, const VecXConstRef<T>&, VecX<T>&,          \
                                EvaluationDetails*,                                          \
                                ForceSelection);                                             \
  template void compute_all_body_motions<T>(const ModelTpl<ParameterScalar<T>>&,             \
                                            Workspace<T>&, double, double,                   \
                                            const VecXConstRef<T>&);
RAILSTAB_DEFINE_RHS(double)
RAILSTAB_DEFINE_RHS(AdScalar)
RAILSTAB_DEFINE_RHS(ParamDual)
RAILSTAB_DEFINE_RHS(ParamAdScalar)
// Exact second and third state derivatives (nonlinear/multilinear_forms.hpp).
RAILSTAB_DEFINE_RHS(Dual3)
#undef RAILSTAB_DEFINE_RHS

}  // namespace railstab
