#include <railstab/model/energy.hpp>

#include <railstab/model/equations_of_motion.hpp>

namespace railstab {

EnergyParts mechanical_energy(const Model& model, double speed_m_per_s, double t_s,
                              const Eigen::VectorXd& x,
                              const Eigen::Vector3d& observer_velocity_W) {
  Workspace<double> ws(model);
  compute_all_body_motions<double>(model, ws, t_s, speed_m_per_s, x);
  EnergyParts e;
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    const Body& body = model.bodies[b];
    const BodyMotion<double>& m = ws.motions[b];
    const Eigen::Vector3d w_B = m.R_IB.transpose() * m.w_B_I;  // body-frame components
    e.kinetic_J += 0.5 * body.mass_kg * (m.v_W - observer_velocity_W).squaredNorm() +
                   0.5 * w_B.dot(body.inertia_kg_m2.cwiseProduct(w_B));
    e.gravity_J += body.mass_kg * model.gravity_m_per_s2 * m.p_W.z();
  }
  const int z0 = model.internal_state_offset();
  for (size_t i = 0; i < model.elements.size(); ++i) {
    const int first = model.element_first_state[i];
    const double* z = first >= 0 ? &x(z0 + first) : nullptr;
    e.elastic_J += std::visit(
        [&](const auto& el) {
          const auto [a1, a2] = element_attachments(el.ends, ws);
          return el.potential(a1, a2, z);
        },
        model.elements[i]);
  }
  // Hertz contact potential (prescribed loads do work from outside: none).
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    const WheelsetKind* wheelset = model.bodies[b].wheelset();
    if (!wheelset) continue;
    const ModelContact& c = model.contacts[wheelset->contact];
    if (c.spec.normal != NormalForceKind::hertz) continue;
    for (int side : {1, -1})
      for (int slot = 0; slot < contact_points_per_wheel(c); ++slot) {
        const WheelContact<double> w =
            evaluate_wheel_contact(c, ws.motions[b], side, model.speed_at(t_s, speed_m_per_s), slot);
        if (w.penetration_m > 0.0) e.contact_J += 0.4 * w.elastic_normal_force_N * w.penetration_m;
      }
  }
  return e;
}

}  // namespace railstab
