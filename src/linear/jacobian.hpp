#pragma once
// Jacobian of the right-hand side, df/dx, by forward-mode automatic
// differentiation: the state is seeded kAdChunk columns at a time with unit
// directions, so an n-state Jacobian costs ceil(n / kAdChunk) AD evaluations
// and no truncation error. Central differences are here only as the
// reference the tests and benchmarks compare against (5-point stencil) (never used in the
// product path).
#include "model/equations_of_motion.hpp"

#include <Eigen/Dense>

namespace railstab {

Eigen::MatrixXd rhs_jacobian_ad(const Model& model, double speed_m_per_s, double t_s,
                                const Eigen::VectorXd& x,
                                ForceSelection forces = ForceSelection::all);

// Reference implementations for tests/benchmarks only.
Eigen::MatrixXd rhs_jacobian_central_difference(const Model& model, double speed_m_per_s, double t_s,
                                                const Eigen::VectorXd& x);
Eigen::MatrixXd rhs_jacobian_forward_difference(const Model& model, double speed_m_per_s, double t_s,
                                                const Eigen::VectorXd& x);

}  // namespace railstab
