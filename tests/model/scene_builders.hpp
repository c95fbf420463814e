#pragma once
// Small scenes built in code (independent of the TOML loader) for model tests.
#include <railstab/scene/scene_spec.hpp>

namespace railstab::test {

inline TrackSpec straight_track(double length_m = 5000.0) {
  TrackSpec t;
  t.segments.push_back({TrackSegmentKind::tangent, length_m, 0.0, 0.0});
  return t;
}

// Tangent, clothoid to radius R with cant ramp, then arc (the thesis layout).
inline TrackSpec curved_track(double radius_m, double cant_m, double start_heading_rad = 0.0,
                              double start_x_m = 0.0, double start_y_m = 0.0) {
  TrackSpec t;
  t.start_heading_rad = start_heading_rad;
  t.start_x_m = start_x_m;
  t.start_y_m = start_y_m;
  t.segments.push_back({TrackSegmentKind::tangent, 100.0, 0.0, 0.0});
  t.segments.push_back({TrackSegmentKind::clothoid, 100.0, 1.0 / radius_m, cant_m});
  t.segments.push_back({TrackSegmentKind::arc, 1000.0, 0.0, cant_m});
  return t;
}

inline BodySpec rigid_body(const std::string& name, double offset_m, double height_m) {
  BodySpec b;
  b.name = name;
  b.mass_kg = 1000.0;
  b.inertia_kg_m2 = Eigen::Vector3d(300.0, 500.0, 600.0);
  b.track_offset_m = offset_m;
  b.position_m = Eigen::Vector3d(0.0, 0.0, height_m);
  return b;
}

inline ElementSpec spring(const std::string& name, const std::string& b1, const std::string& b2,
                          Eigen::Vector3d p1, Eigen::Vector3d p2, Eigen::Vector3d k,
                          Eigen::Vector3d c = Eigen::Vector3d::Zero()) {
  SpringDamper3d<double> e;
  e.ends.name = name;
  e.ends.body1_name = b1;
  e.ends.body2_name = b2;
  e.ends.point1_m = p1;
  e.ends.point2_m = p2;
  e.stiffness_N_per_m = k;
  e.damping_N_s_per_m = c;
  return e;
}

// Two rigid bodies on springs: body "a" hangs from its track frame at four
// corners, body "b" sits on "a"; no damping, no contact. Anisotropic springs.
inline SceneSpec two_body_oscillator(const TrackSpec& track, double speed_m_per_s) {
  SceneSpec s;
  s.name = "two_body_oscillator";
  s.speed_m_per_s = speed_m_per_s;
  s.reference_arc_length_m = 150.0;
  s.track = track;
  s.preload = PreloadMode::none;
  s.bodies.push_back(rigid_body("a", 0.0, 1.0));
  s.bodies.push_back(rigid_body("b", -2.0, 2.0));
  for (double sx : {-1.0, 1.0})
    for (double sy : {-1.0, 1.0}) {
      s.elements.push_back(spring("ta", kTrackBodyName, "a", {sx, sy, 0.5}, {sx, sy, -0.5},
                                  {2e5, 3e5, 5e5}));
      s.elements.push_back(spring("ab", "a", "b", {sx - 1.0, sy, 0.5}, {sx + 1.0, sy, -0.5},
                                  {1e5, 1.5e5, 4e5}));
    }
  s.elements.push_back(spring("diag", "a", "b", {1.0, 0.5, 0.2}, {0.0, -0.5, 0.0}, {5e4, 7e4, 9e4}));
  return s;
}

// One thesis knife-edge wheelset (Table 5.1, 5.7) alone on `track`, free in
// y, z, roll, spin and yaw (x held: it moves with its track frame), no
// suspension: nothing damps its vertical bouncing on the Hertz contact.
inline SceneSpec lone_knife_edge_wheelset(double speed_m_per_s = 20.0,
                                          const TrackSpec& track = straight_track()) {
  SceneSpec s;
  s.name = "lone_wheelset";
  s.speed_m_per_s = speed_m_per_s;
  s.reference_arc_length_m = 50.0;
  s.track = track;
  s.preload = PreloadMode::none;
  ContactSpec c;
  c.name = "knife";
  s.contacts.push_back(c);
  BodySpec w;
  w.name = "wheelset";
  w.is_wheelset = true;
  w.mass_kg = 1500.0;
  w.inertia_kg_m2 = Eigen::Vector3d(799.35, 93.75, 799.35);
  w.position_m = Eigen::Vector3d(0.0, 0.0, 0.45);
  w.free = {false, true, true, true, true, true};
  w.contact = "knife";
  s.bodies.push_back(w);
  return s;
}

}  // namespace railstab::test
