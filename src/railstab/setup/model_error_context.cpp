#include <railstab/setup/model_error_context.hpp>

#include <railstab/equilibrium/equilibrium.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>
#include <utility>
#include <vector>

namespace railstab {

namespace {

std::string lower(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = char(std::tolower(static_cast<unsigned char>(c)));
  return out;
}
bool mentions(const std::string& lower_message, std::initializer_list<const char*> words) {
  for (const char* w : words)
    if (lower_message.find(w) != std::string::npos) return true;
  return false;
}

std::string body_path(const Model& model, int b) {
  return "bodies[" + std::to_string(b) + "] ('" + model.bodies[size_t(b)].name + "')";
}

// "primary_ws1_left, yaw_damper" (the elements acting on body b; at most 4).
std::string elements_on(const Model& model, int b) {
  const std::string& name = model.bodies[size_t(b)].name;
  std::vector<std::string> names;
  for (const auto& e : model.elements) {
    const ElementEnds& ends = ends_of(e);
    if (ends.body1_name == name || ends.body2_name == name) names.push_back(ends.name);
  }
  if (names.empty()) return "none";
  std::string text;
  for (size_t i = 0; i < names.size() && i < 4; ++i) text += (i ? ", " : "") + names[i];
  if (names.size() > 4) text += " and " + std::to_string(names.size() - 4) + " more";
  return text;
}

// The body a state name ("wheelset2.y_m/s") belongs to, or -1.
int body_of_state_name(const Model& model, const std::string& state) {
  const size_t dot = state.rfind('.');
  if (dot == std::string::npos) return -1;
  return model.find_body(state.substr(0, dot));
}

// The body named in a message "... state wheelset2.y_m ..." or "(wheelset2.z_m
// acceleration", by the longest body name followed by '.'.
int body_named_in(const Model& model, const std::string& message) {
  int best = -1;
  size_t best_length = 0;
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    const std::string& name = model.bodies[b].name;
    if (name.size() > best_length && message.find(name + ".") != std::string::npos) {
      best = int(b);
      best_length = name.size();
    }
  }
  return best;
}

struct StateDiagnosis {
  int non_finite_body = -1;
  std::string non_finite_coordinate;
  int displaced_wheelset = -1;  // largest |lateral shift| / flange clearance
  double lateral_shift_m = 0.0, vertical_offset_m = 0.0, roll_rad = 0.0, clearance_m = 0.0;
};

StateDiagnosis diagnose(const Model& model, double V, double t, const Eigen::VectorXd& x) {
  StateDiagnosis d;
  Eigen::MatrixXd q6, qd6;
  model.full_coordinates(t, V, x, q6, qd6);
  double worst_ratio = -1.0;
  for (int b = 0; b < int(model.bodies.size()); ++b) {
    for (int c = 0; c < 6 && d.non_finite_body < 0; ++c)
      if (!std::isfinite(q6(c, b)) || !std::isfinite(qd6(c, b))) {
        d.non_finite_body = b;
        d.non_finite_coordinate = kCoordinateNames[c];
      }
    const Body& body = model.bodies[size_t(b)];
    if (!body.wheelset()) continue;
    const double clearance =
        lateral_validity_limit_m(model.contacts[size_t(body.wheelset()->contact)].spec);
    const double shift = q6(1, b) - body.nominal_q(1);
    const double ratio = std::abs(shift) / clearance;
    if (std::isfinite(ratio) && ratio > worst_ratio) {
      worst_ratio = ratio;
      d.displaced_wheelset = b;
      d.lateral_shift_m = shift;
      d.vertical_offset_m = q6(2, b) - body.nominal_q(2);
      d.roll_rad = q6(3, b);
      d.clearance_m = clearance;
    }
  }
  return d;
}

}  // namespace

std::string without_function_name(std::string_view message) {
  static const std::pair<const char*, const char*> kWords[] = {
      {"hertz_shape: ", "Hertz contact ellipse: "},
      {"kalker_coefficients: ", "Kalker creep coefficients: "},
      {"kalker_table: ", "Kalker creep coefficients: "},
      {"combine_materials: ", "wheel and rail materials: "},
      {"eigen_dense: ", "eigenvalues (dense solver): "},
      {"eigen_arpack_shift_invert: ", "eigenvalues (ARPACK): "},
      {"modal_assurance: ", "mode tracking: "},
      {"assemble_model: ", "model assembly: "},
      {"make_profile_pair: ", "wheel-rail profile pair: "},
      {"make_contact_table: ", "contact table: "},
      {"minimum_gap_in_wheel_range: ", "contact point search: "},
      {"solve_equilibrium: ", "equilibrium solver: "},
  };
  std::string text(message);
  for (const auto& [name, words] : kWords)
    for (size_t at = text.find(name); at != std::string::npos; at = text.find(name, at))
      text.replace(at, std::string_view(name).size(), words);
  return text;
}

std::string describe_model_failure(const Model& model, const EvaluationPlace& place,
                                   const std::exception& error) {
  const double V = place.speed_m_per_s, t = place.time_s;
  const Eigen::VectorXd* x = place.state;
  std::string worst_state;
  if (const auto* eq = dynamic_cast<const EquilibriumError*>(&error)) {
    if (eq->last_state.size() == model.state_size()) x = &eq->last_state;
    worst_state = eq->worst_state;
  }
  const std::string inner = without_function_name(error.what());
  const std::string what = lower(inner);

  std::ostringstream m;
  m.precision(6);
  m << (model.source_path.empty() ? std::string("<scene>") : model.source_path) << ": "
    << place.stage << " of scene '" << model.name << "' at V = " << V << " m/s";
  if (place.on_scene_track)
    m << ", reference point at arc length " << model.reference_arc_length_m + V * t << " m";
  if (t != 0.0) m << " (t = " << t << " s)";
  m << ": " << inner;

  StateDiagnosis d;
  if (x && x->size() == model.state_size()) d = diagnose(model, V, t, *x);
  if (d.non_finite_body >= 0)
    m << ". At this state " << body_path(model, d.non_finite_body) << "." << d.non_finite_coordinate
      << " is not finite";
  else if (d.displaced_wheelset >= 0)
    m << ". At this state " << body_path(model, d.displaced_wheelset) << " is "
      << d.lateral_shift_m * 1e3 << " mm off centre (flange clearance " << d.clearance_m * 1e3
      << " mm), " << d.vertical_offset_m * 1e3 << " mm from its nominal height, roll "
      << d.roll_rad * 1e3 << " mrad";

  // The scene keys most likely responsible, by what failed.
  int body = d.non_finite_body;
  if (body < 0 && !worst_state.empty()) body = body_of_state_name(model, worst_state);
  if (body < 0) body = body_named_in(model, inner);
  if (body < 0 && place.matrix && place.matrix_state_names) {
    const Eigen::MatrixXd& A = *place.matrix;
    for (Eigen::Index i = 0; i < A.rows() && body < 0; ++i)
      for (Eigen::Index j = 0; j < A.cols() && body < 0; ++j)
        if (!std::isfinite(A(i, j)) && size_t(j) < place.matrix_state_names->size())
          body = body_of_state_name(model, (*place.matrix_state_names)[size_t(j)]);
  }
  m << ". Most likely responsible: ";
  if (mentions(what, {"outside the track"})) {
    m << "scene.reference_arc_length_m (or --arc-length) with the bodies' track_offset_m";
    if (t != 0.0) m << ", or simulation.t_end_s (the run covers V t_end_s of track)";
    m << "; the track is " << model.track.length_m() << " m long";
  } else if (mentions(what, {"curvature", "hertz", "semi-ax", "kalker", "penetration"})) {
    const int w = d.displaced_wheelset >= 0 ? d.displaced_wheelset : body;
    if (w >= 0 && model.bodies[size_t(w)].wheelset()) {
      const std::string& contact =
          model.contacts[size_t(model.bodies[size_t(w)].wheelset()->contact)].spec.name;
      m << "contacts." << contact
        << " (nominal_rolling_radius_m, cone_angle_rad, rail_head_transverse_radius_m, Young's "
           "moduli), or what moves "
        << body_path(model, w)
        << " this far: its initial_offset and position_m, the elements on it ("
        << elements_on(model, w) << "), or the cant deficiency at this speed and place";
    } else {
      m << "the [contacts.<name>] tables (radii, cone angle, moduli) or the wheelsets' "
           "initial_offset and position_m";
    }
  } else if (mentions(what, {"nan", "infinite", "non-finite", "not finite"})) {
    if (body >= 0)
      m << body_path(model, body) << ": its mass_kg and inertia_kg_m2, and the stiffness, "
        << "damping and points of the elements on it (" << elements_on(model, body) << ")";
    else
      m << "the bodies' mass_kg and inertia_kg_m2 against the elements' stiffness and damping "
           "(a stiffness/mass ratio of 1e16 1/s2 or more leaves no digits)";
  } else if (mentions(what, {"equilibrium"})) {
    if (d.displaced_wheelset >= 0 && std::abs(d.lateral_shift_m) > d.clearance_m)
      m << "the cant deficiency at this speed and place (scene.speed_m_per_s, "
           "scene.reference_arc_length_m or --arc-length, track.segments end_cant_m): "
        << body_path(model, d.displaced_wheelset)
        << " is past its flange clearance, where the flangeless contact has no steady state";
    else if (body >= 0)
      m << "the elements that hold " << body_path(model, body) << " ("
        << elements_on(model, body)
        << "): a free coordinate without a restoring element has no steady state; or the "
           "speed and cant deficiency (scene.speed_m_per_s, track.segments end_cant_m)";
    else
      m << "the elements that restrain the free coordinates, or the speed and cant deficiency";
  } else if (body >= 0) {
    m << body_path(model, body) << " and the elements on it (" << elements_on(model, body) << ")";
  } else {
    m << "not determined (no body or contact is singled out by the failure)";
  }
  return m.str();
}

}  // namespace railstab
