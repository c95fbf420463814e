#include "linear/jacobian.hpp"

#include "model/equations_of_motion.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace railstab {

Eigen::MatrixXd rhs_jacobian_ad(const Model& model, double t_s, const Eigen::VectorXd& x) {
  const int n = int(x.size());
  const auto frames = track_frames_at(model, t_s);
  Eigen::MatrixXd jac(n, n);
  VecX<AdScalar> x_ad(n), f_ad;
  for (int first = 0; first < n; first += kAdChunk) {
    const int width = std::min(kAdChunk, n - first);
    for (int i = 0; i < n; ++i) {
      x_ad(i).value() = x(i);
      x_ad(i).derivatives().setZero();
      if (i >= first && i < first + width) x_ad(i).derivatives()(i - first) = 1.0;
    }
    evaluate_rhs<AdScalar>(model, t_s, frames, x_ad, f_ad);
    for (int r = 0; r < n; ++r)
      jac.block(r, first, 1, width) = f_ad(r).derivatives().head(width).transpose();
  }
  return jac;
}

namespace {
double step_for(double value, double relative) { return relative * std::max(1.0, std::abs(value)); }
}  // namespace

Eigen::MatrixXd rhs_jacobian_central_difference(const Model& model, double t_s,
                                                const Eigen::VectorXd& x) {
  const int n = int(x.size());
  const auto frames = track_frames_at(model, t_s);
  const double rel = std::cbrt(std::numeric_limits<double>::epsilon());
  Eigen::MatrixXd jac(n, n);
  Eigen::VectorXd xp = x, xm = x, fp, fm;
  for (int j = 0; j < n; ++j) {
    const double h = step_for(x(j), rel);
    xp(j) = x(j) + h;
    xm(j) = x(j) - h;
    evaluate_rhs<double>(model, t_s, frames, xp, fp);
    evaluate_rhs<double>(model, t_s, frames, xm, fm);
    jac.col(j) = (fp - fm) / (xp(j) - xm(j));
    xp(j) = xm(j) = x(j);
  }
  return jac;
}

Eigen::MatrixXd rhs_jacobian_forward_difference(const Model& model, double t_s,
                                                const Eigen::VectorXd& x) {
  const int n = int(x.size());
  const auto frames = track_frames_at(model, t_s);
  const double rel = std::sqrt(std::numeric_limits<double>::epsilon());
  Eigen::MatrixXd jac(n, n);
  Eigen::VectorXd xp = x, f0, fp;
  evaluate_rhs<double>(model, t_s, frames, x, f0);
  for (int j = 0; j < n; ++j) {
    const double h = step_for(x(j), rel);
    xp(j) = x(j) + h;
    evaluate_rhs<double>(model, t_s, frames, xp, fp);
    jac.col(j) = (fp - f0) / (xp(j) - x(j));
    xp(j) = x(j);
  }
  return jac;
}

}  // namespace railstab
