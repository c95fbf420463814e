// The linearisation hot path before and after issue 11, measured in one run
// (CPU time of this process, 5 batches of >= 0.2 s, median of the batch
// means), on the thesis vehicle and the coach:
//  - the AD Jacobian: dense (one direction per column, kAdChunk per
//    evaluation: the old product path) against coloured (one direction per colour of
//    the structural pattern), in residual evaluations (rhs<double>) per
//    Jacobian; the planning (pattern + colouring) alone;
//  - the equilibrium Newton Jacobian: the whole coloured Jacobian with the
//    equations' rows and unknowns' columns copied out (as before) against
//    the coloured Jacobian of those rows and columns only;
//  - eigen_dense: the old one (one QR on the whole matrix,
//    EigenSolver::eigenvectors() rebuilt for every column) against the
//    current one (vectors built once; one QR per diagonal block where the
//    balanced matrix decouples, eigen/decoupled_blocks.hpp), with the
//    results compared bit for bit (one block) or eigenvalue by eigenvalue;
//  - a critical-speed search in-process (CLI defaults: 5..150 m/s, grid
//    2.5 m/s, automatic solver; no plots), the number the build flags are
//    chosen by (its critical speed printed to 12 digits).
//   build/bench_jacobian [cases-dir]
//   build/bench_jacobian [cases-dir] --profile-search N   (N searches and
//     nothing else: a steady workload for perf or callgrind)
//   build/bench_jacobian [cases-dir] --profile-jacobian N (N coloured AD
//     Jacobians of the thesis vehicle, likewise)
#include "cpu_timing.hpp"
#include "support/column_by_column_eigen.hpp"
#include <railstab/eigen/balance.hpp>
#include <railstab/eigen/decoupled_blocks.hpp>
#include <railstab/eigen/eigen_analysis.hpp>
#include <railstab/equilibrium/equilibrium.hpp>
#include <railstab/linear/jacobian.hpp>
#include <railstab/linear/linearization.hpp>
#include <railstab/model/equations_of_motion.hpp>
#include <railstab/setup/prepare_scene.hpp>
#include <railstab/stability/speed_analysis.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <complex>
#include <cstdio>
#include <ctime>
#include <functional>
#include <string>
#include <vector>

using namespace railstab;

namespace {

using bench::cpu_seconds;

// CPU seconds per call: a warm-up call, then 5 batches of at least
// `batch_s` each; the median of the batch means.
double seconds_per_call(const std::function<void()>& call, double batch_s = 0.2) {
  call();
  return bench::median_of_batches(call, 5, batch_s);
}

// --- eigen_dense as it was before issue 11 (reference for the timing):
// tests/support/column_by_column_eigen.hpp with the eigenvector matrix
// rebuilt per column, as the old loop did.
std::vector<EigenPair> legacy_eigen_dense(const Eigen::MatrixXd& A) {
  return test::column_by_column_eigen(A, /*eigenvectors_per_column=*/true);
}

bool same_pairs(const std::vector<EigenPair>& a, const std::vector<EigenPair>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (a[i].value != b[i].value || a[i].vector != b[i].vector ||
        std::abs(a[i].residual - b[i].residual) > 1e-14)  // residuals: round-off either way
      return false;
  return true;
}

// " (bit-identical ...)" where the legacy and current results agree bit for
// bit (one QR on the whole matrix either way); where A decouples into blocks
// the current values come from other QRs: the largest distance of a legacy
// eigenvalue to the nearest current one, relative to max(1, |lambda|).
std::string agreement(const std::vector<EigenPair>& legacy, const std::vector<EigenPair>& now) {
  if (same_pairs(now, legacy)) return " (bit-identical values and vectors)";
  if (legacy.size() != now.size()) return " (DIFFERENT counts!)";
  double worst = 0.0;
  for (const EigenPair& l : legacy) {
    double nearest = INFINITY;
    for (const EigenPair& p : now) nearest = std::min(nearest, std::abs(p.value - l.value));
    worst = std::max(worst, nearest / std::max(1.0, std::abs(l.value)));
  }
  char text[96];
  std::snprintf(text, sizeof text, " (eigenvalues equal to %.1e relative)", worst);
  return text;
}

void bench_scene(const std::string& path, bool search) {
  const PreparedScene scene = prepare_scene(path, {});
  const Model& model = scene.model;
  const double V = scene.speed_m_per_s;
  const Eigen::VectorXd x = perturbed_initial_state(scene);
  const int n = model.state_size();
  std::printf("%s: %d bodies, %d states\n", model.name.c_str(), int(model.bodies.size()), n);

  Workspace<double> ws(model);
  Eigen::VectorXd xdot;
  const double t_rhs = seconds_per_call([&] { evaluate_rhs<double>(model, ws, 0.0, V, x, xdot); });
  const RhsJacobianPlan plan = plan_rhs_jacobian(model);
  const double t_plan = seconds_per_call([&] { plan_rhs_jacobian(model); });
  const double t_dense = seconds_per_call([&] { rhs_jacobian_ad_dense(model, V, 0.0, x); });
  const double t_col = seconds_per_call([&] { rhs_jacobian_ad(model, plan, V, 0.0, x); });
  const double t_col_planned =
      seconds_per_call([&] { rhs_jacobian_ad(model, V, 0.0, x); });
  const bool equal =
      rhs_jacobian_ad(model, plan, V, 0.0, x) == rhs_jacobian_ad_dense(model, V, 0.0, x);
  std::printf("  pattern: %ld non-zeros (%.1f %% dense), longest row %d; %d colours, %d AD "
              "evaluations (dense AD: %d)\n",
              plan.pattern.nonzeros(), 100.0 * plan.pattern.density(),
              plan.pattern.max_row_nonzeros(), plan.colouring.colours, plan.passes(),
              (n + kAdChunk - 1) / kAdChunk);
  std::printf("  rhs<double>                    %9.2f us\n", t_rhs * 1e6);
  std::printf("  AD Jacobian, dense (before)    %9.2f us = %5.1f rhs\n", t_dense * 1e6,
              t_dense / t_rhs);
  std::printf("  AD Jacobian, coloured (after)  %9.2f us = %5.1f rhs   after/before %.3f%s\n",
              t_col * 1e6, t_col / t_rhs, t_col / t_dense,
              equal ? "  (bit-identical)" : "  (DIFFERENT!)");
  std::printf("    planning alone               %9.2f us; coloured incl. planning %.2f us = %.1f rhs\n",
              t_plan * 1e6, t_col_planned * 1e6, t_col_planned / t_rhs);

  // Equilibrium Newton: before, the whole Jacobian and a copy of the block.
  std::vector<int> rows;
  for (int k = model.n_coordinates; k < n; ++k) rows.push_back(k);
  const std::vector<int> unknowns = equilibrium_unknowns(model);
  const RhsJacobianPlan eq_plan = plan_rhs_jacobian(model, rows, unknowns);
  const Eigen::VectorXd xe = scene.equilibrium.state;
  const double t_eq_before = seconds_per_call([&] {
    const Eigen::MatrixXd jac = rhs_jacobian_ad(model, plan, V, 0.0, xe);
    Eigen::MatrixXd J(rows.size(), unknowns.size());
    for (size_t i = 0; i < rows.size(); ++i)
      for (size_t j = 0; j < unknowns.size(); ++j)
        J(Eigen::Index(i), Eigen::Index(j)) = jac(rows[i], unknowns[j]);
  });
  const double t_eq_dense = seconds_per_call([&] {
    const Eigen::MatrixXd jac = rhs_jacobian_ad_dense(model, V, 0.0, xe);
    Eigen::MatrixXd J(rows.size(), unknowns.size());
    for (size_t i = 0; i < rows.size(); ++i)
      for (size_t j = 0; j < unknowns.size(); ++j)
        J(Eigen::Index(i), Eigen::Index(j)) = jac(rows[i], unknowns[j]);
  });
  const double t_eq_after = seconds_per_call([&] { rhs_jacobian_ad(model, eq_plan, V, 0.0, xe); });
  std::printf("  equilibrium Jacobian (%zu x %zu): dense %.2f us = %.1f rhs; whole coloured %.2f "
              "us; unknowns only %.2f us = %.1f rhs (%d colours, %d evaluations); "
              "after/dense %.3f\n",
              rows.size(), unknowns.size(), t_eq_dense * 1e6, t_eq_dense / t_rhs,
              t_eq_before * 1e6, t_eq_after * 1e6, t_eq_after / t_rhs,
              eq_plan.colouring.colours, eq_plan.passes(), t_eq_after / t_eq_dense);

  const LinearModel lin = linearize(model, V, scene.equilibrium.state);
  const double t_eig_before = seconds_per_call([&] { legacy_eigen_dense(lin.A); });
  const double t_eig_after = seconds_per_call([&] { eigen_dense(lin.A); });
  // The QR alone: on A as it comes, and on the balanced matrix (with the
  // balancing), which is what eigen_dense runs; the floor takes the faster.
  const double t_solver_unbalanced =
      seconds_per_call([&] { Eigen::EigenSolver<Eigen::MatrixXd> s(lin.A, true); });
  const double t_solver_balanced = seconds_per_call(
      [&] { Eigen::EigenSolver<Eigen::MatrixXd> s(balance(lin.A).matrix, true); });
  const double t_solver = std::min(t_solver_unbalanced, t_solver_balanced);
  // The QR on the diagonal blocks the balanced matrix decouples into
  // (eigen/decoupled_blocks.hpp), balancing and splitting included: what
  // eigen_dense runs where A decouples.
  const std::vector<std::vector<int>> blocks = decoupled_blocks(balance(lin.A).matrix);
  const double t_solver_blocks = seconds_per_call([&] {
    const Eigen::MatrixXd B = balance(lin.A).matrix;
    for (const std::vector<int>& b : decoupled_blocks(B)) {
      const Eigen::MatrixXd part = B(b, b);
      Eigen::EigenSolver<Eigen::MatrixXd> s(part, true);
    }
  });
  std::printf("  eigen_dense (%d states, %zu block%s): before %.3f ms, after %.3f ms (after/before %.3f; "
              "EigenSolver alone %.3f ms on A, %.3f ms balanced incl. balancing: %.3f; on the "
              "blocks %.3f ms)%s\n",
              int(lin.A.rows()), blocks.size(), blocks.size() == 1 ? "" : "s", t_eig_before * 1e3,
              t_eig_after * 1e3, t_eig_after / t_eig_before, t_solver_unbalanced * 1e3,
              t_solver_balanced * 1e3, t_solver_balanced / t_solver_unbalanced,
              t_solver_blocks * 1e3,
              agreement(legacy_eigen_dense(lin.A), eigen_dense(lin.A)).c_str());

  if (!search) return;
  CriticalSpeedOptions cs;  // the CLI's defaults for critical-speed
  cs.from_m_per_s = 5.0;
  cs.to_m_per_s = 150.0;
  cs.grid_step_m_per_s = 2.5;
  CriticalSpeedResult r;
  const double t_search = seconds_per_call(
      [&] { r = find_critical_speed(model, scene.equilibrium.state, V, cs); }, 0.5);
  std::printf("  critical-speed search (5..150 m/s, step 2.5, no plots): %.4f s CPU, %d speeds, "
              "V_crit %.12g m/s\n",
              t_search, r.evaluations, r.critical_speed_found ? r.critical_speed_m_per_s : 0.0);
  // The floor: per speed one dense eigen-solve and one coloured Jacobian,
  // nothing else (issue 11's target: the search within 1.2x of it). As the
  // issue defined it (one QR on the whole matrix) and with the QR on the
  // decoupled blocks (the best dense solve now).
  const double floor_s = r.evaluations * (t_solver + t_col);
  const double floor_blocks_s = r.evaluations * (std::min(t_solver, t_solver_blocks) + t_col);
  std::printf("  floor %d x (EigenSolver %.3f ms + coloured Jacobian %.3f ms) = %.4f s; "
              "search / floor %.2f\n",
              r.evaluations, t_solver * 1e3, t_col * 1e3, floor_s, t_search / floor_s);
  std::printf("  floor with the QR on the blocks %d x (%.3f ms + %.3f ms) = %.4f s; search / floor %.2f\n",
              r.evaluations, std::min(t_solver, t_solver_blocks) * 1e3, t_col * 1e3, floor_blocks_s,
              t_search / floor_blocks_s);
}

// The thesis vehicle's default-range search, `repeats` times (for profilers).
void profile_search(const std::string& dir, int repeats) {
  const PreparedScene scene = prepare_scene(dir + "/thesis_vehicle_tangent.toml", {});
  CriticalSpeedOptions cs;
  cs.from_m_per_s = 5.0;
  cs.to_m_per_s = 150.0;
  cs.grid_step_m_per_s = 2.5;
  CriticalSpeedResult r;
  const double start = cpu_seconds();
  for (int i = 0; i < repeats; ++i)
    r = find_critical_speed(scene.model, scene.equilibrium.state, scene.speed_m_per_s, cs);
  std::printf("%d searches: %.4f s CPU each, %d speeds, V_crit %.12g m/s\n", repeats,
              (cpu_seconds() - start) / repeats, r.evaluations, r.critical_speed_m_per_s);
}

void profile_jacobian(const std::string& dir, int repeats) {
  const PreparedScene scene = prepare_scene(dir + "/thesis_vehicle_tangent.toml", {});
  const RhsJacobianPlan plan = plan_rhs_jacobian(scene.model);
  const double start = cpu_seconds();
  double sum = 0.0;
  for (int i = 0; i < repeats; ++i)
    sum += rhs_jacobian_ad(scene.model, plan, scene.speed_m_per_s, 0.0, scene.equilibrium.state)(0, 0);
  std::printf("%d Jacobians: %.2f us CPU each (%g)\n", repeats,
              1e6 * (cpu_seconds() - start) / repeats, sum);
}

}  // namespace

int main(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : "cases";
  if (argc > 3 && std::string(argv[2]) == "--profile-search") {
    profile_search(dir, std::max(1, std::atoi(argv[3])));
    return 0;
  }
  if (argc > 3 && std::string(argv[2]) == "--profile-jacobian") {
    profile_jacobian(dir, std::max(1, std::atoi(argv[3])));
    return 0;
  }
  bench_scene(dir + "/thesis_vehicle_tangent.toml", true);
  bench_scene(dir + "/coach_tangent.toml", false);
  return 0;
}
