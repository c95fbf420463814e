#include <railstab/model/model.hpp>

#include <railstab/kinematics/attachment.hpp>

#include <stdexcept>

namespace railstab {

namespace {

BodyKind body_kind(const BodySpec& spec, const SceneSpec& scene) {
  if (!spec.is_wheelset) return RigidBodyKind{};
  WheelsetKind w;
  for (size_t c = 0; c < scene.contacts.size(); ++c)
    if (scene.contacts[c].name == spec.contact) w.contact = int(c);
  if (w.contact < 0)
    throw std::invalid_argument("wheelset '" + spec.name + "' names unknown contact '" +
                                spec.contact + "'");
  w.nominal_rolling_radius_m = scene.contacts[w.contact].nominal_rolling_radius_m;
  return w;
}

// Attachment of a body at its nominal position on straight, level track:
// every frame aligned with W, the body at (track offset + nominal x, y, z).
// Elements measure their free lengths and vectors here (the body does not
// move: velocities zero).
Attachment<double> nominal_attachment(const Model& model, int body, int body2) {
  Attachment<double> a;
  a.body = nullptr;
  a.R_WF.setIdentity();
  const Body& b = model.bodies[body == kTrackBody ? body2 : body];
  a.origin_W = Eigen::Vector3d(b.track_offset_m, 0, 0);
  if (body != kTrackBody) a.origin_W += model.bodies[body].nominal_q.head<3>();
  a.origin_v_W.setZero();
  a.w_W.setZero();
  return a;
}

}  // namespace

Model assemble_model(const SceneSpec& scene, const std::vector<Eigen::Vector3d>& preloads) {
  if (!preloads.empty() && preloads.size() != scene.elements.size())
    throw std::invalid_argument("assemble_model: " + std::to_string(preloads.size()) +
                                " preloads for " + std::to_string(scene.elements.size()) +
                                " elements");
  Model model(scene.track);
  model.name = scene.name;
  model.source_path = scene.source_path;
  model.source_sha256 = scene.source_sha256;
  model.gravity_m_per_s2 = scene.gravity_m_per_s2;
  model.reference_arc_length_m = scene.reference_arc_length_m;

  for (const ContactSpec& c : scene.contacts) {
    // The set-up step builds profile contact tables (setup/contact_tables.hpp).
    if (uses_contact_table(c.geometry) && !c.profile_geometry)
      throw std::invalid_argument("assemble_model: contacts." + c.name + ": geometry = \"" +
                                  std::string(contact_geometry_name(c.geometry)) +
                                  "\" without its contact table (build_model or "
                                  "build_contact_tables builds or reads it)");
    model.contacts.push_back(make_model_contact(c));
  }

  for (const BodySpec& spec : scene.bodies) {
    Body body;
    body.name = spec.name;
    body.kind = body_kind(spec, scene);
    body.mass_kg = spec.mass_kg;
    body.inertia_kg_m2 = spec.inertia_kg_m2;
    body.track_offset_m = spec.track_offset_m;
    body.nominal_q.setZero();
    body.nominal_q.head<3>() = spec.position_m;
    for (int i = 0; i < 6; ++i) {
      body.initial_offset(i) = spec.initial_offset[i];
      body.initial_rate(i) = spec.initial_rate[i];
    }
    for (const MeasurePointSpec& point : spec.measure_points)
      model.measure_points.push_back({int(model.bodies.size()), point.name, point.position_m});
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

  for (size_t i = 0; i < scene.elements.size(); ++i) {
    ElementSpec element = scene.elements[i];
    ElementEnds& ends = ends_of(element);
    ends.body1 = ends.body1_name == kTrackBodyName ? kTrackBody : model.find_body(ends.body1_name);
    ends.body2 = model.find_body(ends.body2_name);
    if ((ends.body1 < 0 && ends.body1_name != kTrackBodyName) || ends.body2 < 0)
      throw std::invalid_argument("element '" + ends.name + "' names an unknown body");
    const Attachment<double> a1 = nominal_attachment(model, ends.body1, ends.body2);
    const Attachment<double> a2 = nominal_attachment(model, ends.body2, ends.body2);
    std::visit(
        [&](auto& e) {
          e.set_nominal(a1, a2);
          if (!preloads.empty()) e.set_preload(preloads[i]);
        },
        element);
    const int n_internal = internal_states_of(element);
    model.element_first_state.push_back(n_internal > 0 ? model.n_internal_states : -1);
    for (int k = 0; k < n_internal; ++k)
      model.element_of_internal_state.emplace_back(int(i), k);
    model.n_internal_states += n_internal;
    model.elements.push_back(std::move(element));
  }
  return model;
}

}  // namespace railstab
