#include "linear/linearization.hpp"

#include "linear/jacobian.hpp"
#include "model/equations_of_motion.hpp"

#include <sstream>
#include <stdexcept>

namespace railstab {

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
  const Eigen::MatrixXd full =
      options.jacobian_plan
          ? rhs_jacobian_ad(model, *options.jacobian_plan, speed_m_per_s, options.time_s, x)
          : rhs_jacobian_ad(model, speed_m_per_s, options.time_s, x);
  // A position whose column is exactly zero is cyclic: drop it (its row only
  // says d q/dt = u and feeds nothing back).
  for (int k = 0; k < model.state_size(); ++k) {
    if (model.is_position(k) && full.col(k).cwiseAbs().maxCoeff() == 0.0) {
      lin.removed_states.push_back(model.state_name(k));
    } else {
      lin.kept_states.push_back(k);
      lin.state_names.push_back(model.state_name(k));
    }
  }
  const int m = int(lin.kept_states.size());
  lin.A.resize(m, m);
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) lin.A(i, j) = full(lin.kept_states[i], lin.kept_states[j]);
  return lin;
}

}  // namespace railstab
