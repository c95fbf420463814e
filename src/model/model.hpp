#pragma once
// The assembled model: what the scene asked for, resolved into indices, with
// everything a right-hand-side evaluation needs precomputed. Built once from a
// SceneSpec (build_model), then read-only: simulation, equilibrium and
// linearisation all evaluate the same Model.
//
// State layout: x = [q; u], q the free coordinates of all bodies in body
// order (each body's free coordinates in the order x, y, z, roll, pitch, yaw),
// u = dq/dt in the same order. Frozen coordinates are not states: they are
// prescribed, q(t) = q0 + rate t (rate 0, except a wheelset's spin at V/r0).
#include "contact/hertz.hpp"
#include "scene/scene_spec.hpp"
#include "track/track.hpp"

#include <Eigen/Dense>

#include <array>
#include <string>
#include <vector>

namespace railstab {

inline constexpr int kTrackBody = -1;  // element attached to a track frame

struct ModelBody {
  std::string name;
  bool is_wheelset = false;
  double mass_kg = 0.0;
  Eigen::Vector3d inertia_kg_m2 = Eigen::Vector3d::Zero();
  double track_offset_m = 0.0;
  int contact = -1;                          // index into Model::contacts
  std::array<int, 6> state_index{};          // index into q, or -1 when frozen
  Eigen::Matrix<double, 6, 1> initial_q;     // nominal + initial offset
  Eigen::Matrix<double, 6, 1> initial_rate;  // incl. spin V/r0 of wheelsets
  Eigen::Matrix<double, 6, 1> nominal_q;     // nominal position, no offsets
};

struct ModelContact {
  ContactSpec spec;
  ElasticPair materials{};
  double rail_curvature_B_per_m = 0.0;  // B = 1 / (2 R_rail), transverse
};

struct ModelElement {
  std::string name;
  ElementKind kind = ElementKind::spring_damper_3d;
  int body1 = kTrackBody;  // kTrackBody: the track frame of body2
  int body2 = 0;
  Eigen::Vector3d point1_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d point2_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d stiffness = Eigen::Vector3d::Zero();
  Eigen::Vector3d damping = Eigen::Vector3d::Zero();
  Eigen::Vector3d actuator = Eigen::Vector3d::Zero();  // scene's constant force/moment
  Eigen::Vector3d preload = Eigen::Vector3d::Zero();   // solved (ERRATA 13)
  Eigen::Vector3d free_vector_m = Eigen::Vector3d::Zero();  // d0, in body1's frame
};

struct Model {
  std::string name;
  std::string source_path;
  Track track;
  double speed_m_per_s = 0.0;
  double gravity_m_per_s2 = 9.81;
  double reference_arc_length_m = 0.0;
  std::vector<ModelBody> bodies;
  std::vector<ModelContact> contacts;
  std::vector<ModelElement> elements;
  int n_coordinates = 0;  // free coordinates; the state has 2 n_coordinates entries
  // For each free coordinate: (body, coordinate index 0..5).
  std::vector<std::pair<int, int>> coordinate_of_state;

  explicit Model(const TrackSpec& track_spec) : track(track_spec) {}

  int state_size() const { return 2 * n_coordinates; }
  double arc_length_of(int body, double t_s) const {
    return reference_arc_length_m + bodies[body].track_offset_m + speed_m_per_s * t_s;
  }
  int find_body(const std::string& body_name) const;  // -1 if absent
  // Human-readable name of state entry i ("wheelset1.y_m", "wheelset1.y_m/s").
  std::string state_name(int i) const;
  // Initial state from the scene's initial offsets and rates.
  Eigen::VectorXd initial_state() const;
  // All six coordinates and rates of every body at time t from a state.
  void full_coordinates(double t_s, const Eigen::VectorXd& x, Eigen::MatrixXd& q6,
                        Eigen::MatrixXd& qd6) const;
};

// Resolve a validated scene into a model. Throws std::invalid_argument on
// inconsistencies the loader cannot see.
Model build_model(const SceneSpec& scene);

}  // namespace railstab
