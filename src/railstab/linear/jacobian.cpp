#include <railstab/linear/jacobian.hpp>

#include <railstab/model/equations_of_motion.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace railstab {

namespace {

void require_state_size(const Model& model, const Eigen::VectorXd& x, const char* who) {
  if (x.size() != model.state_size())
    throw std::invalid_argument(std::string(who) + ": state has " + std::to_string(x.size()) +
                                " entries, model '" + model.name + "' has " +
                                std::to_string(model.state_size()) + " states");
}

std::vector<int> all_indices(int n) {
  std::vector<int> v(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) v[std::size_t(i)] = i;
  return v;
}

}  // namespace

RhsJacobianPlan plan_rhs_jacobian(const Model& model) {
  return plan_rhs_jacobian(model, all_indices(model.state_size()),
                           all_indices(model.state_size()));
}

RhsJacobianPlan plan_rhs_jacobian(const Model& model, std::vector<int> rows,
                                  std::vector<int> columns) {
  RhsJacobianPlan plan;
  plan.pattern = sub_pattern(rhs_jacobian_pattern(model), rows, columns);
  plan.rows = std::move(rows);
  plan.columns = std::move(columns);
  plan.colouring = colour_columns(plan.pattern);
  return plan;
}

namespace {

// The coloured AD passes: put(i, j, value) for every entry (i, j) of the
// plan's pattern. Dense and sparse results share this, so they are the same
// numbers.
template <class Put>
void coloured_passes(const Model& model, const RhsJacobianPlan& plan, double speed_m_per_s,
                     double t_s, const Eigen::VectorXd& x, ForceSelection forces, Put&& put) {
  require_state_size(model, x, "rhs_jacobian_ad");
  const int n = int(x.size());
  const int n_rows = int(plan.rows.size()), n_cols = int(plan.columns.size());
  if (plan.pattern.rows != n_rows || plan.pattern.cols != n_cols)
    throw std::invalid_argument("rhs_jacobian_ad: plan's pattern does not match its rows/columns");
  for (int c : plan.columns)
    if (c < 0 || c >= n) throw std::invalid_argument("rhs_jacobian_ad: plan is for another model");
  const std::vector<int>& colour = plan.colouring.colour_of_column;
  Workspace<AdScalar> ws(model);
  VecX<AdScalar> x_ad(n), f_ad;
  for (int i = 0; i < n; ++i) x_ad(i) = AdScalar(x(i), AdDerivatives::Zero());
  for (int first = 0; first < plan.colouring.colours; first += kAdChunk) {
    // Direction d of this evaluation is colour first + d: a 1 in each of its columns.
    for (int j = 0; j < n_cols; ++j) {
      AdDerivatives& d = x_ad(plan.columns[std::size_t(j)]).derivatives();
      d.setZero();
      const int slot = colour[std::size_t(j)] - first;
      if (slot >= 0 && slot < kAdChunk) d(slot) = 1.0;
    }
    evaluate_rhs<AdScalar>(model, ws, t_s, speed_m_per_s, x_ad, f_ad, nullptr, forces);
    for (int i = 0; i < n_rows; ++i) {
      const AdDerivatives& d = f_ad(plan.rows[std::size_t(i)]).derivatives();
      for (int j : plan.pattern.columns_of_row[std::size_t(i)]) {
        const int slot = colour[std::size_t(j)] - first;
        if (slot >= 0 && slot < kAdChunk) put(i, j, d(slot));
      }
    }
  }
}

}  // namespace

Eigen::MatrixXd rhs_jacobian_ad(const Model& model, const RhsJacobianPlan& plan,
                                double speed_m_per_s, double t_s, const Eigen::VectorXd& x,
                                ForceSelection forces) {
  Eigen::MatrixXd jac = Eigen::MatrixXd::Zero(Eigen::Index(plan.rows.size()),
                                              Eigen::Index(plan.columns.size()));
  coloured_passes(model, plan, speed_m_per_s, t_s, x, forces,
                  [&](int i, int j, double v) { jac(i, j) = v; });
  return jac;
}

void rhs_jacobian_ad_entries(const Model& model, const RhsJacobianPlan& plan,
                             double speed_m_per_s, double t_s, const Eigen::VectorXd& x,
                             ForceSelection forces,
                             const std::function<void(int, int, double)>& put) {
  coloured_passes(model, plan, speed_m_per_s, t_s, x, forces, put);
}

Eigen::SparseMatrix<double> rhs_jacobian_ad_sparse(const Model& model, const RhsJacobianPlan& plan,
                                                   double speed_m_per_s, double t_s,
                                                   const Eigen::VectorXd& x,
                                                   ForceSelection forces) {
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(std::size_t(plan.pattern.nonzeros()));
  coloured_passes(model, plan, speed_m_per_s, t_s, x, forces, [&](int i, int j, double v) {
    if (v != 0.0) entries.emplace_back(i, j, v);
  });
  Eigen::SparseMatrix<double> jac(Eigen::Index(plan.rows.size()), Eigen::Index(plan.columns.size()));
  jac.setFromTriplets(entries.begin(), entries.end());
  return jac;
}

Eigen::MatrixXd rhs_jacobian_ad(const Model& model, double speed_m_per_s, double t_s,
                                const Eigen::VectorXd& x, ForceSelection forces) {
  return rhs_jacobian_ad(model, plan_rhs_jacobian(model), speed_m_per_s, t_s, x, forces);
}

Eigen::MatrixXd rhs_jacobian_ad_dense(const Model& model, double speed_m_per_s, double t_s,
                                      const Eigen::VectorXd& x, ForceSelection forces) {
  require_state_size(model, x, "rhs_jacobian_ad_dense");
  const int n = int(x.size());
  Workspace<AdScalar> ws(model);
  Eigen::MatrixXd jac(n, n);
  VecX<AdScalar> x_ad(n), f_ad;
  for (int first = 0; first < n; first += kAdChunk) {
    const int width = std::min(kAdChunk, n - first);
    for (int i = 0; i < n; ++i) {
      x_ad(i).value() = x(i);
      x_ad(i).derivatives().setZero();
      if (i >= first && i < first + width) x_ad(i).derivatives()(i - first) = 1.0;
    }
    evaluate_rhs<AdScalar>(model, ws, t_s, speed_m_per_s, x_ad, f_ad, nullptr, forces);
    for (int r = 0; r < n; ++r)
      jac.block(r, first, 1, width) = f_ad(r).derivatives().head(width).transpose();
  }
  return jac;
}

namespace {
// Difference step for state j. Positions are scaled to 1 mm / 1 mrad, not to
// their value: a wheelset's z is ~0.45 m but the Hertz law it feeds varies on
// the scale of the ~0.1 mm penetration. Rates are scaled to their value.
double step_for(const Model& model, const Eigen::VectorXd& x, int j, double relative) {
  if (model.is_position(j) || model.is_internal(j)) return relative * 1e-3;
  return relative * std::max(1.0, std::abs(x(j)));
}
}  // namespace

// Fourth-order central differences (5-point stencil), step eps^(1/5) scaled:
// truncation ~ (h/scale)^4 and round-off ~ eps/h both stay near 1e-10, which
// a plain central difference cannot reach for the stiff contact rows.
Eigen::MatrixXd rhs_jacobian_central_difference(const Model& model, double speed_m_per_s, double t_s,
                                                const Eigen::VectorXd& x) {
  const int n = int(x.size());
  Workspace<double> ws(model);
  const double rel = std::pow(std::numeric_limits<double>::epsilon(), 0.2);
  Eigen::MatrixXd jac(n, n);
  Eigen::VectorXd xs = x, f[4];
  const double offsets[4] = {-2.0, -1.0, 1.0, 2.0};
  for (int j = 0; j < n; ++j) {
    const double h = step_for(model, x, j, rel);
    for (int i = 0; i < 4; ++i) {
      xs(j) = x(j) + offsets[i] * h;
      evaluate_rhs<double>(model, ws, t_s, speed_m_per_s, xs, f[i]);
    }
    xs(j) = x(j);
    jac.col(j) = (f[0] - 8.0 * f[1] + 8.0 * f[2] - f[3]) / (12.0 * h);
  }
  return jac;
}

Eigen::MatrixXd rhs_jacobian_forward_difference(const Model& model, double speed_m_per_s, double t_s,
                                                const Eigen::VectorXd& x) {
  const int n = int(x.size());
  Workspace<double> ws(model);
  const double rel = std::sqrt(std::numeric_limits<double>::epsilon());
  Eigen::MatrixXd jac(n, n);
  Eigen::VectorXd xp = x, f0, fp;
  evaluate_rhs<double>(model, ws, t_s, speed_m_per_s, x, f0);
  for (int j = 0; j < n; ++j) {
    const double h = step_for(model, x, j, rel);
    xp(j) = x(j) + h;
    evaluate_rhs<double>(model, ws, t_s, speed_m_per_s, xp, fp);
    jac.col(j) = (fp - f0) / (xp(j) - x(j));
    xp(j) = x(j);
  }
  return jac;
}

}  // namespace railstab
