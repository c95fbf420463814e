#include "model/energy.hpp"

#include "elements/spring_damper.hpp"
#include "model/equations_of_motion.hpp"

namespace railstab {

EnergyParts mechanical_energy(const Model& model, double t_s, const Eigen::VectorXd& x,
                              const Eigen::Vector3d& observer_velocity_W) {
  const auto frames = track_frames_at(model, t_s);
  std::vector<BodyMotion<double>> motions;
  compute_all_body_motions<double>(model, t_s, frames, x, motions);
  EnergyParts e;
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    const ModelBody& body = model.bodies[b];
    const BodyMotion<double>& m = motions[b];
    const Eigen::Vector3d w_B = m.R_IB.transpose() * m.w_B_I;  // body-frame components
    e.kinetic_J += 0.5 * body.mass_kg * (m.v_W - observer_velocity_W).squaredNorm() +
                   0.5 * w_B.dot(body.inertia_kg_m2.cwiseProduct(w_B));
    e.gravity_J += body.mass_kg * model.gravity_m_per_s2 * m.p_W.z();
  }
  for (const ModelElement& el : model.elements) {
    Attachment<double> a1 = el.body1 == kTrackBody ? attachment_of<double>(frames[el.body2])
                                                   : attachment_of(motions[el.body1]);
    Attachment<double> a2 = attachment_of(motions[el.body2]);
    const Eigen::Vector3d f0 = el.actuator + el.preload;
    if (el.kind == ElementKind::spring_damper_3d) {
      const Eigen::Vector3d dd = spring_deflection(el, a1, a2).d - el.free_vector_m;
      e.elastic_J += 0.5 * dd.dot(el.stiffness.cwiseProduct(dd)) + f0.dot(dd);
    } else {
      const Eigen::Vector3d th = rotation_vector<double>(a1.R_WF.transpose() * a2.R_WF);
      e.elastic_J += 0.5 * th.dot(el.stiffness.cwiseProduct(th)) + f0.dot(th);
    }
  }
  // Hertz contact potential (prescribed loads do work from outside: none).
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    const ModelBody& body = model.bodies[b];
    if (body.contact < 0) continue;
    const ModelContact& c = model.contacts[body.contact];
    if (c.spec.normal != NormalForceKind::hertz) continue;
    for (int side : {1, -1}) {
      const WheelContact<double> w = evaluate_wheel_contact(c, motions[b], side, model.speed_m_per_s);
      if (w.penetration_m > 0.0) e.contact_J += 0.4 * w.elastic_normal_force_N * w.penetration_m;
    }
  }
  return e;
}

}  // namespace railstab
