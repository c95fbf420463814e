#pragma once
// Work-precision study: each integrator over a ladder of tolerances against a
// tight reference, error against CPU time. Shared by the `work-precision`
// command and analysis/bench_integrators.
//
// Error measure: max over the output times and over the body coordinates of
// |x - x_ref|, positions only (m and rad), without the wheelsets' spin angles
// (they grow like V t / r0, ~900 rad in 20 s at 20 m/s; the rest of the
// state does not depend on them, ERRATA 11a).
// Work: process CPU seconds (std::clock) of integrate(): robust to other
// processes on the machine, and the same as wall time for this
// single-threaded code when the machine is idle (wall is recorded too).
#include <railstab/integrate/integrator.hpp>

#include <functional>
#include <string>
#include <vector>

namespace railstab {

// An integrator and its order cap (0: default), e.g. BDF capped at order 2.
struct IntegratorVariant {
  IntegratorKind kind = IntegratorKind::cvode_bdf;
  int order = 0;
  std::string label() const;  // "cvode_bdf", "cvode_bdf_q2", ...
};

// cvode_bdf, cvode_bdf_q2, cvode_adams, arkode_erk, arkode_dirk, arkode_imex.
std::vector<IntegratorVariant> default_variants();
// "arkode_dirk_q3" -> {arkode_dirk, 3}; throws std::invalid_argument.
IntegratorVariant parse_integrator_variant(const std::string& label);

struct WorkPrecisionSettings {
  double t_end_s = 5.0;
  double output_interval_s = 0.01;
  std::vector<double> relative_tolerances = {1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8};
  // atol = rtol * scale, same units as the state (m, rad, m/s, rad/s). 1e-3:
  // the lateral motions of interest are ~1 mm (the thesis cases' initial
  // offset), so a 1 mm coordinate gets equal absolute and relative weight;
  // the defaults of the scene files (rtol 1e-6, atol 1e-9) follow the same rule.
  double absolute_tolerance_scale = 1e-3;
  IntegratorKind reference_kind = IntegratorKind::cvode_bdf;
  double reference_rtol = 1e-11;
  // A second reference, to bound the first's error (a different method makes
  // the check independent of the reference's own error behaviour).
  IntegratorKind reference_check_kind = IntegratorKind::cvode_bdf;
  double reference_check_rtol = 1e-10;
  double cpu_budget_per_run_s = 5.0;    // a run over it is recorded as "gave up"
  std::vector<IntegratorVariant> variants = default_variants();
};

struct WorkPrecisionRun {
  std::string label;
  double rtol = 0.0, atol = 0.0;
  double error = 0.0;           // see above; NaN when the run did not finish
  std::string error_coordinate; // where the maximum is, e.g. "wheelset1.z_m"
  double lateral_error = 0.0;   // the same over lateral shifts and yaw angles only
  double cpu_seconds = 0.0, wall_seconds = 0.0;
  IntegrationStats stats;
  std::string status;           // "ok", "gave up", "skipped", "failed: ...", "stopped early: ..."
};

struct ReferenceSolution {
  Trajectory trajectory;
  IntegratorKind kind = IntegratorKind::cvode_bdf, check_kind = IntegratorKind::cvode_bdf;
  double rtol = 0.0, atol = 0.0;
  double check_rtol = 0.0;
  // The error measure between the reference and the looser check reference:
  // an upper estimate of the reference's own error (the check's error
  // dominates it).
  double check_difference = 0.0;
  double cpu_seconds = 0.0, check_cpu_seconds = 0.0;
};

struct WorkPrecisionResult {
  ReferenceSolution reference;
  std::vector<WorkPrecisionRun> runs;
};

// Which coordinates an error measure compares.
enum class ErrorCoordinates {
  positions,  // all body positions and angles but the wheelset spin (the measure above)
  lateral     // lateral shift and yaw only: the hunting motion itself
};

// The error measure of `run` against `ref` over the output times both have
// (a run stopped at a root ends at its own time, which is skipped); sets
// `where` to the state name of the maximum and `compared` to the number of
// common outputs. NaN as soon as a difference is NaN.
double trajectory_position_error(const Model& model, const Trajectory& run, const Trajectory& ref,
                                 std::string* where = nullptr,
                                 ErrorCoordinates which = ErrorCoordinates::positions,
                                 int* compared = nullptr);

ReferenceSolution compute_reference(const Model& model, double speed_m_per_s,
    const Eigen::VectorXd& x0,
                                    const WorkPrecisionSettings& settings);

// One integrator at one tolerance against the reference.
WorkPrecisionRun run_against_reference(const Model& model, double speed_m_per_s,
    const Eigen::VectorXd& x0,
                                       const WorkPrecisionSettings& settings,
                                       const IntegratorVariant& variant, double rtol,
                                       const ReferenceSolution& reference);

// All variants and tolerances (loose to tight). After a variant gives up,
// its tighter tolerances are skipped (they would cost more). `progress`
// receives one line per run.
WorkPrecisionResult run_work_precision(const Model& model, double speed_m_per_s,
    const Eigen::VectorXd& x0,
                                       const WorkPrecisionSettings& settings,
                                       const std::function<void(const std::string&)>& progress);

}  // namespace railstab
