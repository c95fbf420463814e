#include "integrate/integrator.hpp"

#include "linear/jacobian.hpp"
#include "model/equations_of_motion.hpp"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <chrono>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace railstab {

std::string integrator_name(IntegratorKind kind) {
  switch (kind) {
    case IntegratorKind::cvode_bdf: return "cvode_bdf";
    case IntegratorKind::cvode_adams: return "cvode_adams";
  }
  return "unknown";
}

namespace {

// Validity limits as CVODE root functions: g = c^2 - y^2 for every wheelset
// with a free lateral coordinate (c: flange clearance of its contact).
struct LateralLimit {
  int state;
  double clearance_m;
  std::string body;
};

std::vector<LateralLimit> lateral_limits(const Model& model) {
  std::vector<LateralLimit> limits;
  for (const ModelBody& b : model.bodies) {
    const int k = b.state_index[int(CoordinateIndex::y)];
    if (b.contact >= 0 && k >= 0)
      limits.push_back({k, model.contacts[b.contact].spec.flange_clearance_m, b.name});
  }
  return limits;
}

struct CallbackData {
  const Model* model;
  std::string error;  // first failure inside a callback
  std::vector<LateralLimit> limits;
};

Eigen::Map<Eigen::VectorXd> as_eigen(N_Vector v) {
  return Eigen::Map<Eigen::VectorXd>(N_VGetArrayPointer(v), N_VGetLength(v));
}

int rhs_callback(realtype t, N_Vector y, N_Vector ydot, void* user) {
  auto* data = static_cast<CallbackData*>(user);
  try {
    as_eigen(ydot) = rhs(*data->model, t, as_eigen(y));
  } catch (const std::exception& e) {
    if (data->error.empty()) data->error = e.what();
    return 1;  // recoverable: CVODE retries with a smaller step
  }
  return 0;
}

int root_callback(realtype, N_Vector y, realtype* g, void* user) {
  auto* data = static_cast<CallbackData*>(user);
  const realtype* x = N_VGetArrayPointer(y);
  for (size_t i = 0; i < data->limits.size(); ++i) {
    const LateralLimit& l = data->limits[i];
    g[i] = l.clearance_m * l.clearance_m - x[l.state] * x[l.state];
  }
  return 0;
}

int jacobian_callback(realtype t, N_Vector y, N_Vector, SUNMatrix J, void* user, N_Vector,
                      N_Vector, N_Vector) {
  auto* data = static_cast<CallbackData*>(user);
  const long n = SUNDenseMatrix_Rows(J);
  Eigen::Map<Eigen::MatrixXd> jac(SUNDenseMatrix_Data(J), n, n);  // column-major
  try {
    jac = rhs_jacobian_ad(*data->model, t, as_eigen(y));
  } catch (const std::exception& e) {
    if (data->error.empty()) data->error = e.what();
    return 1;
  }
  return jac.allFinite() ? 0 : 1;
}

// RAII for the SUNDIALS objects of one run.
struct CvodeRun {
  SUNContext ctx = nullptr;
  N_Vector y = nullptr;
  SUNMatrix A = nullptr;
  SUNLinearSolver LS = nullptr;
  void* mem = nullptr;
  ~CvodeRun() {
    if (mem) CVodeFree(&mem);
    if (LS) SUNLinSolFree(LS);
    if (A) SUNMatDestroy(A);
    if (y) N_VDestroy(y);
    if (ctx) SUNContext_Free(&ctx);
  }
};

void check(int flag, const char* call) {
  if (flag < 0) throw std::runtime_error(std::string("SUNDIALS ") + call + " failed, flag " +
                                         std::to_string(flag));
}

}  // namespace

Trajectory integrate(const Model& model, const Eigen::VectorXd& x0,
                     const IntegrationOptions& options) {
  const auto wall_start = std::chrono::steady_clock::now();
  const long n = x0.size();
  CallbackData data{&model, {}, lateral_limits(model)};
  CvodeRun run;
  check(SUNContext_Create(nullptr, &run.ctx), "SUNContext_Create");
  run.y = N_VNew_Serial(n, run.ctx);
  as_eigen(run.y) = x0;
  const bool bdf = options.kind == IntegratorKind::cvode_bdf;
  run.mem = CVodeCreate(bdf ? CV_BDF : CV_ADAMS, run.ctx);
  if (!run.mem) throw std::runtime_error("CVodeCreate failed");
  check(CVodeInit(run.mem, rhs_callback, options.t_start_s, run.y), "CVodeInit");
  check(CVodeSStolerances(run.mem, options.relative_tolerance, options.absolute_tolerance),
        "CVodeSStolerances");
  check(CVodeSetUserData(run.mem, &data), "CVodeSetUserData");
  check(CVodeSetMaxNumSteps(run.mem, options.max_steps), "CVodeSetMaxNumSteps");
  run.A = SUNDenseMatrix(n, n, run.ctx);
  run.LS = SUNLinSol_Dense(run.y, run.A, run.ctx);
  check(CVodeSetLinearSolver(run.mem, run.LS, run.A), "CVodeSetLinearSolver");
  check(CVodeSetJacFn(run.mem, jacobian_callback), "CVodeSetJacFn");
  if (!data.limits.empty())
    check(CVodeRootInit(run.mem, int(data.limits.size()), root_callback), "CVodeRootInit");

  Trajectory traj;
  traj.times_s.push_back(options.t_start_s);
  traj.states.push_back(x0);
  const double span = options.t_end_s - options.t_start_s;
  const long n_out = std::max(1L, long(std::ceil(span / options.output_interval_s - 1e-9)));
  auto last_report = wall_start;
  for (long i = 1; i <= n_out; ++i) {
    const double t_out = std::min(options.t_end_s, options.t_start_s + i * options.output_interval_s);
    realtype t_reached = 0.0;
    const int flag = CVode(run.mem, t_out, run.y, &t_reached, CV_NORMAL);
    if (flag < 0) {
      std::ostringstream msg;
      msg << "time integration (" << integrator_name(options.kind) << ") stopped at t = "
          << t_reached << " s: " << CVodeGetReturnFlagName(flag);
      if (!data.error.empty()) msg << "; cause: " << data.error;
      throw std::runtime_error(msg.str());
    }
    traj.times_s.push_back(t_reached);
    traj.states.push_back(as_eigen(run.y));
    if (flag == CV_ROOT_RETURN) {
      std::vector<int> found(data.limits.size());
      CVodeGetRootInfo(run.mem, found.data());
      for (size_t r = 0; r < found.size(); ++r)
        if (found[r] != 0) {
          std::ostringstream msg;
          msg << data.limits[r].body << " lateral shift reached the flange clearance "
              << data.limits[r].clearance_m << " m at t = " << t_reached
              << " s: flange contact is outside the model's validity";
          traj.stopped_early = msg.str();
          break;
        }
      break;
    }
    const auto now = std::chrono::steady_clock::now();
    if (options.progress && now - last_report > std::chrono::seconds(1)) {
      options.progress(t_reached);
      last_report = now;
    }
  }
  long v = 0;
  CVodeGetNumSteps(run.mem, &v), traj.stats.steps = v;
  CVodeGetNumRhsEvals(run.mem, &v), traj.stats.rhs_evaluations = v;
  CVodeGetNumJacEvals(run.mem, &v), traj.stats.jacobian_evaluations = v;
  CVodeGetNumErrTestFails(run.mem, &v), traj.stats.error_test_failures = v;
  CVodeGetNumNonlinSolvConvFails(run.mem, &v), traj.stats.nonlinear_failures = v;
  traj.stats.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  return traj;
}

}  // namespace railstab
