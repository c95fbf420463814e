#pragma once
// Time integration of the nonlinear model on SUNDIALS.
//
// Default: CVODE BDF (variable order 1-5) with a dense Newton solver and the
// exact AD Jacobian: the wheel-rail contact is stiff (Hertz vertical modes
// near 200 Hz, creep damping up to f/(mV) ~ 1e3-1e4 1/s at low speed).
#include "model/model.hpp"

#include <Eigen/Dense>

#include <functional>
#include <string>
#include <vector>

namespace railstab {

enum class IntegratorKind { cvode_bdf, cvode_adams };

struct IntegrationOptions {
  IntegratorKind kind = IntegratorKind::cvode_bdf;
  double t_start_s = 0.0;
  double t_end_s = 1.0;
  double output_interval_s = 0.01;
  double relative_tolerance = 1e-6;
  double absolute_tolerance = 1e-9;
  long max_steps = 5000000;
  // Called about once per wall-clock second with the current time.
  std::function<void(double t_s)> progress;
};

struct IntegrationStats {
  long steps = 0, rhs_evaluations = 0, jacobian_evaluations = 0, error_test_failures = 0,
       nonlinear_failures = 0;
  double wall_seconds = 0.0;
};

struct Trajectory {
  std::vector<double> times_s;
  std::vector<Eigen::VectorXd> states;
  IntegrationStats stats;
  // Set when the run ended before t_end at a validity limit, e.g.
  // "wheelset1 lateral shift reached the flange clearance 0.0075 m at t = 3.21 s".
  std::string stopped_early;
};

// Throws std::runtime_error with SUNDIALS' reason and the time reached.
Trajectory integrate(const Model& model, const Eigen::VectorXd& x0,
                     const IntegrationOptions& options);

std::string integrator_name(IntegratorKind kind);

}  // namespace railstab
