#pragma once
// Jacobian of the right-hand side, df/dx, by forward-mode automatic
// differentiation, without truncation error.
//
// Coloured (the product path): the pattern of df/dx comes from the model's
// structure and its columns are coloured so that columns of one colour share
// no row (linear/jacobian_pattern.hpp). Each colour is one AD direction,
// seeded with a 1 in every column of that colour; a row's derivative in that
// direction is then its entry in the one column of that colour it depends on.
// kAdChunk colours per evaluation: ceil(colours / kAdChunk) evaluations
// instead of ceil(n / kAdChunk). Every entry is computed by the same lane
// arithmetic as with one column per direction, so the result equals the
// dense AD Jacobian bit for bit (tests/linear/test_jacobian_pattern.cpp).
//
// Dense AD (one direction per column) and central differences are kept as
// references for tests and benchmarks (never used in the product path).
#include <railstab/model/equations_of_motion.hpp>

#include <railstab/linear/jacobian_pattern.hpp>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <functional>
#include <vector>

namespace railstab {

// The whole Jacobian (all rows, all columns).
RhsJacobianPlan plan_rhs_jacobian(const Model& model);
// Rows `rows` of f with respect to columns `columns` of x (e.g. the
// equilibrium equations with respect to its unknowns). Throws
// std::invalid_argument for an index outside the state or a repeated column.
RhsJacobianPlan plan_rhs_jacobian(const Model& model, std::vector<int> rows,
                                  std::vector<int> columns);

// The coloured AD Jacobian: plan.rows.size() x plan.columns.size(), entry
// (i, j) = d f(rows[i]) / d x(columns[j]). `plan` must come from `model`.
Eigen::MatrixXd rhs_jacobian_ad(const Model& model, const RhsJacobianPlan& plan,
                                double speed_m_per_s, double t_s, const Eigen::VectorXd& x,
                                ForceSelection forces = ForceSelection::all);

// The same entries stored sparse (only the non-zeros of the pattern): for
// large models (trains) where the dense matrix would be mostly zeros.
Eigen::SparseMatrix<double> rhs_jacobian_ad_sparse(const Model& model, const RhsJacobianPlan& plan,
                                                   double speed_m_per_s, double t_s,
                                                   const Eigen::VectorXd& x,
                                                   ForceSelection forces = ForceSelection::all);

// The same AD passes handing every entry (i, j) of the plan's pattern, zero
// or not, to put(i, j, value): for callers that keep their own storage (the
// time domain's sparse Newton matrix, integrate/sparse_newton.hpp).
void rhs_jacobian_ad_entries(const Model& model, const RhsJacobianPlan& plan,
                             double speed_m_per_s, double t_s, const Eigen::VectorXd& x,
                             ForceSelection forces,
                             const std::function<void(int, int, double)>& put);

// The whole coloured AD Jacobian (plans on every call: hot loops keep a plan).
Eigen::MatrixXd rhs_jacobian_ad(const Model& model, double speed_m_per_s, double t_s,
                                const Eigen::VectorXd& x,
                                ForceSelection forces = ForceSelection::all);

// Reference: AD with one direction per column, kAdChunk columns per
// evaluation (the product path before the colouring).
Eigen::MatrixXd rhs_jacobian_ad_dense(const Model& model, double speed_m_per_s, double t_s,
                                      const Eigen::VectorXd& x,
                                      ForceSelection forces = ForceSelection::all);

// Reference implementations for tests/benchmarks only.
Eigen::MatrixXd rhs_jacobian_central_difference(const Model& model, double speed_m_per_s, double t_s,
                                                const Eigen::VectorXd& x);
Eigen::MatrixXd rhs_jacobian_forward_difference(const Model& model, double speed_m_per_s, double t_s,
                                                const Eigen::VectorXd& x);

}  // namespace railstab
