#include "model/model.hpp"

#include <stdexcept>

namespace railstab {

int Model::find_body(const std::string& body_name) const {
  for (size_t b = 0; b < bodies.size(); ++b)
    if (bodies[b].name == body_name) return int(b);
  return -1;
}

std::string Model::state_name(int i) const {
  const bool is_rate = i >= n_coordinates;
  const auto [b, c] = coordinate_of_state[is_rate ? i - n_coordinates : i];
  return bodies[b].name + "." + kCoordinateNames[c] + (is_rate ? "/s" : "");
}

Eigen::VectorXd Model::initial_state() const {
  Eigen::VectorXd x(state_size());
  for (int k = 0; k < n_coordinates; ++k) {
    const auto [b, c] = coordinate_of_state[k];
    x(k) = bodies[b].initial_q(c);
    x(n_coordinates + k) = bodies[b].initial_rate(c);
  }
  return x;
}

void Model::full_coordinates(double t_s, const Eigen::VectorXd& x, Eigen::MatrixXd& q6,
                             Eigen::MatrixXd& qd6) const {
  q6.resize(6, bodies.size());
  qd6.resize(6, bodies.size());
  for (size_t b = 0; b < bodies.size(); ++b) {
    for (int i = 0; i < 6; ++i) {
      const int k = bodies[b].state_index[i];
      if (k >= 0) {
        q6(i, b) = x(k);
        qd6(i, b) = x(n_coordinates + k);
      } else {
        q6(i, b) = bodies[b].initial_q(i) + bodies[b].initial_rate(i) * t_s;
        qd6(i, b) = bodies[b].initial_rate(i);
      }
    }
  }
}

namespace {

ModelContact build_contact(const ContactSpec& spec) {
  ModelContact c;
  c.spec = spec;
  c.materials = combine_materials(spec.wheel_young_modulus_Pa, spec.wheel_poisson_ratio,
                                  spec.rail_young_modulus_Pa, spec.rail_poisson_ratio);
  c.rail_curvature_B_per_m = 0.5 / spec.rail_head_transverse_radius_m;
  return c;
}

// Undeformed vector d0 of a 3D spring, in body1's frame: the deflection at
// the nominal configuration on straight, level track (all frames aligned).
Eigen::Vector3d nominal_deflection(const Model& model, const ModelElement& e) {
  const ModelBody& b2 = model.bodies[e.body2];
  Eigen::Vector3d r2 = Eigen::Vector3d(b2.track_offset_m, 0, 0) +
                       b2.nominal_q.head<3>() + e.point2_m;
  Eigen::Vector3d r1;
  if (e.body1 == kTrackBody) {
    r1 = Eigen::Vector3d(b2.track_offset_m, 0, 0) + e.point1_m;
  } else {
    const ModelBody& b1 = model.bodies[e.body1];
    r1 = Eigen::Vector3d(b1.track_offset_m, 0, 0) + b1.nominal_q.head<3>() + e.point1_m;
  }
  return r2 - r1;
}

}  // namespace

Model build_model(const SceneSpec& scene) {
  Model model(scene.track);
  model.name = scene.name;
  model.source_path = scene.source_path;
  model.speed_m_per_s = scene.speed_m_per_s;
  model.gravity_m_per_s2 = scene.gravity_m_per_s2;
  model.reference_arc_length_m = scene.reference_arc_length_m;

  for (const ContactSpec& c : scene.contacts) model.contacts.push_back(build_contact(c));

  for (const BodySpec& spec : scene.bodies) {
    ModelBody body;
    body.name = spec.name;
    body.is_wheelset = spec.is_wheelset;
    body.mass_kg = spec.mass_kg;
    body.inertia_kg_m2 = spec.inertia_kg_m2;
    body.track_offset_m = spec.track_offset_m;
    body.nominal_q.setZero();
    body.nominal_q.head<3>() = spec.position_m;
    for (int i = 0; i < 6; ++i) {
      body.initial_q(i) = body.nominal_q(i) + spec.initial_offset[i];
      body.initial_rate(i) = spec.initial_rate[i];
    }
    if (spec.is_wheelset) {
      for (size_t c = 0; c < scene.contacts.size(); ++c)
        if (scene.contacts[c].name == spec.contact) body.contact = int(c);
      if (body.contact < 0)
        throw std::invalid_argument("wheelset '" + spec.name + "' names unknown contact '" +
                                    spec.contact + "'");
      // Steady rolling: spin rate V / r0 (pitch about +y rolls forward).
      body.initial_rate(4) +=
          scene.speed_m_per_s / scene.contacts[body.contact].nominal_rolling_radius_m;
    }
    model.bodies.push_back(body);
  }

  // Free coordinates get state indices in body order.
  for (size_t b = 0; b < scene.bodies.size(); ++b) {
    for (int i = 0; i < 6; ++i) {
      if (scene.bodies[b].free[i]) {
        model.bodies[b].state_index[i] = model.n_coordinates++;
        model.coordinate_of_state.emplace_back(int(b), i);
      } else {
        model.bodies[b].state_index[i] = -1;
      }
    }
  }

  for (const ElementSpec& spec : scene.elements) {
    ModelElement e;
    e.name = spec.name;
    e.kind = spec.kind;
    e.body1 = spec.body1 == kTrackBodyName ? kTrackBody : model.find_body(spec.body1);
    e.body2 = model.find_body(spec.body2);
    if ((e.body1 < 0 && spec.body1 != kTrackBodyName) || e.body2 < 0)
      throw std::invalid_argument("element '" + spec.name + "' names an unknown body");
    e.point1_m = spec.point1_m;
    e.point2_m = spec.point2_m;
    e.stiffness = spec.stiffness;
    e.damping = spec.damping;
    e.actuator = spec.actuator;
    if (e.kind == ElementKind::spring_damper_3d) e.free_vector_m = nominal_deflection(model, e);
    model.elements.push_back(e);
  }
  return model;
}

}  // namespace railstab
