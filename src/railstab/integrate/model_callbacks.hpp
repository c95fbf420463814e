#pragma once
// The model seen through SUNDIALS' C callbacks. CVODE and ARKODE share the
// signatures (right-hand side, dense Jacobian, root functions), so every
// stepper uses these. Callbacks never throw: an exception becomes a return
// code and its message is kept in `error` for the driver's report.
//
// IMEX split (arkode_imex), f = f_I + f_E:
//   f_I = the right-hand side of a copy of the model without force elements
//         and without gravity: dq/dt = u, the wheel-rail contact forces and
//         the inertial (gyroscopic, moving-frame) terms. The contact is the
//         stiff part: Hertz normal stiffness (modes at 150-240 Hz, some with
//         zeta ~ 0.008) and creep damping f/(V m) (real eigenvalues to
//         -4e3 1/s). dq/dt = u must be on the implicit side with the contact
//         forces, or the Hertz oscillator would still be integrated
//         explicitly. The inertial terms ride along because the model
//         computes them with the body accelerations; they are cheap and
//         non-stiff.
//   f_E = f - f_I: suspension springs/dampers and gravity. The stiffest
//         suspension modes are near 35-55 Hz (|lambda| <~ 350 1/s), mildly
//         stiff compared with the contact.
// f_E is formed as a difference: one full right-hand side plus one f_I per
// explicit stage evaluation (f_I is reused when ARKStep has just evaluated it
// at the same point, e.g. at the start of a step).
#include <railstab/integrate/root_functions.hpp>
#include <railstab/integrate/sparse_newton.hpp>
#include <railstab/linear/jacobian_pattern.hpp>
#include <railstab/model/model.hpp>
#include <railstab/model/workspace.hpp>

#include <nvector/nvector_serial.h>
#include <sundials/sundials_matrix.h>

#include <Eigen/Dense>

#include <ctime>
#include <memory>
#include <string>

namespace railstab {

struct ModelCallbackData {
  ModelCallbackData(const Model& model, double speed_m_per_s, const RootFunctionSet& roots,
                    double cpu_budget_s);

  const Model* model;
  double speed_m_per_s;
  const RootFunctionSet* roots;
  bool imex_split = false;  // IMEX only: see above
  Workspace<double> workspace;
  RhsJacobianPlan jacobian_plan;  // the coloured AD Jacobian's, made once per run
  // Set (non-empty) when the Newton matrix is sparse (integrate/sparse_newton.hpp):
  // the Jacobian callbacks then fill a CSC SUNMatrix in this layout.
  SparseJacobianLayout sparse_layout;
  bool sparse_newton() const { return sparse_layout.n > 0; }
  Eigen::VectorXd xdot_buffer;  // sized once: the rhs callbacks do not allocate
  std::string error;                     // first failure inside a callback
  std::string sundials_message;          // SUNDIALS' last error message
  bool budget_exhausted = false;
  // Model right-hand sides evaluated (full model or the IMEX implicit part),
  // excluding AD Jacobians and root functions.
  long model_evaluations = 0;

  // Returns false once the CPU budget is spent (checked every few calls).
  bool within_budget();

  // Cache of the last f_I evaluation (IMEX).
  double cached_t = 0.0;
  Eigen::VectorXd cached_x, cached_fi;
  bool cache_valid = false;

 private:
  std::clock_t cpu_start_;
  double cpu_budget_s_;
  long calls_ = 0;
};

// Prepares `data` for the IMEX split.
void prepare_imex_split(ModelCallbackData& data);

Eigen::Map<Eigen::VectorXd> as_eigen(N_Vector v);

// SUNDIALS callbacks; user data is a ModelCallbackData*.
int full_rhs_callback(double t, N_Vector y, N_Vector ydot, void* user);
int implicit_rhs_callback(double t, N_Vector y, N_Vector ydot, void* user);
int explicit_rhs_callback(double t, N_Vector y, N_Vector ydot, void* user);
int full_jacobian_callback(double t, N_Vector y, N_Vector fy, SUNMatrix J, void* user, N_Vector,
                           N_Vector, N_Vector);
int implicit_jacobian_callback(double t, N_Vector y, N_Vector fy, SUNMatrix J, void* user,
                               N_Vector, N_Vector, N_Vector);
int root_callback(double t, N_Vector y, double* g, void* user);
// Keeps error messages for the driver's exception (instead of SUNDIALS'
// default print to stderr); warnings still go to stderr.
void error_handler_callback(int error_code, const char* module, const char* function, char* msg,
                            void* user);

}  // namespace railstab
