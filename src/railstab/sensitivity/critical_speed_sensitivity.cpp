#include <railstab/sensitivity/critical_speed_sensitivity.hpp>

#include <railstab/equilibrium/equilibrium.hpp>
#include <railstab/linear/linearization.hpp>
#include <railstab/model/equations_of_motion.hpp>
#include <railstab/sensitivity/parameter_derivative.hpp>
#include <railstab/setup/build_model.hpp>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace railstab {

namespace {

// The eigenpair of A nearest to `target`.
std::pair<std::complex<double>, Eigen::VectorXcd> nearest_eigenpair(const Eigen::MatrixXd& A,
                                                                    std::complex<double> target) {
  const Eigen::EigenSolver<Eigen::MatrixXd> solver(A);
  Eigen::Index best = 0;
  (solver.eigenvalues().array() - target).abs().minCoeff(&best);
  return {solver.eigenvalues()(best), solver.eigenvectors().col(best)};
}

// The state matrix at speed V (the analyses' equilibrium and linearisation).
Eigen::MatrixXd state_matrix_at(const SceneSpec& scene, double V) {
  SceneSpec spec = scene;
  spec.speed_m_per_s = V;
  const Model model = build_model(spec);
  const Eigen::VectorXd x = solve_equilibrium(model, V, lowered_nominal_state(model, V)).state;
  return linearize(model, V, x).A;
}

}  // namespace

CriticalSpeedSensitivities critical_speed_sensitivities(const SceneSpec& scene, double Vc,
                                                        double hunting_frequency_hz,
                                                        std::vector<std::string> keys,
                                                        const CriticalSpeedSensitivityOptions& options) {
  if (keys.empty()) keys = parameter_keys(scene);
  CriticalSpeedSensitivities out;
  out.critical_speed_m_per_s = Vc;
  const std::complex<double> target(0.0, 2.0 * std::numbers::pi * hunting_frequency_hz);

  // d Re lambda / dV by central difference, the eigenvalue followed by nearness.
  const double h = options.speed_step_m_per_s;
  const Eigen::MatrixXd A0 = state_matrix_at(scene, Vc);
  const auto [lambda, v0] = nearest_eigenpair(A0, target);
  out.eigenvalue = lambda;
  const std::complex<double> up = nearest_eigenpair(state_matrix_at(scene, Vc + h), lambda).first;
  const std::complex<double> down = nearest_eigenpair(state_matrix_at(scene, Vc - h), lambda).first;
  out.real_part_speed_derivative = (up.real() - down.real()) / (2.0 * h);
  if (!(std::abs(out.real_part_speed_derivative) > 0.0) || !std::isfinite(out.real_part_speed_derivative))
    throw std::runtime_error("critical-speed sensitivity: the hunting eigenvalue's real part does not "
                             "change with speed at " + std::to_string(Vc) + " m/s (no crossing there)");

  for (const std::string& key : keys) {
    const StateMatrixDerivative d = state_matrix_derivative(scene, Vc, key);
    // The same eigenpair, from the same state matrix the derivative belongs to.
    const auto [l, v] = nearest_eigenpair(d.linear.A, lambda);
    ParameterSensitivity s;
    s.key = key;
    s.value = d.parameter_value;
    s.eigenvalue_derivative = eigenvalue_derivative(d.linear.A, d.A_derivative, l, v);
    s.critical_speed_derivative = -s.eigenvalue_derivative.real() / out.real_part_speed_derivative;
    s.elasticity = s.value / Vc * s.critical_speed_derivative;
    out.parameters.push_back(std::move(s));
  }
  std::stable_sort(out.parameters.begin(), out.parameters.end(),
                   [](const ParameterSensitivity& a, const ParameterSensitivity& b) {
                     return std::abs(a.elasticity) > std::abs(b.elasticity);
                   });
  return out;
}

}  // namespace railstab
