#pragma once
// Time integration of the nonlinear model on SUNDIALS.
//
// One driver (integrator.cpp: output times, events, progress, budget,
// statistics) over interchangeable steppers (stepper.hpp), one per SUNDIALS
// package:
//   cvode_bdf    CVODE BDF, variable order 1-5 (order caps it), dense
//                Newton with the exact AD Jacobian. The default of
//                IntegrationOptions; a scene's [simulation] defaults to
//                arkode_dirk (SimulationSpec, scene/scene_spec.hpp), and so
//                do the commands.
//   cvode_adams  CVODE Adams-Moulton, orders 1-12, same Newton solver.
//   arkode_erk   ARKODE ERKStep, explicit adaptive Runge-Kutta, default order
//                4: Zonneveld 5-3-4 (5 stages, embedded order 3). No Jacobian.
//   arkode_dirk  ARKODE ARKStep fully implicit, default order 4: SDIRK 5-3-4
//                (L-stable), dense Newton with the AD Jacobian.
//   arkode_imex  ARKODE ARKStep additive IMEX, default order 4: ARK4(3)7L[2]SA
//                (ARK436L2SA ERK/DIRK 6-3-4). Split (see model_callbacks.hpp):
//                implicit = kinematics dq/dt = u, wheel-rail contact forces and
//                the inertial terms; explicit = suspension elements and gravity.
//
// Why stiff: the wheel-rail contact. Hertz vertical modes near 150-240 Hz,
// some nearly undamped (zeta ~ 0.008), and creep damping f/(V m) giving real
// eigenvalues to -3e3...-4e3 1/s on the thesis vehicles at 20 m/s.
#include <railstab/model/model.hpp>
#include <railstab/scene/integrator_kind.hpp>

#include <Eigen/Dense>

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace railstab {

// The Newton matrix I - gamma J of the implicit methods: dense (Eigen's LU)
// or sparse (SUNDIALS' KLU on the coloured AD Jacobian's pattern,
// integrate/sparse_newton.hpp). automatic: sparse from
// kSparseNewtonFromStates states on, the crossover measured by
// analysis/bench_scaling (README, issue 11).
enum class NewtonMatrixKind { automatic, dense, sparse };
inline constexpr int kSparseNewtonFromStates = 200;
bool uses_sparse_newton(NewtonMatrixKind kind, int n_states);

struct IntegrationOptions {
  IntegratorKind kind = IntegratorKind::cvode_bdf;
  double t_start_s = 0.0;
  double t_end_s = 1.0;
  double output_interval_s = 0.01;
  double relative_tolerance = 1e-6;
  double absolute_tolerance = 1e-9;
  // Per output interval (SUNDIALS counts steps per call); exceeding it throws
  // IntegrationGaveUp.
  long max_steps = 5000000;
  // Method order; 0: the method's default. CVODE: the maximum order (BDF
  // 5, Adams 12; the order still adapts below it). BDF capped at 2 is
  // A-stable: orders 3-5 are unstable near the imaginary axis, where the
  // nearly undamped Hertz modes sit, and hold the step near h |lambda| ~ 0.8.
  // ARKODE: the order of the Runge-Kutta table, default 4 (ERK 2-8; DIRK
  // 2-5, 3 = ARK324L2SA ESDIRK 4-2-3, 5 = ARK548L2SA ESDIRK 8-4-5; IMEX 3-5).
  int order = 0;
  // Process CPU seconds for the whole run; 0 = no limit. Exceeding it throws
  // IntegrationGaveUp (used by benchmarks to cap explicit methods).
  double cpu_time_budget_s = 0.0;
  // Stop at the first loss of wheel-rail contact (Trajectory::stopped_early).
  // Otherwise losses and regains are only recorded (Trajectory::events): the
  // Hertz force is simply zero while a wheel is in the air.
  bool stop_on_lift_off = false;
  // Called about once per wall-clock second with the current time.
  std::function<void(double t_s)> progress;
  // Called at every output with its time and state: a non-empty answer
  // ends the run there, as Trajectory::stopped_early (e.g. a speed ramp
  // whose hunting has died away, nonlinear/speed_ramp.hpp).
  std::function<std::string(double t_s, const Eigen::VectorXd& x)> stop_at_output;
  // Upper bound on (t_end - t_start) / output_interval: every output state is
  // kept in memory (Trajectory), so a run asking for more (t_end 1e20,
  // output_interval 1e-12) stops before it starts, naming both.
  double max_outputs = 1e6;
  NewtonMatrixKind newton_matrix = NewtonMatrixKind::automatic;
};

struct IntegrationStats {
  // rhs_evaluations: model right-hand sides (for arkode_imex the full model
  // and its implicit part both count), not AD Jacobians or root functions.
  long steps = 0, rhs_evaluations = 0, jacobian_evaluations = 0, error_test_failures = 0,
       nonlinear_failures = 0, root_evaluations = 0;
  double wall_seconds = 0.0;
  double cpu_seconds = 0.0;  // std::clock: process CPU time of the run
};

// A wheel losing or regaining contact (root of its penetration).
struct ContactEvent {
  enum class Kind { lost, regained, out_of_contact_at_start };
  Kind kind = Kind::lost;
  double time_s = 0.0;
  int body = 0;   // index into Model::bodies
  int side = 1;   // +1 left, -1 right
  std::string description;  // "wheelset2 left wheel lost contact at t = 3.21 s"
};

struct Trajectory {
  std::vector<double> times_s;
  std::vector<Eigen::VectorXd> states;
  IntegrationStats stats;
  // Set when the run ended before t_end at a validity limit or event, e.g.
  // "wheelset1 lateral shift reached the flange clearance 0.0075 m at t = 3.21 s"
  // or (stop_on_lift_off) "wheelset2 left wheel lost contact at t = 3.21 s".
  std::string stopped_early;
  // Contact losses and regains in time order (not an error: the run goes on).
  std::vector<ContactEvent> events;
};

// Thrown when the work limit (max_steps or cpu_time_budget_s) is reached,
// with the work done until then.
struct IntegrationGaveUp : std::runtime_error {
  IntegrationGaveUp(const std::string& what, double t_reached, const IntegrationStats& work)
      : std::runtime_error(what), t_reached_s(t_reached), stats(work) {}
  double t_reached_s;
  IntegrationStats stats;
};

// The scene's [simulation] choices: integrator, order, tolerances, end time
// and output interval.
IntegrationOptions integration_options_for(const SimulationSpec& simulation);

// Throws std::runtime_error with SUNDIALS' reason and the time reached
// (IntegrationGaveUp for work limits).
Trajectory integrate(const Model& model, double speed_m_per_s,
    const Eigen::VectorXd& x0,
                     const IntegrationOptions& options);


}  // namespace railstab
