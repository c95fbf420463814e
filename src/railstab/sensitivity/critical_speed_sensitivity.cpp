#include <railstab/sensitivity/critical_speed_sensitivity.hpp>

#include <railstab/equilibrium/equilibrium.hpp>
#include <railstab/linear/linearization.hpp>
#include <railstab/model/equations_of_motion.hpp>
#include <railstab/sensitivity/parameter_derivative.hpp>
#include <railstab/setup/build_model.hpp>

#include <railstab/linalg/dense_decompositions.hpp>

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

}  // namespace

CriticalSpeedSensitivities critical_speed_sensitivities(const SceneSpec& scene, double Vc,
                                                        double hunting_frequency_hz,
                                                        std::vector<std::string> keys,
                                                        const CriticalSpeedSensitivityOptions& options) {
  if (keys.empty()) keys = parameter_keys(scene);
  CriticalSpeedSensitivities out;
  out.critical_speed_m_per_s = Vc;
  const std::complex<double> target(0.0, 2.0 * std::numbers::pi * hunting_frequency_hz);

  // d Re lambda / dV exactly: V as the parameter (kSpeedParameter).
  const StateMatrixDerivative dV = state_matrix_derivative(scene, Vc, kSpeedParameter);
  const auto [lambda, v0] = nearest_eigenpair(dV.linear.A, target);
  out.eigenvalue = lambda;
  out.real_part_speed_derivative = eigenvalue_derivative(dV.linear.A, dV.A_derivative, lambda, v0).real();
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
