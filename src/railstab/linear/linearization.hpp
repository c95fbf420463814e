#pragma once
// Exact linearisation about an equilibrium: A = df/dx by forward-mode AD.
//
// Like Drake's Linearize, it refuses a point that is not an equilibrium
// within a tolerance. Coordinates whose Jacobian column is exactly zero
// (the spin angle of an axisymmetric wheelset, ERRATA 11a, or any other
// cyclic coordinate) are removed together with their row: each removal drops
// one exact zero eigenvalue and nothing else. The removal is reported.
#include <railstab/linear/jacobian_pattern.hpp>
#include <railstab/model/model.hpp>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <string>
#include <type_traits>
#include <vector>

namespace railstab {

struct LinearModel {
  // The reduced state matrix, dense (A) or, when LinearizationOptions::sparse
  // asked for it, sparse (A_sparse, and A left empty). A speed sweep may
  // release both once the eigenvalues are known (stability/speed_analysis).
  Eigen::MatrixXd A;
  Eigen::SparseMatrix<double> A_sparse;
  double norm_A = 0.0;                    // Frobenius norm of the reduced matrix
  std::vector<int> kept_states;           // indices into the full state
  std::vector<std::string> state_names;   // of the kept states
  std::vector<std::string> removed_states;  // cyclic coordinates dropped
  double equilibrium_residual = 0.0;      // max |acceleration| (and internal rate) at the point
  int states() const { return int(kept_states.size()); }

  LinearModel() = default;
  LinearModel(const LinearModel&) = default;
  LinearModel& operator=(const LinearModel&) = default;
  // Eigen 3.4's SparseMatrix has no move constructor (moving one copies it,
  // and a copy may throw), so without these a LinearModel, and everything
  // holding one, is not nothrow-movable and std::vector copies its elements
  // when it grows: a speed sweep copied every StabilityPoint (modes,
  // vectors, shapes). Swapping the sparse matrix moves it without throwing.
  LinearModel(LinearModel&& other) noexcept { *this = std::move(other); }
  LinearModel& operator=(LinearModel&& other) noexcept {
    A = std::move(other.A);
    A_sparse.swap(other.A_sparse);
    norm_A = other.norm_A;
    kept_states = std::move(other.kept_states);
    state_names = std::move(other.state_names);
    removed_states = std::move(other.removed_states);
    equilibrium_residual = other.equilibrium_residual;
    return *this;
  }
};
static_assert(std::is_nothrow_move_constructible_v<LinearModel>);

struct LinearizationOptions {
  double time_s = 0.0;
  double max_equilibrium_residual = 1e-6;  // m/s^2 or rad/s^2
  // The whole Jacobian's plan, plan_rhs_jacobian(model), for callers that
  // linearise many times on one model. nullptr: planned per call.
  const RhsJacobianPlan* jacobian_plan = nullptr;
  // Store A sparse (A_sparse) instead of dense: the same entries.
  bool sparse = false;
};

// Throws std::runtime_error naming the worst residual when x is not an
// equilibrium.
LinearModel linearize(const Model& model, double speed_m_per_s, const Eigen::VectorXd& x,
                      const LinearizationOptions& options = {});

}  // namespace railstab
