// ARKODE ERKStep: explicit adaptive Runge-Kutta. Default order 4, the
// Zonneveld 5-3-4 table (5 stages, embedded 3rd order). Stable only while
// h |lambda| stays inside its region (about 2.8 on the negative real axis):
// on the thesis vehicles the contact eigenvalues (-3e3...-4.4e3 1/s at
// 20 m/s) cap the step near 0.6-0.9 ms whatever the tolerance.
#include <railstab/integrate/stepper.hpp>

#include <arkode/arkode_erkstep.h>

namespace railstab {

namespace {

class ErkStepper final : public Stepper {
 public:
  ErkStepper(const IntegrationOptions& o, const Eigen::VectorXd& x0, ModelCallbackData& data)
      : Stepper(x0),
        erk_(ERKStepCreate(full_rhs_callback, o.t_start_s, y_, ctx_), ERKStepFree),
        n_roots_(data.roots->size()) {
    void* mem = erk_.mem;
    check_sundials(ERKStepSetErrHandlerFn(mem, error_handler_callback, &data),
                   "ERKStepSetErrHandlerFn");
    check_sundials(ERKStepSStolerances(mem, o.relative_tolerance, o.absolute_tolerance),
                   "ERKStepSStolerances");
    check_sundials(ERKStepSetUserData(mem, &data), "ERKStepSetUserData");
    check_sundials(ERKStepSetMaxNumSteps(mem, o.max_steps), "ERKStepSetMaxNumSteps");
    if (o.order > 0) check_sundials(ERKStepSetOrder(mem, o.order), "ERKStepSetOrder");
    if (n_roots_ > 0) {
      check_sundials(ERKStepRootInit(mem, n_roots_, root_callback), "ERKStepRootInit");
      check_sundials(ERKStepSetNoInactiveRootWarn(mem), "ERKStepSetNoInactiveRootWarn");
    }
  }

  StepOutcome advance(double t_out) override {
    StepOutcome out;
    const int flag = ERKStepEvolve(erk_.mem, t_out, y_, &out.t_reached, ARK_NORMAL);
    out.flag_name = take_sundials_string(ERKStepGetReturnFlagName(flag));
    if (flag == ARK_ROOT_RETURN) out.status = StepOutcome::Status::root;
    else if (flag == ARK_TOO_MUCH_WORK) out.status = StepOutcome::Status::too_much_work;
    else if (flag < 0) out.status = StepOutcome::Status::failed;
    if (flag < 0) ERKStepGetCurrentTime(erk_.mem, &out.t_reached);  // not set on failure
    return out;
  }

  std::vector<int> root_directions() override {
    std::vector<int> found(size_t(n_roots_), 0);
    if (n_roots_ > 0) ERKStepGetRootInfo(erk_.mem, found.data());
    return found;
  }

  IntegrationStats statistics() override {
    void* mem = erk_.mem;
    IntegrationStats s;
    long v = 0;
    ERKStepGetNumSteps(mem, &v), s.steps = v;
    ERKStepGetNumErrTestFails(mem, &v), s.error_test_failures = v;
    // Only with root functions: without them the call is an "illegal" error
    // whose message would be appended to the run's real one.
    if (n_roots_ > 0) ERKStepGetNumGEvals(mem, &v), s.root_evaluations = v;
    return s;
  }

 private:
  IntegratorMemory erk_;
  int n_roots_;
};

}  // namespace

std::unique_ptr<Stepper> make_erk_stepper(const IntegrationOptions& options,
                                          const Eigen::VectorXd& x0, ModelCallbackData& data) {
  return std::make_unique<ErkStepper>(options, x0, data);
}

}  // namespace railstab
