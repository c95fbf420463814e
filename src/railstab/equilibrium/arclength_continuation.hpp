#pragma once
// Steady states followed along a one-parameter path of problems by
// pseudo-arclength continuation (Keller 1977; Allgower and Georg,
// "Introduction to Numerical Continuation Methods", 2003, ch. 2): the branch
// of solutions u(lambda) of
//
//   F(u, lambda) = 0      (every free acceleration and internal-state rate),
//
// lambda in [0, 1] the path parameter (a speed, a curvature, both), is
// parameterised by its arclength s in the scaled (u, lambda) space, so it is
// followed around a fold (dlambda/ds = 0) where natural continuation in
// lambda (speed_continuation.hpp) must stop: steady curving on real profiles
// folds where a wheelset's contact moves from the tread onto the flange root
// (the coach of cases/coach_s1002_curve.toml at 56.76 m/s), and the branch
// carries on, after a second fold, with the flange against the rail.
//
// One step from (w_k, Lambda_k) with unit tangent t_k (w = u / scale, the
// scaled unknowns; Lambda = L lambda, L the path's length scale):
//   predictor   z_p = z_k + ds t_k,
//   corrector   Newton on  [F(u, lambda); t_k . (z - z_p)] = 0
//               with the matrix [F_u S, F_lambda / L; t_k^T]
//               (F_u exact by forward AD, F_lambda by central differences),
//   tangent     t_{k+1} solves [F_u S, F_lambda / L; t_k^T] t = [0; 1],
//               normalised (so it keeps the direction of travel through a
//               fold);
//   step        a corrector that does not reach |F| <= tolerance in
//               max_corrector_iterations, or moves farther than ds / 2
//               from the prediction (it jumped to another branch), halves ds;
//               one that converges in <= 3 iterations lets ds grow 1.5x.
// The end: the first step that passes lambda = 1 is replaced by Newton's
// method at lambda = 1 exactly (solve_equilibrium, no fallback) from the
// secant interpolation, so the result is a plain Newton solution of the
// target problem. It stops without reaching 1 when ds falls below
// min_step, after max_steps, when lambda returns below -max_backtrack / L
// (the branch turned back for good; between two folds of an S-shaped branch
// it runs back beyond its start before it turns forward again), when the
// speed falls below 1 m/s, or when `stop` says so at a converged point (a
// physical limit, e.g. flange climbing).
#include <railstab/equilibrium/equilibrium.hpp>

#include <functional>
#include <string>
#include <vector>

namespace railstab {

// The problems along the path. model_at may return a reference to storage
// that the next call overwrites (a model whose track is rebuilt per lambda).
class SteadyStatePath {
 public:
  virtual ~SteadyStatePath() = default;
  virtual const Model& model_at(double lambda) = 0;
  virtual double speed_at(double lambda) const = 0;
  // L: the path's length in the continuation's units (a unit of Lambda is
  // about 1 m/s of speed or 1 cm of cant deficiency), so that one unit of
  // scaled arclength moves the vehicle by about a millimetre or the
  // condition by about 1 m/s.
  virtual double length_scale() const = 0;
  // "V = 56.8 m/s, cant deficiency 196 mm, R = 1500 m": where lambda is.
  virtual std::string describe(double lambda) const = 0;
};

// A path in speed alone on one model: V(lambda) = V0 + lambda (V1 - V0).
class SpeedPath : public SteadyStatePath {
 public:
  SpeedPath(const Model& model, double from_m_per_s, double to_m_per_s)
      : model_(model), from_(from_m_per_s), to_(to_m_per_s) {}
  const Model& model_at(double) override { return model_; }
  double speed_at(double lambda) const override { return from_ + lambda * (to_ - from_); }
  double length_scale() const override;
  std::string describe(double lambda) const override;

 private:
  const Model& model_;
  double from_, to_;
};

struct ArclengthOptions {
  double time_s = 0.0;
  double acceleration_tolerance = 1e-7;  // of the final Newton solve at lambda = 1
  // The corrector's tolerance on max |F| (the end point is polished to
  // acceleration_tolerance).
  double corrector_tolerance = 1e-6;
  double initial_step = 0.25;  // scaled arclength
  // Short enough that a corrector does not hop between the two stable
  // branches of an S-shaped fold (on S1002 they lie ~1.4 mm apart).
  double max_step = 1.0;
  // How far behind its start (in units of Lambda: about m/s or cm of cant
  // deficiency) the branch may run between two folds.
  double max_backtrack = 20.0;
  double min_step = 1e-4;
  int max_steps = 600;
  int max_corrector_iterations = 10;
  // Called at every converged point (lambda, state); a non-empty answer
  // stops the continuation there (ArclengthResult::stop_reason).
  std::function<std::string(double lambda, const Eigen::VectorXd& state)> stop;
};

struct ArclengthResult {
  bool reached = false;          // lambda = 1 solved
  EquilibriumResult end;         // at lambda = 1 (reached)
  double last_lambda = 0.0;      // last converged point
  Eigen::VectorXd last_state;
  // The converged point nearest the target (largest lambda): where a failed
  // continuation got to (after a fold the last point may lie behind it).
  double furthest_lambda = 0.0;
  Eigen::VectorXd furthest_state;
  int steps = 0;                 // accepted predictor-corrector steps
  // Each fold passed (a sign change of dlambda/ds), in order: where
  // dlambda/ds changes sign between two converged points. With a =
  // dLambda/ds at the point before, b < 0 (or > 0) at the point after and
  // h = |z_after - z_before| the chord between them, Lambda(s) taken as the
  // quadratic with those end slopes puts the fold at Lambda_before + a^2 h /
  // (2 (a - b)): its error is O(h^3), so a short max_step locates the fold
  // closely (stability/steady_state_fold.hpp). The turning point lies at
  // least as far as both converged points (they are on the branch), so the
  // fold is never put short of them: at a corner of the branch (the
  // Jacobian jumps) the quadratic's vertex can fall just below the point
  // past it.
  struct Fold {
    double lambda = 0.0;           // interpolated, at least before_ and after_lambda
    double before_lambda = 0.0, after_lambda = 0.0;
    Eigen::VectorXd before_state, after_state;
  };
  std::vector<Fold> fold_points;
  std::string stop_reason;       // from options.stop
  std::string failure;           // why it stopped otherwise (not reached)
};

// From the converged state at lambda = 0 (`start`, a solution of
// model_at(0) at speed_at(0)). Never throws for a failure of the solver
// along the path (see ArclengthResult); throws std::invalid_argument for a
// start of the wrong size.
ArclengthResult continue_by_arclength(SteadyStatePath& path, const Eigen::VectorXd& start,
                                      const ArclengthOptions& options = {});

}  // namespace railstab
