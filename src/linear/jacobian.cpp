#include "linear/jacobian.hpp"

#include "model/equations_of_motion.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace railstab {

Eigen::MatrixXd rhs_jacobian_ad(const Model& model, double speed_m_per_s, double t_s,
                                const Eigen::VectorXd& x, ForceSelection forces) {
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
