#include <railstab/nonlinear/flow_sensitivity.hpp>

#include <railstab/integrate/dense_newton_matrix.hpp>
#include <railstab/integrate/eigen_dense_solver.hpp>
#include <railstab/nonlinear/cvodes_flow_support.hpp>
#include <railstab/nonlinear/variational_pass.hpp>

#include <cvodes/cvodes.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <cmath>
#include <ctime>
#include <string>
#include <vector>

namespace railstab {

namespace {

using flow_support::check;
using flow_support::guarded;
using flow_support::view;

// What the CVODES callbacks see. The Jacobian is cached on (t, x): the
// staggered corrector evaluates the sensitivity right-hand sides several
// times at one converged state.
struct FlowCallbackData {
  const FlowSystem* system = nullptr;
  double speed = 0.0;
  Eigen::VectorXd x, f, dfdV;
  Eigen::MatrixXd J;
  bool jacobian_valid = false;
  double jacobian_t = 0.0;
  Eigen::VectorXd jacobian_x;
  long jacobian_evaluations = 0;
  long dfdV_at_evaluation = -1;  // dfdV belongs to this Jacobian evaluation
  std::string error;

  const Eigen::MatrixXd& jacobian_at(double t, const Eigen::Map<Eigen::VectorXd>& y) {
    if (!(jacobian_valid && t == jacobian_t && y == jacobian_x)) {
      x = y;
      system->jacobian(x, speed, J);
      if (!J.allFinite()) throw std::runtime_error("non-finite Jacobian entry");
      jacobian_x = x, jacobian_t = t, jacobian_valid = true;
      ++jacobian_evaluations;
    }
    return J;
  }
};

int rhs_callback(double, N_Vector y, N_Vector ydot, void* user) {
  auto& d = *static_cast<FlowCallbackData*>(user);
  return guarded(d.error, [&] {
    d.x = view(y);
    d.system->rhs(d.x, d.speed, d.f);
    if (!d.f.allFinite()) throw std::runtime_error("non-finite state derivative");
    view(ydot) = d.f;
    return 0;
  });
}

int jacobian_callback(double t, N_Vector y, N_Vector, SUNMatrix Jmat, void* user, N_Vector,
                      N_Vector, N_Vector) {
  auto& d = *static_cast<FlowCallbackData*>(user);
  return guarded(d.error, [&] {
    const Eigen::MatrixXd& J = d.jacobian_at(t, view(y));
    const sunindextype n = SM_ROWS_D(Jmat);
    Eigen::Map<Eigen::MatrixXd>(SM_DATA_D(Jmat), n, n) = J;  // column-major, ldim n
    return 0;
  });
}

// ySdot_i = J yS_i, plus df/dV for the last (the speed's) sensitivity.
int sensitivity_callback(int Ns, double t, N_Vector y, N_Vector, N_Vector* yS, N_Vector* ySdot,
                         void* user, N_Vector, N_Vector) {
  auto& d = *static_cast<FlowCallbackData*>(user);
  return guarded(d.error, [&] {
    const Eigen::MatrixXd& J = d.jacobian_at(t, view(y));
    for (int i = 0; i < Ns; ++i) view(ySdot[i]).noalias() = J * view(yS[i]);
    if (d.dfdV_at_evaluation != d.jacobian_evaluations) {  // same (t, x) as J
      d.dfdV = speed_derivative(*d.system, d.jacobian_x, d.speed);
      if (!d.dfdV.allFinite()) throw std::runtime_error("non-finite df/dV");
      d.dfdV_at_evaluation = d.jacobian_evaluations;
    }
    view(ySdot[Ns - 1]) += d.dfdV;
    return 0;
  });
}

}  // namespace

FlowResult integrate_flow(const FlowSystem& system, const Eigen::VectorXd& x0,
                          double speed_m_per_s, double duration_s, const FlowOptions& options) {
  const int n = system.size;
  if (x0.size() != n)
    throw std::invalid_argument("integrate_flow: initial state has size " +
                                std::to_string(x0.size()) + ", the system " + std::to_string(n));
  if (!(duration_s > 0.0) || !std::isfinite(duration_s))
    throw std::invalid_argument("integrate_flow: the time span must be positive and finite");
  const std::clock_t cpu0 = std::clock();
  FlowCallbackData data;
  data.system = &system;
  data.speed = speed_m_per_s;

  flow_support::CvodesRun run;
  check(SUNContext_Create(nullptr, &run.ctx), "SUNContext_Create");
  run.y = N_VNew_Serial(n, run.ctx);
  view(run.y) = x0;
  run.A = make_dense_newton_matrix(n, run.ctx);  // SUNDIALS dense, faster copy and I - gamma J
  // Eigen's blocked LU (integrate/eigen_dense_solver.hpp): with the
  // variational equations each step solves n + 1 sensitivity systems with
  // the factored matrix, and SUNDIALS' scalar dense solves were half of an
  // orbit's CPU on the S1002 vehicle.
  run.LS = make_eigen_dense_solver(n, run.ctx);
  run.mem = CVodeCreate(CV_BDF, run.ctx);
  if (!run.y || !run.A || !run.LS || !run.mem) throw std::runtime_error("integrate_flow: out of memory");
  void* mem = run.mem;
  check(CVodeSetErrHandlerFn(mem, flow_support::keep_first_error, &data.error), "CVodeSetErrHandlerFn");
  check(CVodeInit(mem, rhs_callback, 0.0, run.y), "CVodeInit");
  check(CVodeSStolerances(mem, options.relative_tolerance, options.absolute_tolerance),
        "CVodeSStolerances");
  check(CVodeSetUserData(mem, &data), "CVodeSetUserData");
  check(CVodeSetMaxNumSteps(mem, options.max_steps), "CVodeSetMaxNumSteps");
  check(CVodeSetLinearSolver(mem, run.LS, run.A), "CVodeSetLinearSolver");
  check(CVodeSetJacFn(mem, jacobian_callback), "CVodeSetJacFn");
  const bool second_pass =
      options.sensitivities && options.variational == FlowOptions::Variational::second_pass;
  const bool alongside = options.sensitivities && !second_pass;
  if (alongside) {
    run.Ns = n + 1;
    run.yS = N_VCloneVectorArray(run.Ns, run.y);
    for (int i = 0; i < run.Ns; ++i) N_VConst(0.0, run.yS[i]);
    for (int i = 0; i < n; ++i) NV_Ith_S(run.yS[i], i) = 1.0;
    check(CVodeSensInit(mem, run.Ns, CV_STAGGERED, sensitivity_callback, run.yS), "CVodeSensInit");
    std::vector<double> abstol(size_t(run.Ns), options.sensitivity_absolute_tolerance);
    check(CVodeSensSStolerances(mem, options.sensitivity_relative_tolerance, abstol.data()),
          "CVodeSensSStolerances");
    check(CVodeSetSensErrCon(mem, options.sensitivity_error_control ? SUNTRUE : SUNFALSE),
          "CVodeSetSensErrCon");
  }

  FlowResult out;
  const int intervals = std::max(1, options.samples);
  if (options.samples > 0) {
    out.sample_times_s.push_back(0.0);
    out.samples.push_back(x0);
  }
  // Never step past T (an orbit's end); samples before it are interpolated
  // (CVODES's dense output), so they do not shorten the steps.
  check(CVodeSetStopTime(mem, duration_s), "CVodeSetStopTime");
  auto fail = [&](int flag) { flow_support::throw_stopped(mem, flag, "CVODES", duration_s, data.error); };
  auto sample_time = [&](int k) { return k == intervals ? duration_s : duration_s * double(k) / intervals; };
  RecordedTrajectory trajectory;
  if (!second_pass) {
    for (int k = 1; k <= intervals; ++k) {
      const double t_out = sample_time(k);
      double t_reached = 0.0;
      const int flag = CVode(mem, t_out, run.y, &t_reached, CV_NORMAL);
      if (flag < 0) fail(flag);
      if (options.samples > 0) {
        out.sample_times_s.push_back(t_out);
        out.samples.push_back(view(run.y));
      }
    }
  } else {
    // Step by step: every step's end and rate recorded for the second pass,
    // the samples interpolated within the step that holds them.
    trajectory.times_s.push_back(0.0);
    trajectory.states.push_back(x0);
    trajectory.rates.emplace_back();
    system.rhs(x0, speed_m_per_s, trajectory.rates.back());
    N_Vector work = N_VClone(run.y);
    if (!work) throw std::runtime_error("integrate_flow: out of memory");
    struct Free {
      N_Vector v;
      ~Free() { N_VDestroy(v); }
    } free_work{work};
    int next_sample = 1;
    double t = 0.0;
    for (int flag = CV_SUCCESS; flag != CV_TSTOP_RETURN && t < duration_s;) {
      flag = CVode(mem, duration_s, run.y, &t, CV_ONE_STEP);
      if (flag < 0) fail(flag);
      for (; options.samples > 0 && next_sample <= intervals && sample_time(next_sample) <= t;
           ++next_sample) {
        const double ts = sample_time(next_sample);
        check(CVodeGetDky(mem, ts, 0, work), "CVodeGetDky");
        out.sample_times_s.push_back(ts);
        out.samples.push_back(view(work));
      }
      check(CVodeGetDky(mem, t, 1, work), "CVodeGetDky");
      trajectory.times_s.push_back(t);
      trajectory.states.push_back(view(run.y));
      trajectory.rates.push_back(view(work));
    }
  }
  out.end_state = view(run.y);
  if (options.sensitivities) out.sensitivity_relative_tolerance = options.sensitivity_relative_tolerance;
  if (alongside) {
    double t_reached = 0.0;
    check(CVodeGetSens(mem, &t_reached, run.yS), "CVodeGetSens");
    out.state_sensitivity.resize(n, n);
    for (int i = 0; i < n; ++i) out.state_sensitivity.col(i) = view(run.yS[i]);
    out.speed_sensitivity = view(run.yS[n]);
  }
  long v = 0;
  CVodeGetNumSteps(mem, &v), out.steps = v;
  CVodeGetNumRhsEvals(mem, &v), out.rhs_evaluations = v;
  CVodeGetNumErrTestFails(mem, &v), out.error_test_failures = v;
  out.jacobian_evaluations = data.jacobian_evaluations;
  if (second_pass) {
    VariationalResult pass = integrate_variational_equations(system, trajectory, speed_m_per_s, options);
    out.state_sensitivity = std::move(pass.state_sensitivity);
    out.speed_sensitivity = std::move(pass.speed_sensitivity);
    out.variational_steps = pass.steps;
    out.steps += pass.steps;
    out.rhs_evaluations += pass.rhs_evaluations;
    out.jacobian_evaluations += pass.jacobian_evaluations;
    out.error_test_failures += pass.error_test_failures;
  }
  out.cpu_seconds = double(std::clock() - cpu0) / CLOCKS_PER_SEC;
  return out;
}

}  // namespace railstab
