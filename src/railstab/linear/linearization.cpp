#include <railstab/linear/linearization.hpp>

#include <railstab/linear/jacobian.hpp>
#include <railstab/model/equations_of_motion.hpp>

#include <sstream>
#include <stdexcept>

namespace railstab {

namespace {

// A position whose column is exactly zero is cyclic: drop it (its row only
// says d q/dt = u and feeds nothing back).
template <class ColumnIsNonZero>
void keep_non_cyclic(const Model& model, ColumnIsNonZero&& nonzero, LinearModel& lin) {
  for (int k = 0; k < model.state_size(); ++k) {
    if (model.is_position(k) && !nonzero(k)) {
      lin.removed_states.push_back(model.state_name(k));
    } else {
      lin.kept_states.push_back(k);
      lin.state_names.push_back(model.state_name(k));
    }
  }
}

}  // namespace

LinearModel linearize(const Model& model, double speed_m_per_s, const Eigen::VectorXd& x,
                      const LinearizationOptions& options) {
  const int n = model.n_coordinates;
  LinearModel lin;
  const Eigen::VectorXd acc =
      rhs(model, speed_m_per_s, options.time_s, x).tail(model.state_size() - n);
  Eigen::Index worst = 0;
  lin.equilibrium_residual = acc.size() > 0 ? acc.cwiseAbs().maxCoeff(&worst) : 0.0;
  if (lin.equilibrium_residual > options.max_equilibrium_residual) {
    std::ostringstream msg;
    msg << "cannot linearise scene '" << model.name << "': the point is not an equilibrium ("
        << model.state_name(n + int(worst)) << " acceleration " << lin.equilibrium_residual
        << " > " << options.max_equilibrium_residual << ")";
    throw std::runtime_error(msg.str());
  }
  if (options.jacobian_plan &&
      (options.jacobian_plan->rows.size() != size_t(model.state_size()) ||
       options.jacobian_plan->columns.size() != size_t(model.state_size())))
    throw std::invalid_argument("linearize: options.jacobian_plan is not the whole Jacobian's "
                                "plan of this model (use plan_rhs_jacobian(model))");
  const RhsJacobianPlan own_plan = options.jacobian_plan ? RhsJacobianPlan{} : plan_rhs_jacobian(model);
  const RhsJacobianPlan& plan = options.jacobian_plan ? *options.jacobian_plan : own_plan;
  if (options.sparse) {
    const Eigen::SparseMatrix<double> full =
        rhs_jacobian_ad_sparse(model, plan, speed_m_per_s, options.time_s, x);
    keep_non_cyclic(model, [&](int k) { return full.col(k).nonZeros() > 0; }, lin);
    // Reduced matrix: kept rows and columns, renumbered.
    std::vector<int> new_index(std::size_t(model.state_size()), -1);
    for (std::size_t i = 0; i < lin.kept_states.size(); ++i) new_index[std::size_t(lin.kept_states[i])] = int(i);
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(std::size_t(full.nonZeros()));
    for (int k = 0; k < full.outerSize(); ++k)
      for (Eigen::SparseMatrix<double>::InnerIterator it(full, k); it; ++it) {
        const int r = new_index[std::size_t(it.row())], c = new_index[std::size_t(it.col())];
        if (r >= 0 && c >= 0) entries.emplace_back(r, c, it.value());
      }
    const int m = lin.states();
    lin.A_sparse.resize(m, m);
    lin.A_sparse.setFromTriplets(entries.begin(), entries.end());
    lin.norm_A = lin.A_sparse.norm();
    return lin;
  }
  const Eigen::MatrixXd full = rhs_jacobian_ad(model, plan, speed_m_per_s, options.time_s, x);
  keep_non_cyclic(model, [&](int k) { return full.col(k).cwiseAbs().maxCoeff() != 0.0; }, lin);
  const int m = lin.states();
  lin.A.resize(m, m);
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) lin.A(i, j) = full(lin.kept_states[i], lin.kept_states[j]);
  lin.norm_A = lin.A.norm();
  return lin;
}

}  // namespace railstab
