#pragma once
// One SUNDIALS integrator behind a common face, so the driver
// (integrator.cpp) has one code path for options, outputs, roots and
// statistics. Each package lives in its own file: cvode_stepper.cpp,
// erk_stepper.cpp, ark_stepper.cpp.
#include <railstab/integrate/integrator.hpp>
#include <railstab/integrate/model_callbacks.hpp>

#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>

#include <memory>
#include <string>
#include <vector>

namespace railstab {

struct StepOutcome {
  enum class Status { reached, root, too_much_work, failed };
  Status status = Status::reached;
  double t_reached = 0.0;
  std::string flag_name;  // SUNDIALS' name of the return flag
};

// Owns the SUNDIALS context and the state vector; the integrator memory is
// the derived class's.
class Stepper {
 public:
  Stepper(const Eigen::VectorXd& x0);
  virtual ~Stepper();
  Stepper(const Stepper&) = delete;
  Stepper& operator=(const Stepper&) = delete;

  // Integrates to t_out, or to the first root before it.
  virtual StepOutcome advance(double t_out) = 0;
  // For each root function: +1 rising through zero, -1 falling, 0 not found
  // (after a StepOutcome::Status::root).
  virtual std::vector<int> root_directions() = 0;
  // Steps, Jacobians, failures, root evaluations (the driver counts the
  // right-hand sides itself).
  virtual IntegrationStats statistics() = 0;

  Eigen::Map<Eigen::VectorXd> state() { return as_eigen(y_); }

 protected:
  SUNContext ctx_ = nullptr;
  N_Vector y_ = nullptr;
};

// Integrator memory (CVODE, ERKStep, ARKStep) with its free function; a
// member declared after the linear solver, so it is freed first.
struct IntegratorMemory {
  void* mem = nullptr;
  void (*free)(void**) = nullptr;
  IntegratorMemory(void* m, void (*f)(void**));
  ~IntegratorMemory();
  IntegratorMemory(const IntegratorMemory&) = delete;
  IntegratorMemory& operator=(const IntegratorMemory&) = delete;
};

// Matrix and direct solver for the Newton iterations (CVODE, ARKStep):
// SUNDIALS assembles I - gamma J in it. Dense: Eigen's LU
// (eigen_dense_solver.hpp); sparse (data.sparse_newton()): a CSC matrix in
// the Jacobian's layout and KLU (sparse_newton.hpp).
struct NewtonLinearSolver {
  NewtonLinearSolver(N_Vector y, SUNContext ctx, const ModelCallbackData& data);
  ~NewtonLinearSolver();
  NewtonLinearSolver(const NewtonLinearSolver&) = delete;
  NewtonLinearSolver& operator=(const NewtonLinearSolver&) = delete;
  SUNMatrix A = nullptr;
  SUNLinearSolver LS = nullptr;
};

// SUNDIALS' *GetReturnFlagName functions (CVode, ARKStep, ERKStep) return a
// string malloc'ed per call that the caller must free: copies it and frees it.
std::string take_sundials_string(char* name);

// Throws std::runtime_error naming the call when a SUNDIALS setup call fails.
void check_sundials(int flag, const char* call);

// `data` outlives the stepper; options are read at construction only.
std::unique_ptr<Stepper> make_cvode_stepper(const IntegrationOptions& options,
                                            const Eigen::VectorXd& x0, ModelCallbackData& data);
std::unique_ptr<Stepper> make_erk_stepper(const IntegrationOptions& options,
                                          const Eigen::VectorXd& x0, ModelCallbackData& data);
// arkode_dirk or arkode_imex (options.kind).
std::unique_ptr<Stepper> make_ark_stepper(const IntegrationOptions& options,
                                          const Eigen::VectorXd& x0, ModelCallbackData& data);

}  // namespace railstab
