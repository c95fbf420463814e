// CVODE (BDF or Adams-Moulton) with a dense Newton solver and the AD Jacobian.
#include <railstab/integrate/stepper.hpp>

// CVODES: CVODE with the forward sensitivity module (the periodic orbits'
// monodromy, nonlinear/flow_sensitivity.hpp). One library for both: CVODE
// and CVODES export the same CVode* symbols, so a program cannot link both.
#include <cvodes/cvodes.h>

namespace railstab {

namespace {

class CvodeStepper final : public Stepper {
 public:
  CvodeStepper(const IntegrationOptions& o, const Eigen::VectorXd& x0, ModelCallbackData& data)
      : Stepper(x0),
        linear_(y_, ctx_, data),
        cvode_(CVodeCreate(o.kind == IntegratorKind::cvode_adams ? CV_ADAMS : CV_BDF, ctx_),
               CVodeFree),
        n_roots_(data.roots->size()) {
    void* mem = cvode_.mem;
    check_sundials(CVodeSetErrHandlerFn(mem, error_handler_callback, &data), "CVodeSetErrHandlerFn");
    check_sundials(CVodeInit(mem, full_rhs_callback, o.t_start_s, y_), "CVodeInit");
    check_sundials(CVodeSStolerances(mem, o.relative_tolerance, o.absolute_tolerance),
                   "CVodeSStolerances");
    check_sundials(CVodeSetUserData(mem, &data), "CVodeSetUserData");
    check_sundials(CVodeSetMaxNumSteps(mem, o.max_steps), "CVodeSetMaxNumSteps");
    if (o.order > 0) check_sundials(CVodeSetMaxOrd(mem, o.order), "CVodeSetMaxOrd");
    check_sundials(CVodeSetLinearSolver(mem, linear_.LS, linear_.A), "CVodeSetLinearSolver");
    check_sundials(CVodeSetJacFn(mem, full_jacobian_callback), "CVodeSetJacFn");
    if (n_roots_ > 0) {
      check_sundials(CVodeRootInit(mem, n_roots_, root_callback), "CVodeRootInit");
      check_sundials(CVodeSetNoInactiveRootWarn(mem), "CVodeSetNoInactiveRootWarn");
    }
  }

  StepOutcome advance(double t_out) override {
    StepOutcome out;
    const int flag = CVode(cvode_.mem, t_out, y_, &out.t_reached, CV_NORMAL);
    out.flag_name = take_sundials_string(CVodeGetReturnFlagName(flag));
    if (flag == CV_ROOT_RETURN) out.status = StepOutcome::Status::root;
    else if (flag == CV_TOO_MUCH_WORK) out.status = StepOutcome::Status::too_much_work;
    else if (flag < 0) out.status = StepOutcome::Status::failed;
    if (flag < 0) CVodeGetCurrentTime(cvode_.mem, &out.t_reached);  // not set on failure
    return out;
  }

  std::vector<int> root_directions() override {
    std::vector<int> found(size_t(n_roots_), 0);
    if (n_roots_ > 0) CVodeGetRootInfo(cvode_.mem, found.data());
    return found;
  }

  IntegrationStats statistics() override {
    void* mem = cvode_.mem;
    IntegrationStats s;
    long v = 0;
    CVodeGetNumSteps(mem, &v), s.steps = v;
    CVodeGetNumJacEvals(mem, &v), s.jacobian_evaluations = v;
    CVodeGetNumErrTestFails(mem, &v), s.error_test_failures = v;
    CVodeGetNumNonlinSolvConvFails(mem, &v), s.nonlinear_failures = v;
    // Only with root functions: without them the call is an "illegal" error
    // whose message would be appended to the run's real one.
    if (n_roots_ > 0) CVodeGetNumGEvals(mem, &v), s.root_evaluations = v;
    return s;
  }

 private:
  NewtonLinearSolver linear_;
  IntegratorMemory cvode_;  // declared last: freed before the solver
  int n_roots_;
};

}  // namespace

std::unique_ptr<Stepper> make_cvode_stepper(const IntegrationOptions& options,
                                            const Eigen::VectorXd& x0, ModelCallbackData& data) {
  return std::make_unique<CvodeStepper>(options, x0, data);
}

}  // namespace railstab
