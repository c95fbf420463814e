#include <railstab/nonlinear/variational_pass.hpp>

#include <railstab/integrate/dense_newton_matrix.hpp>
#include <railstab/integrate/eigen_dense_solver.hpp>
#include <railstab/nonlinear/cvodes_flow_support.hpp>

#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <string>

namespace railstab {

using flow_support::check;
using flow_support::guarded;
using flow_support::view;

void RecordedTrajectory::state_at(double t_s, Eigen::VectorXd& out) const {
  if (times_s.size() < 2) throw std::logic_error("RecordedTrajectory: fewer than two points");
  t_s = std::clamp(t_s, times_s.front(), times_s.back());
  // The step [t_k, t_k+1] that holds t.
  size_t k = size_t(std::upper_bound(times_s.begin(), times_s.end(), t_s) - times_s.begin());
  k = std::clamp<size_t>(k, 1, times_s.size() - 1) - 1;
  const double h = times_s[k + 1] - times_s[k], s = (t_s - times_s[k]) / h;
  const double s2 = s * s, s3 = s2 * s;
  const double h00 = 2.0 * s3 - 3.0 * s2 + 1.0, h10 = s3 - 2.0 * s2 + s, h01 = 3.0 * s2 - 2.0 * s3,
               h11 = s3 - s2;
  out = h00 * states[k] + (h10 * h) * rates[k] + h01 * states[k + 1] + (h11 * h) * rates[k + 1];
}

namespace {

// What the CVODES callbacks see: J and df/dV at the time CVODES asks for,
// evaluated once per time.
struct PassData {
  const FlowSystem* system = nullptr;
  const RecordedTrajectory* trajectory = nullptr;
  double speed = 0.0;
  Eigen::Index n = 0;
  Eigen::VectorXd x, dfdV;
  Eigen::MatrixXd J, Y, Ydot;
  bool valid = false;
  double t_cached = 0.0;
  long jacobian_evaluations = 0;
  std::string error;

  void evaluate_at(double t) {
    if (valid && t == t_cached) return;
    trajectory->state_at(t, x);
    system->jacobian(x, speed, J);
    if (!J.allFinite()) throw std::runtime_error("non-finite Jacobian entry");
    dfdV = speed_derivative(*system, x, speed);
    if (!dfdV.allFinite()) throw std::runtime_error("non-finite df/dV");
    t_cached = t, valid = true;
    ++jacobian_evaluations;
  }
};

// Y' = J Y + [0 | df/dV], Y column-major n x (n + 1).
int rhs_callback(double t, N_Vector y, N_Vector ydot, void* user) {
  auto& d = *static_cast<PassData*>(user);
  return guarded(d.error, [&] {
    d.evaluate_at(t);
    // Through Eigen-owned (aligned) copies: the product's vectorised kernel
    // then sums in the same order whatever the N_Vector's address, so a run
    // gives the same digits in every process.
    d.Y = Eigen::Map<const Eigen::MatrixXd>(N_VGetArrayPointer(y), d.n, d.n + 1);
    d.Ydot.noalias() = d.J * d.Y;
    d.Ydot.col(d.n) += d.dfdV;
    Eigen::Map<Eigen::MatrixXd>(N_VGetArrayPointer(ydot), d.n, d.n + 1) = d.Ydot;
    return 0;
  });
}

// The Newton matrix's J: the same n x n J for every column of Y.
int jacobian_callback(double t, N_Vector, N_Vector, SUNMatrix Jmat, void* user, N_Vector, N_Vector,
                      N_Vector) {
  auto& d = *static_cast<PassData*>(user);
  return guarded(d.error, [&] {
    d.evaluate_at(t);
    Eigen::Map<Eigen::MatrixXd>(SM_DATA_D(Jmat), d.n, d.n) = d.J;
    return 0;
  });
}

}  // namespace

VariationalResult integrate_variational_equations(const FlowSystem& system,
                                                  const RecordedTrajectory& trajectory,
                                                  double speed_m_per_s, const FlowOptions& options) {
  const Eigen::Index n = system.size;
  if (trajectory.times_s.size() < 2 || trajectory.states.size() != trajectory.times_s.size() ||
      trajectory.rates.size() != trajectory.times_s.size())
    throw std::invalid_argument("integrate_variational_equations: the trajectory has fewer than two steps");
  const double duration_s = trajectory.times_s.back() - trajectory.times_s.front();
  PassData data;
  data.system = &system;
  data.trajectory = &trajectory;
  data.speed = speed_m_per_s;
  data.n = n;

  flow_support::CvodesRun run;
  check(SUNContext_Create(nullptr, &run.ctx), "SUNContext_Create");
  run.y = N_VNew_Serial(sunindextype(n * (n + 1)), run.ctx);
  run.A = make_dense_newton_matrix(long(n), run.ctx);
  run.LS = make_eigen_dense_solver(long(n), run.ctx);
  run.mem = CVodeCreate(CV_BDF, run.ctx);
  if (!run.y || !run.A || !run.LS || !run.mem)
    throw std::runtime_error("integrate_variational_equations: out of memory");
  Eigen::Map<Eigen::MatrixXd> Y(N_VGetArrayPointer(run.y), n, n + 1);
  Y.setZero();
  Y.leftCols(n).setIdentity();
  void* mem = run.mem;
  check(CVodeSetErrHandlerFn(mem, flow_support::keep_first_error, &data.error), "CVodeSetErrHandlerFn");
  check(CVodeInit(mem, rhs_callback, trajectory.times_s.front(), run.y), "CVodeInit");
  check(CVodeSStolerances(mem, options.sensitivity_relative_tolerance,
                          options.sensitivity_absolute_tolerance),
        "CVodeSStolerances");
  check(CVodeSetUserData(mem, &data), "CVodeSetUserData");
  check(CVodeSetMaxNumSteps(mem, options.max_steps), "CVodeSetMaxNumSteps");
  check(CVodeSetLinearSolver(mem, run.LS, run.A), "CVodeSetLinearSolver");
  check(CVodeSetJacFn(mem, jacobian_callback), "CVodeSetJacFn");
  const double t_end = trajectory.times_s.back();
  check(CVodeSetStopTime(mem, t_end), "CVodeSetStopTime");
  double t_reached = 0.0;
  const int flag = CVode(mem, t_end, run.y, &t_reached, CV_NORMAL);
  if (flag < 0)
    flow_support::throw_stopped(mem, flag, "the variational equations", duration_s, data.error);
  VariationalResult out;
  out.state_sensitivity = Y.leftCols(n);
  out.speed_sensitivity = Y.col(n);
  long v = 0;
  CVodeGetNumSteps(mem, &v), out.steps = v;
  CVodeGetNumRhsEvals(mem, &v), out.rhs_evaluations = v;
  CVodeGetNumErrTestFails(mem, &v), out.error_test_failures = v;
  out.jacobian_evaluations = data.jacobian_evaluations;
  return out;
}

}  // namespace railstab
