#pragma once
// Scenes built in code for the integrator tests.
#include "model/scene_builders.hpp"
#include <railstab/scene/scene_spec.hpp>

#include <cmath>
#include <numbers>

namespace railstab::test {

// One rigid body free in y only, on a lateral spring-damper to its track
// frame at its centre of mass, on tangent track (the track frame moves at
// constant V, so it is inertial): exactly m y'' + c y' + k y = 0.
struct LateralOscillator {
  double mass_kg = 1000.0;  // rigid_body()
  double frequency_hz = 2.0;
  double damping_ratio = 0.05;
  double y0_m = 0.01;

  double omega() const { return 2.0 * std::numbers::pi * frequency_hz; }
  double stiffness() const { return mass_kg * omega() * omega(); }
  double damping() const { return 2.0 * damping_ratio * std::sqrt(stiffness() * mass_kg); }

  SceneSpec scene() const {
    SceneSpec s;
    s.name = "lateral_oscillator";
    s.speed_m_per_s = 10.0;
    s.reference_arc_length_m = 10.0;
    s.track = straight_track();
    s.preload = PreloadMode::none;
    BodySpec b = rigid_body("body", 0.0, 1.0);
    b.free = {false, true, false, false, false, false};
    b.initial_offset = {0.0, y0_m, 0.0, 0.0, 0.0, 0.0};
    s.bodies.push_back(b);
    s.elements.push_back(spring("lateral", kTrackBodyName, "body", {0.0, 0.0, 1.0},
                                {0.0, 0.0, 0.0}, {0.0, stiffness(), 0.0},
                                {0.0, damping(), 0.0}));
    return s;
  }

  // Free response from y(0) = y0, y'(0) = 0.
  double exact(double t) const {
    const double z = damping_ratio, w = omega();
    const double wd = w * std::sqrt(1.0 - z * z);
    return std::exp(-z * w * t) * y0_m * (std::cos(wd * t) + z * w / wd * std::sin(wd * t));
  }
};

}  // namespace railstab::test
