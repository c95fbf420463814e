#include <railstab/verify/damped_sinusoid_fit.hpp>

#include <cmath>
#include <stdexcept>

namespace railstab {

namespace {

// Linear least squares for (a, b, c) at fixed sigma, omega.
Eigen::Vector3d linear_coefficients(const std::vector<double>& t, const std::vector<double>& y,
                                    double sigma, double omega) {
  const Eigen::Index n = Eigen::Index(t.size());
  Eigen::MatrixXd M(n, 3);
  Eigen::VectorXd rhs(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double e = std::exp(sigma * t[i]);
    M(i, 0) = e * std::cos(omega * t[i]);
    M(i, 1) = e * std::sin(omega * t[i]);
    M(i, 2) = 1.0;
    rhs(i) = y[i];
  }
  return M.colPivHouseholderQr().solve(rhs);
}

double rms(const Eigen::VectorXd& r) { return std::sqrt(r.squaredNorm() / double(r.size())); }

}  // namespace

DampedSinusoid fit_damped_sinusoid(const std::vector<double>& t, const std::vector<double>& y,
                                   double sigma_guess, double omega_guess) {
  if (t.size() != y.size() || t.size() < 8)
    throw std::invalid_argument("damped-sinusoid fit: need at least 8 samples of equal length");
  const Eigen::Index n = Eigen::Index(t.size());
  // Times relative to the window start keep exp(sigma t) of order one.
  const double t0 = t.front();
  std::vector<double> tau(t.size());
  for (size_t i = 0; i < t.size(); ++i) tau[i] = t[i] - t0;

  Eigen::Matrix<double, 5, 1> p;  // sigma, omega, a, b, c
  const Eigen::Vector3d abc = linear_coefficients(tau, y, sigma_guess, omega_guess);
  p << sigma_guess, omega_guess, abc(0), abc(1), abc(2);
  auto residual = [&](const Eigen::Matrix<double, 5, 1>& q, Eigen::VectorXd& r,
                      Eigen::MatrixXd* J) {
    r.resize(n);
    if (J) J->resize(n, 5);
    for (Eigen::Index i = 0; i < n; ++i) {
      const double e = std::exp(q(0) * tau[i]), co = std::cos(q(1) * tau[i]),
                   si = std::sin(q(1) * tau[i]);
      const double osc = q(2) * co + q(3) * si;
      r(i) = e * osc + q(4) - y[i];
      if (J) {
        (*J)(i, 0) = tau[i] * e * osc;
        (*J)(i, 1) = e * tau[i] * (-q(2) * si + q(3) * co);
        (*J)(i, 2) = e * co;
        (*J)(i, 3) = e * si;
        (*J)(i, 4) = 1.0;
      }
    }
  };
  Eigen::VectorXd r;
  Eigen::MatrixXd J;
  residual(p, r, &J);
  double cost = r.squaredNorm();
  DampedSinusoid fit;
  double lambda = 1e-3;  // Levenberg-Marquardt damping
  for (int it = 0; it < 200; ++it) {
    fit.iterations = it + 1;
    const Eigen::MatrixXd JtJ = J.transpose() * J;
    const Eigen::VectorXd g = J.transpose() * r;
    Eigen::MatrixXd A = JtJ;
    A.diagonal() += lambda * JtJ.diagonal().cwiseMax(1e-300);
    const Eigen::Matrix<double, 5, 1> step = A.ldlt().solve(-g);
    const Eigen::Matrix<double, 5, 1> trial = p + step;
    Eigen::VectorXd r_trial;
    residual(trial, r_trial, nullptr);
    const double trial_cost = r_trial.squaredNorm();
    if (trial_cost < cost) {
      const bool converged = cost - trial_cost <= 1e-14 * cost ||
                             step.head<2>().norm() <= 1e-12 * (1.0 + p.head<2>().norm());
      p = trial;
      cost = trial_cost;
      residual(p, r, &J);
      lambda = std::max(lambda / 10.0, 1e-12);
      if (converged) break;
    } else {
      lambda *= 10.0;
      if (lambda > 1e12) break;  // no further descent: at the minimum
    }
  }
  if (!std::isfinite(cost)) throw std::runtime_error("damped-sinusoid fit diverged");
  fit.sigma_per_s = p(0);
  fit.omega_rad_s = std::abs(p(1));
  fit.a = p(2);
  fit.b = p(3);
  fit.c = p(4);
  fit.rms_residual = rms(r);
  Eigen::VectorXd centred(n);
  for (Eigen::Index i = 0; i < n; ++i) centred(i) = y[i] - p(4);
  fit.rms_signal = rms(centred);
  return fit;
}

}  // namespace railstab
