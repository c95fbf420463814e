#include <railstab/stability/loss_of_stability.hpp>

#include <railstab/core/coordinates.hpp>
#include <railstab/stability/speed_analysis.hpp>

#include <cmath>
#include <sstream>

namespace railstab {

std::string loss_of_stability_key(LossOfStabilityKind kind) {
  switch (kind) {
    case LossOfStabilityKind::oscillatory_crossing: return "oscillatory_crossing";
    case LossOfStabilityKind::aperiodic_crossing: return "aperiodic_crossing";
    case LossOfStabilityKind::jump: return "jump";
    case LossOfStabilityKind::undetermined: return "undetermined";
  }
  return "undetermined";
}

LossOfStability classify_loss_of_stability(const Model& model, const StabilityPoint& grid_stable,
                                           const StabilityPoint& grid_unstable,
                                           const StabilityPoint& stable,
                                           const StabilityPoint& unstable,
                                           const StabilityPoint& at_critical) {
  LossOfStability out;
  out.stable_speed_m_per_s = stable.speed_m_per_s;
  out.unstable_speed_m_per_s = unstable.speed_m_per_s;
  out.stable_max_real_part_per_s = stable.max_real_part;
  out.unstable_max_real_part_per_s = unstable.max_real_part;
  out.grid_real_part_difference_per_s = grid_unstable.max_real_part - grid_stable.max_real_part;
  if (unstable.least_stable >= 0) {
    const ModeReport& m = unstable.modes[size_t(unstable.least_stable)];
    out.unstable_mode = m.name;
    out.unstable_eigenvalue = m.eigenvalue;
  }
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
    case LossOfStabilityKind::undetermined:
      s << "not judged (the bisection did not narrow the bracket)";
      break;
  }
  return s.str();
}

}  // namespace railstab
