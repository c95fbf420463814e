#include <railstab/nonlinear/flow_system.hpp>

#include <railstab/equilibrium/equilibrium.hpp>
#include <railstab/linear/jacobian.hpp>
#include <railstab/model/equations_of_motion.hpp>
#include <railstab/model/workspace.hpp>

#include <memory>
#include <stdexcept>

namespace railstab {

Eigen::VectorXd speed_derivative(const FlowSystem& system, const Eigen::VectorXd& x,
                                 double speed_m_per_s) {
  Eigen::VectorXd out;
  if (system.speed_derivative) {
    system.speed_derivative(x, speed_m_per_s, out);
    return out;
  }
  const double h = system.speed_difference_step_m_per_s;
  Eigen::VectorXd up, down;
  system.rhs(x, speed_m_per_s + h, up);
  system.rhs(x, speed_m_per_s - h, down);
  return (up - down) / (2.0 * h);
}

Eigen::VectorXd reduce_state(const std::vector<int>& reduced_states, const Eigen::VectorXd& full) {
  Eigen::VectorXd r(Eigen::Index(reduced_states.size()));
  for (size_t i = 0; i < reduced_states.size(); ++i) r(Eigen::Index(i)) = full(reduced_states[i]);
  return r;
}

Eigen::VectorXd embed_state(const Model& model, const std::vector<int>& reduced_states,
                            const Eigen::VectorXd& reduced) {
  if (reduced.size() != Eigen::Index(reduced_states.size()))
    throw std::invalid_argument("embed_state: reduced state has the wrong size");
  Eigen::VectorXd full = Eigen::VectorXd::Zero(model.state_size());
  for (size_t i = 0; i < reduced_states.size(); ++i) full(reduced_states[i]) = reduced(Eigen::Index(i));
  return full;
}

namespace {

// What the closures share: the model, its index maps, a workspace and the
// Jacobian's plan (made once).
struct ModelFlowData {
  ModelFlowData(const Model& m, double t, std::vector<int> kept)
      : model(&m), time_s(t), reduced(std::move(kept)), workspace(m),
        plan(plan_rhs_jacobian(m, reduced, reduced)), full(Eigen::VectorXd::Zero(m.state_size())),
        full_rate(m.state_size()) {}
  const Model* model;
  double time_s;
  std::vector<int> reduced;
  Workspace<double> workspace;
  RhsJacobianPlan plan;
  Eigen::VectorXd full, full_rate;

  void embed(const Eigen::VectorXd& x) {
    for (size_t i = 0; i < reduced.size(); ++i) full(reduced[i]) = x(Eigen::Index(i));
  }
};

}  // namespace

FlowSystem model_flow_system(const Model& model, double time_s, std::vector<int>* reduced_states) {
  std::vector<int> kept;
  for (int k = 0; k < model.state_size(); ++k)
    if (!is_spin_angle(model, k)) kept.push_back(k);
  if (reduced_states) *reduced_states = kept;
  auto data = std::make_shared<ModelFlowData>(model, time_s, kept);
  FlowSystem s;
  s.size = int(kept.size());
  for (int k : kept) s.state_names.push_back(model.state_name(k));
  s.rhs = [data](const Eigen::VectorXd& x, double V, Eigen::VectorXd& out) {
    data->embed(x);
    const VecXConstRef<double> xr(data->full);
    evaluate_rhs<double>(*data->model, data->workspace, data->time_s, V, xr, data->full_rate);
    out.resize(x.size());
    for (size_t i = 0; i < data->reduced.size(); ++i)
      out(Eigen::Index(i)) = data->full_rate(data->reduced[i]);
  };
  s.jacobian = [data](const Eigen::VectorXd& x, double V, Eigen::MatrixXd& out) {
    data->embed(x);
    out = rhs_jacobian_ad(*data->model, data->plan, V, data->time_s, data->full);
  };
  // df/dV: the speed enters through the creepages (V in their
  // denominators), the rolling-rate states and the track frame's motion;
  // smooth in V, so the central difference (FlowSystem) is accurate to
  // about 1e-9 relative with h = 1e-4 m/s at railway speeds.
  return s;
}

}  // namespace railstab
