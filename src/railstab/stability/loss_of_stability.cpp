#include <railstab/stability/loss_of_stability.hpp>

#include <railstab/core/coordinates.hpp>
#include <railstab/eigen/eigen_analysis.hpp>
#include <railstab/stability/speed_analysis.hpp>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace railstab {

std::string loss_of_stability_key(LossOfStabilityKind kind) {
  switch (kind) {
    case LossOfStabilityKind::oscillatory_crossing: return "oscillatory_crossing";
    case LossOfStabilityKind::aperiodic_crossing: return "aperiodic_crossing";
    case LossOfStabilityKind::jump: return "jump";
    case LossOfStabilityKind::fold: return "fold";
    case LossOfStabilityKind::undetermined: return "undetermined";
  }
  return "undetermined";
}

namespace {

// The two sides of a bracket: speeds, largest real parts and the unstable
// side's least stable mode.
LossOfStability bracket_sides(const StabilityPoint& stable, const StabilityPoint& unstable) {
  LossOfStability out;
  out.stable_speed_m_per_s = stable.speed_m_per_s;
  out.unstable_speed_m_per_s = unstable.speed_m_per_s;
  out.stable_max_real_part_per_s = stable.max_real_part;
  out.unstable_max_real_part_per_s = unstable.max_real_part;
  if (unstable.least_stable >= 0) {
    const ModeReport& m = unstable.modes[size_t(unstable.least_stable)];
    out.unstable_mode = m.name;
    out.unstable_eigenvalue = m.eigenvalue;
  }
  return out;
}

}  // namespace

LossOfStability classify_loss_of_stability(const Model& model, const StabilityPoint& grid_stable,
                                           const StabilityPoint& grid_unstable,
                                           const StabilityPoint& stable,
                                           const StabilityPoint& unstable,
                                           const StabilityPoint& at_critical) {
  LossOfStability out = bracket_sides(stable, unstable);
  out.grid_real_part_difference_per_s = grid_unstable.max_real_part - grid_stable.max_real_part;
  out.unstable_side_from_pseudo_transient = unstable.equilibrium.pseudo_transient_steps > 0;
  // Largest change of a translation coordinate between two steady states
  // (rotations are in rad, not comparable with m).
  const auto largest_change = [&](const Eigen::VectorXd& a, const Eigen::VectorXd& b,
                                  std::string* state) {
    double largest = 0.0;
    if (a.size() != b.size()) return largest;
    for (int i = 0; i < model.n_coordinates; ++i) {
      const int c = model.coordinate_of_state[size_t(i)].second;
      if (c > int(CoordinateIndex::z)) continue;
      const double d = std::abs(b(i) - a(i));
      if (d > largest) {
        largest = d;
        if (state) *state = model.state_name(i);
      }
    }
    return largest;
  };
  out.largest_translation_change_m = largest_change(
      stable.equilibrium.state, unstable.equilibrium.state, &out.largest_translation_change_state);
  out.grid_translation_change_m =
      largest_change(grid_stable.equilibrium.state, grid_unstable.equilibrium.state, nullptr);

  const double grid_width = grid_unstable.speed_m_per_s - grid_stable.speed_m_per_s;
  const double width = unstable.speed_m_per_s - stable.speed_m_per_s;
  const double difference = unstable.max_real_part - stable.max_real_part;
  if (!(width <= LossOfStability::kShrunkBracket * grid_width)) {
    out.kind = LossOfStabilityKind::undetermined;
  } else if (difference >= LossOfStability::kJumpShare * out.grid_real_part_difference_per_s) {
    out.kind = LossOfStabilityKind::jump;
    // Continuous: the final bracket's change is what the grid bracket's mean
    // slope allows with the same factor as the real part's rule (1 /
    // kJumpShare^2 = 16 times steeper), plus round-off; and the unstable
    // side is the branch followed from below, not another steady state.
    const double allowed = out.grid_translation_change_m / grid_width * width /
                               (LossOfStability::kJumpShare * LossOfStability::kJumpShare) +
                           1e-9;
    out.steady_state_continuous =
        out.largest_translation_change_m <= allowed && !out.unstable_side_from_pseudo_transient;
  } else {
    const bool oscillatory = at_critical.least_stable >= 0 &&
                             !(at_critical.modes[size_t(at_critical.least_stable)].frequency_hz == 0.0);
    out.kind = oscillatory ? LossOfStabilityKind::oscillatory_crossing
                           : LossOfStabilityKind::aperiodic_crossing;
  }
  return out;
}

LossOfStability fold_loss_of_stability(const StabilityPoint& before, const StabilityPoint& after,
                                       const SteadyStateFold& fold) {
  LossOfStability out = bracket_sides(before, after);
  out.kind = LossOfStabilityKind::fold;
  out.grid_real_part_difference_per_s = after.max_real_part - before.max_real_part;
  out.fold_speed_m_per_s = fold.speed_m_per_s;
  out.fold_coarse_speed_m_per_s = fold.coarse_speed_m_per_s;
  // Smooth (a saddle-node) where the unstable mode past the fold is, below
  // it, a real eigenvalue on its way to zero: the mode matched to it by
  // eigenvector continuity is real and negative, within a factor
  // kSmoothFoldRatio of its value past the fold (both scale as
  // sqrt(|V - V_fold|) and the two points lie about as far from the fold).
  // Otherwise the branch turns at a corner, where the Jacobian jumps.
  out.fold_smooth = false;
  if (after.least_stable >= 0) {
    // The stable side's mode most like it (largest MAC; match_modes pairs
    // oscillatory modes only, and this one is real).
    const Eigen::VectorXcd& v = after.modes[size_t(after.least_stable)].vector;
    int j = -1;
    double best = 0.0;
    for (size_t k = 0; k < before.modes.size(); ++k) {
      const ModeReport& m = before.modes[k];
      if (m.neutral || m.eigenvalue.imag() < 0.0 || m.vector.size() != v.size()) continue;
      const double mac = modal_assurance(v, m.vector);
      if (mac > best) {
        best = mac;
        j = int(k);
      }
    }
    if (j >= 0) {
      const std::complex<double> b = before.modes[size_t(j)].eigenvalue;
      const double a = out.unstable_eigenvalue.real();
      out.fold_stable_side_eigenvalue = b;
      out.fold_smooth = b.imag() == 0.0 && b.real() < 0.0 && a > 0.0 &&
                        -b.real() <= LossOfStability::kSmoothFoldRatio * a &&
                        a <= LossOfStability::kSmoothFoldRatio * -b.real();
    }
  }
  return out;
}

std::string describe_loss_of_stability(const LossOfStability& loss) {
  std::ostringstream s;
  s.precision(4);
  switch (loss.kind) {
    case LossOfStabilityKind::oscillatory_crossing:
      s << "an oscillatory mode crosses into the right half-plane (Hopf)";
      break;
    case LossOfStabilityKind::aperiodic_crossing:
      s << "a real eigenvalue crosses zero (divergence, or the fold of the steady state)";
      break;
    case LossOfStabilityKind::jump:
      s.precision(8);  // the bracket may be 1e-6 m/s wide
      s << (loss.steady_state_continuous ? "a jump of the eigenvalues on a continuous steady state"
                                         : "a jump of the steady state")
        << " between " << loss.stable_speed_m_per_s << " and " << loss.unstable_speed_m_per_s
        << " m/s, not a crossing: the largest real part is ";
      s.precision(4);
      s << loss.stable_max_real_part_per_s << " 1/s below and " << loss.unstable_max_real_part_per_s
        << " 1/s above (" << loss.unstable_mode;
      if (loss.unstable_eigenvalue.imag() == 0.0) s << ", real eigenvalue";
      s << ")";
      if (loss.largest_translation_change_m > 0.0)
        s << "; the steady state moves by " << loss.largest_translation_change_m * 1e3 << " mm ("
          << loss.largest_translation_change_state << "; "
          << loss.grid_translation_change_m * 1e3 << " mm across the grid step)";
      if (loss.steady_state_continuous)
        s << "; the Jacobian is discontinuous there (a contact point appears or switches), so "
             "no eigenvalue crosses the axis smoothly";
      if (loss.unstable_side_from_pseudo_transient)
        s << "; above, the steady state followed from below could not be continued and "
             "another one was found by pseudo-transient continuation";
      break;
    case LossOfStabilityKind::fold:
      s.precision(6);
      s << "the steady state's branch folds back in speed at " << loss.fold_speed_m_per_s
        << " m/s: above it no steady state near the one followed from below exists. Past the fold the branch returns to lower speeds as unstable "
           "steady states (at "
        << loss.unstable_speed_m_per_s << " m/s the largest real part is ";
      s.precision(4);
      s << loss.unstable_max_real_part_per_s << " 1/s: " << loss.unstable_mode;
      if (loss.unstable_eigenvalue.imag() == 0.0) s << ", real eigenvalue";
      s << "; below the fold, at " << std::setprecision(6) << loss.stable_speed_m_per_s
        << " m/s, " << std::setprecision(4) << loss.stable_max_real_part_per_s << " 1/s). ";
      if (loss.fold_smooth)
        s << "A smooth fold: that mode's real eigenvalue is " << loss.fold_stable_side_eigenvalue.real()
          << " 1/s just below it.";
      else
        s << "Not a smooth fold: the branch turns at a corner, where the Jacobian jumps (a "
             "contact point appears or switches): just below it the same mode has the "
             "eigenvalue "
          << loss.fold_stable_side_eigenvalue.real() << (loss.fold_stable_side_eigenvalue.imag() < 0 ? " - " : " + ")
          << std::abs(loss.fold_stable_side_eigenvalue.imag())
          << "i 1/s, so no eigenvalue passes through zero.";
      s << " Located to " << std::abs(loss.fold_speed_m_per_s - loss.fold_coarse_speed_m_per_s)
        << " m/s (the last two refinements of the continuation)";
      break;
    case LossOfStabilityKind::undetermined:
      s << "not judged (the bisection did not narrow the bracket)";
      break;
  }
  return s.str();
}

}  // namespace railstab
