#pragma once
// What lies between the last speed of a stability sweep with a steady state
// and the next one without: the branch followed from below either goes on
// (Newton missed it; the sweep resumes on it) or folds back in speed (a
// saddle-node: the Jacobian's real eigenvalue of the fold mode reaches zero
// and the branch returns as unstable steady states). On real profiles in a
// curve that is the tread branch ending where a wheelset's contact moves
// onto the flange root (cases/coach_s1002_curve.toml at 56.76 m/s): above
// the fold no steady state near the one followed exists, so the vehicle
// cannot stay there, and the sweep's "no steady state" is that fold.
//
// Found by pseudo-arclength continuation in speed
// (equilibrium/arclength_continuation.hpp) from the last converged state:
// first with the continuation's default steps; where it passes a fold, once
// more from the same start with steps of at most kRefineMaxStep scaled
// arclength (about 0.1 mm or 0.1 m/s) up to the first fold, and once more
// with a fifth of that from the third point before it. The fold's speed is
// the quadratic interpolation of the speed along the arclength between the
// two points whose tangents straddle it (error O(h^3)); the previous, 5x
// coarser estimate is kept in coarse_speed_m_per_s: their difference bounds
// the error (the finer one's is about 1/125 of it).
#include <railstab/equilibrium/equilibrium.hpp>

#include <optional>
#include <string>

namespace railstab {

struct SteadyStateFold {
  double speed_m_per_s = 0.0;         // from the finest continuation
  double coarse_speed_m_per_s = 0.0;  // the estimate before it (5x longer steps)
  // The converged points on either side of the fold: before on the branch
  // followed from below, after on its continuation past the fold (at a
  // lower speed, one real eigenvalue beyond zero).
  double before_speed_m_per_s = 0.0, after_speed_m_per_s = 0.0;
  Eigen::VectorXd before_state, after_state;
};

struct LostSteadyState {
  std::optional<SteadyStateFold> fold;  // the first fold between from and to
  // The continuation came to the target speed (without a fold: Newton had
  // missed the branch; after folds: on another part of the branch).
  bool reached = false;
  EquilibriumResult at_target;
  std::string failure;  // why the continuation stopped short (neither of the above)
};

inline constexpr double kRefineMaxStep = 0.1;

// `state`: a steady state at from_m_per_s (the sweep's last point),
// to_m_per_s the speed where the sweep found none.
LostSteadyState continue_past_lost_steady_state(const Model& model, const Eigen::VectorXd& state,
                                                double from_m_per_s, double to_m_per_s,
                                                double time_s);

}  // namespace railstab
