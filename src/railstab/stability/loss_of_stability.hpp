#pragma once
// How a steady state loses stability at the critical speed found by the
// bisection on the largest real part (stability/speed_analysis.hpp).
//
// The bisection brackets a change of sign of max Re(lambda) between two
// speeds. That is a crossing of the imaginary axis only if max Re(lambda) is
// continuous in the speed. On real profiles with saturated creep, in a curve
// at high cant deficiency, it need not be: the steady state followed from
// below can end (a fold, or Newton losing it at a contact-point jump), and
// the steady state found above is another one, e.g. a saddle with a real
// eigenvalue of +200 1/s. The bisection then still converges, to the end of
// the branch, and a "critical speed" with the least stable mode of the
// stable side (which never crossed) would be a wrong statement.
//
// Classification from the grid bracket [V0, V1] (largest real parts s0 < 0
// < s1) and the final bracket [v0, v1] (r0 < 0 < r1):
//  - jump: the final bracket is at most a quarter of the grid bracket but
//    the difference r1 - r0 still is at least kJumpShare of s1 - s0. For a
//    continuous max Re(lambda) the difference shrinks with the bracket
//    (r1 - r0 ~ slope (v1 - v0)); it stays finite only if the function
//    jumps. kJumpShare = 0.25 leaves a factor 100 for a local slope steeper
//    than the grid's mean (the default bracket shrinks 250x: 2.5 m/s to
//    0.01 m/s); the thesis cases' crossings stay below 0.02.
//    Within a jump, the steady state itself jumps when its largest
//    translation change across the final bracket exceeds what the grid
//    bracket's mean slope allows over the final bracket's width, times
//    1 / kJumpShare^2 = 16 (plus 1e-9 m of round-off), or when the unstable
//    side's steady state is another one (found by pseudo-transient
//    continuation, not followed from below); otherwise only the
//    eigenvalues jump on a continuous steady state: a contact point
//    appearing or switching makes the Jacobian discontinuous (a coach in a
//    curve with saturated creep: max Re from -0.35 to +0.09 1/s across
//    0.01 m/s with the steady state moving 3e-5 m).
//  - oscillatory_crossing (Hopf: hunting is one): continuous, and the least
//    stable mode at the critical speed oscillates (Im > 0).
//  - aperiodic_crossing (divergence, or the fold of a steady state): a real
//    eigenvalue crosses zero continuously.
//  - fold: the speed grid found no steady state at its next speed, and the
//    branch followed from below, continued by arclength, folds back in
//    speed before it (stability/steady_state_fold.hpp): a saddle-node, the
//    real eigenvalue of the fold mode reaches zero at the fold speed and is
//    positive on the branch's unstable continuation past it. Stable up to
//    the fold, the steady state is lost there; the sides are the
//    continuation's points next to the fold (stable_speed_m_per_s on the
//    branch from below, unstable_speed_m_per_s past the fold, at a lower
//    speed) and the unstable side's least stable mode names the mode. The
//    fold is smooth (a saddle-node) when that mode, matched by eigenvector
//    continuity to the stable side, is there a real negative eigenvalue of
//    comparable size (both go as sqrt(|V - V_fold|)); otherwise the branch
//    turns at a corner where the Jacobian jumps (on S1002 the shipped curve
//    cases' folds are such corners: a complex pair on one side, a real
//    positive eigenvalue on the other).
//  - undetermined: the bracket did not shrink (a bisection midpoint without a
//    steady state stopped it), so continuity cannot be judged.
#include <railstab/model/model.hpp>
#include <railstab/stability/steady_state_fold.hpp>

#include <complex>
#include <string>

namespace railstab {

struct StabilityPoint;  // stability/speed_analysis.hpp (which holds a LossOfStability)

enum class LossOfStabilityKind { oscillatory_crossing, aperiodic_crossing, jump, fold, undetermined };

// "oscillatory_crossing", ... (JSON keys).
std::string loss_of_stability_key(LossOfStabilityKind kind);

struct LossOfStability {
  static constexpr double kJumpShare = 0.25;     // of the grid bracket's difference
  static constexpr double kShrunkBracket = 0.25;  // final/grid bracket width for a judgement
  LossOfStabilityKind kind = LossOfStabilityKind::undetermined;
  // The final bracket: speeds and largest real parts (1/s).
  double stable_speed_m_per_s = 0.0, unstable_speed_m_per_s = 0.0;
  double stable_max_real_part_per_s = 0.0, unstable_max_real_part_per_s = 0.0;
  // The grid bracket's difference of largest real parts (1/s).
  double grid_real_part_difference_per_s = 0.0;
  // The unstable side's least stable mode.
  std::string unstable_mode;
  std::complex<double> unstable_eigenvalue;
  // Largest change of a translation coordinate of the steady state across
  // the final bracket (m) and which: a jump of the steady state shows here.
  double largest_translation_change_m = 0.0;
  std::string largest_translation_change_state;
  // The same across the grid bracket (m), and whether the steady state is
  // continuous across the final bracket (the change shrank with it).
  double grid_translation_change_m = 0.0;
  bool steady_state_continuous = true;
  // The unstable side's steady state came from the pseudo-transient
  // fallback, not from continuation in speed: the branch followed from below
  // could not be continued.
  bool unstable_side_from_pseudo_transient = false;
  // fold: where the branch turns (m/s), and the first, coarser
  // continuation's value (their difference shows how well it is located).
  double fold_speed_m_per_s = 0.0, fold_coarse_speed_m_per_s = 0.0;
  // fold: a smooth fold (saddle-node: the unstable mode's eigenvalue passes
  // through zero), or a corner of the branch where the Jacobian jumps; and
  // that mode's eigenvalue just below the fold (fold_loss_of_stability).
  static constexpr double kSmoothFoldRatio = 10.0;
  bool fold_smooth = false;
  std::complex<double> fold_stable_side_eigenvalue;
};

// grid_stable/grid_unstable: the grid bracket; stable/unstable: the final
// one (the same points when the bisection did not move); at_critical: the
// point evaluated at the critical speed (its least stable mode decides
// oscillatory or aperiodic).
LossOfStability classify_loss_of_stability(const Model& model, const StabilityPoint& grid_stable,
                                           const StabilityPoint& grid_unstable,
                                           const StabilityPoint& stable,
                                           const StabilityPoint& unstable,
                                           const StabilityPoint& at_critical);

// The fold's classification from its two sides, evaluated at the
// continuation's points (kind fold).
LossOfStability fold_loss_of_stability(const StabilityPoint& before, const StabilityPoint& after,
                                       const SteadyStateFold& fold);

// One sentence for reports, e.g. "a jump of the steady state between 47.49
// and 47.5 m/s: no eigenvalue crosses (largest real part -0.0257 1/s below,
// 207 1/s above: wheelset4 spin, aperiodic); ...".
std::string describe_loss_of_stability(const LossOfStability& loss);

}  // namespace railstab
