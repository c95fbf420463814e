#pragma once
// The assembled model (Pinocchio's "Model"): parameters and topology,
// resolved into indices, built once from a scene (setup/build_model) and not
// changed afterwards. Everything an evaluation writes lives in a workspace
// (model/workspace.hpp), and the speed V is an argument of every evaluation,
// not a property of the model: one model serves a whole speed sweep.
//
// State layout: x = [q; u; z]. q: the free coordinates of all bodies in body
// order (each body's free coordinates in the order x, y, z, roll, pitch,
// yaw); u = dq/dt in the same order; z: the internal states of force
// elements (e.g. the damper elongation of a series spring-damper), element
// by element. Frozen coordinates are not states: they are prescribed,
// q(t) = nominal + offset + rate t (rate 0, except a wheelset's spin V/r0).
//
// Speed law (docs/speed_ramp.md): the speed argument V0 of an evaluation is
// the speed at t = 0; a time-domain run with a speed ramp has
//   V(t) = V0 + speed_rate_m_per_s2 t,   s(t) = s(0) + V0 t + speed_rate t^2 / 2
// for every body's track frame, and a frozen spin follows V(t)/r0. Every
// steady-state analysis (equilibrium, linearisation, eigenvalues) is of a
// model with speed_rate_m_per_s2 = 0, the default: then V(t) = V0 exactly.
//
// S is the scalar of the parameters: double, or an AD type when derivatives
// with respect to parameters are wanted (cast<S2>(), as Pinocchio's
// model.cast<NewScalar>()).
#include <railstab/bodies/body.hpp>
#include <railstab/contact/model_contact.hpp>
#include <railstab/elements/element.hpp>
#include <railstab/scene/scene_spec.hpp>
#include <railstab/track/track.hpp>

#include <Eigen/Dense>

#include <string>
#include <utility>
#include <vector>

namespace railstab {

// A point fixed in a rigid body where accelerations are reported
// (ride/point_acceleration.hpp), from the scene's [[bodies.measure_points]].
struct MeasurePoint {
  int body = 0;                 // index into bodies (never a wheelset)
  std::string name;             // as in the scene; reported as "<body>.<name>"
  Eigen::Vector3d position_B_m = Eigen::Vector3d::Zero();  // from the CM, body axes
};

template <class S> struct ModelTpl {
  std::string name;
  std::string source_path;
  std::string source_sha256;  // of the scene file as read (SceneSpec::source_sha256)
  Track track;
  double gravity_m_per_s2 = 9.81;
  double reference_arc_length_m = 0.0;
  // dV/dt of time-domain runs (m/s^2; < 0 decelerates); 0: constant speed.
  double speed_rate_m_per_s2 = 0.0;
  // The speed V is a direction of the parameter scalar S (ParamDual): the
  // evaluation seeds dV/dV = 1 in the track frames' rates, the prescribed
  // rates and the creepages' V (sensitivity/parameter_derivative.hpp,
  // kSpeedParameter). Off for every analysis; meaningless for double.
  bool differentiated_in_speed = false;
  std::vector<BodyTpl<S>> bodies;
  std::vector<ModelContactTpl<S>> contacts;
  std::vector<ElementTpl<S>> elements;
  std::vector<MeasurePoint> measure_points;
  int n_coordinates = 0;      // free coordinates q (and as many rates u)
  int n_internal_states = 0;  // element states z
  // For each free coordinate: (body, coordinate index 0..5).
  std::vector<std::pair<int, int>> coordinate_of_state;
  // For each element: index of its first internal state in z (-1: none).
  std::vector<int> element_first_state;
  // For each internal state: (element, its index within the element).
  std::vector<std::pair<int, int>> element_of_internal_state;

  explicit ModelTpl(const TrackSpec& track_spec) : track(track_spec) {}
  explicit ModelTpl(const Track& built_track) : track(built_track) {}

  int state_size() const { return 2 * n_coordinates + n_internal_states; }
  int internal_state_offset() const { return 2 * n_coordinates; }
  bool is_position(int i) const { return i < n_coordinates; }
  bool is_rate(int i) const { return i >= n_coordinates && i < 2 * n_coordinates; }
  bool is_internal(int i) const { return i >= 2 * n_coordinates; }
  // V(t) and the distance travelled since t = 0, from V0 = the evaluation's
  // speed. With no speed rate both are the constant-speed values, bit for bit.
  double speed_at(double t_s, double speed_m_per_s) const {
    return speed_rate_m_per_s2 == 0.0 ? speed_m_per_s : speed_m_per_s + speed_rate_m_per_s2 * t_s;
  }
  double distance_at(double t_s, double speed_m_per_s) const {
    return speed_rate_m_per_s2 == 0.0 ? speed_m_per_s * t_s
                                      : speed_m_per_s * t_s + 0.5 * speed_rate_m_per_s2 * t_s * t_s;
  }
  double arc_length_of(int body, double t_s, double speed_m_per_s) const {
    return reference_arc_length_m + bodies[body].track_offset_m + distance_at(t_s, speed_m_per_s);
  }
  int find_body(const std::string& body_name) const {
    for (size_t b = 0; b < bodies.size(); ++b)
      if (bodies[b].name == body_name) return int(b);
    return -1;
  }
  // Human-readable name of state entry i: "wheelset1.y_m", "wheelset1.y_m/s",
  // "yaw_damper_left.damper_elongation_m".
  std::string state_name(int i) const {
    if (is_internal(i)) {
      const auto [e, k] = element_of_internal_state[i - internal_state_offset()];
      return ends_of(elements[e]).name + "." +
             std::visit([k = k](const auto& el) { return el.internal_state_name(k); },
                        elements[e]);
    }
    const bool rate = is_rate(i);
    const auto [b, c] = coordinate_of_state[rate ? i - n_coordinates : i];
    return bodies[b].name + "." + kCoordinateNames[c] + (rate ? "/s" : "");
  }
  // All six coordinates and rates of every body at time t from a state.
  void full_coordinates(double t_s, double speed_m_per_s, const Eigen::VectorXd& x,
                        Eigen::MatrixXd& q6, Eigen::MatrixXd& qd6) const {
    q6.resize(6, bodies.size());
    qd6.resize(6, bodies.size());
    for (size_t b = 0; b < bodies.size(); ++b) {
      for (int i = 0; i < 6; ++i) {
        const int k = bodies[b].state_index[i];
        if (k >= 0) {
          q6(i, b) = x(k);
          qd6(i, b) = x(n_coordinates + k);
        } else {
          q6(i, b) = bodies[b].prescribed_value(i, t_s, speed_m_per_s, speed_rate_m_per_s2);
          qd6(i, b) = bodies[b].prescribed_rate(i, speed_at(t_s, speed_m_per_s));
        }
      }
    }
  }

  template <class S2> ModelTpl<S2> cast() const {
    ModelTpl<S2> m(track);
    m.name = name;
    m.source_path = source_path;
    m.source_sha256 = source_sha256;
    m.gravity_m_per_s2 = gravity_m_per_s2;
    m.reference_arc_length_m = reference_arc_length_m;
    m.speed_rate_m_per_s2 = speed_rate_m_per_s2;
    m.differentiated_in_speed = differentiated_in_speed;
    for (const BodyTpl<S>& b : bodies) m.bodies.push_back(b.template cast<S2>());
    for (const ModelContactTpl<S>& c : contacts) m.contacts.push_back(c.template cast<S2>());
    for (const ElementTpl<S>& e : elements)
      m.elements.push_back(std::visit(
          [](const auto& el) -> ElementTpl<S2> { return el.template cast<S2>(); }, e));
    m.measure_points = measure_points;
    m.n_coordinates = n_coordinates;
    m.n_internal_states = n_internal_states;
    m.coordinate_of_state = coordinate_of_state;
    m.element_first_state = element_first_state;
    m.element_of_internal_state = element_of_internal_state;
    return m;
  }
};

using Model = ModelTpl<double>;
using Body = BodyTpl<double>;

// Resolve a validated scene into a model, with the element preloads given
// (one per element, in scene order; empty: none). Geometry that elements
// measure from (free lengths, free vectors) is taken at the nominal
// configuration on straight, level track. Throws std::invalid_argument on
// inconsistencies the loader cannot see. setup/build_model.hpp adds the
// preloads the scene asks for: most callers want that one.
Model assemble_model(const SceneSpec& scene, const std::vector<Eigen::Vector3d>& preloads = {});

}  // namespace railstab
