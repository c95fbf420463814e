#pragma once
// Mechanical energy of the model in the fixed frame W: kinetic energy of all
// bodies, gravitational potential and the elastic potential of the force
// elements. Used to check conservation (no damping, no creep) in tests.
//
// Kinetic energy is measured by an observer moving at a constant velocity
// (W itself by default). Elements anchored to a track frame that moves at V
// do work in W; on tangent track the frame moving with the track is inertial
// and the energy measured there is conserved.
#include <railstab/model/model.hpp>

#include <Eigen/Dense>

namespace railstab {

struct EnergyParts {
  double kinetic_J = 0.0, gravity_J = 0.0, elastic_J = 0.0;
  double contact_J = 0.0;  // Hertz: integral of K delta^1.5 = 0.4 N delta per wheel
  double total() const { return kinetic_J + gravity_J + elastic_J + contact_J; }
};

EnergyParts mechanical_energy(const Model& model, double speed_m_per_s, double t_s,
                              const Eigen::VectorXd& x,
                              const Eigen::Vector3d& observer_velocity_W = Eigen::Vector3d::Zero());

}  // namespace railstab
