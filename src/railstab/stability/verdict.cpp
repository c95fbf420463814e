#include <railstab/stability/verdict.hpp>

#include <iomanip>
#include <sstream>

namespace railstab {

StabilityVerdict stability_verdict(const CriticalSpeedResult& r) {
  if (r.unstable_at_start) return StabilityVerdict::unstable_at_start;
  if (r.critical_speed_found) return StabilityVerdict::critical_speed_found;
  if (r.stable_in_range) return StabilityVerdict::stable_in_range;
  return StabilityVerdict::stable_below_equilibrium_loss;
}

std::string verdict_key(StabilityVerdict v) {
  switch (v) {
    case StabilityVerdict::unstable_at_start: return "unstable_at_start";
    case StabilityVerdict::critical_speed_found: return "critical_speed_found";
    case StabilityVerdict::stable_in_range: return "stable_in_range";
    case StabilityVerdict::stable_below_equilibrium_loss: return "stable_below_equilibrium_loss";
  }
  return "unknown";
}

std::string verdict_sentence(const CriticalSpeedResult& r) {
  std::ostringstream s;
  s << std::setprecision(6);
  switch (stability_verdict(r)) {
    case StabilityVerdict::unstable_at_start:
      s << "already unstable at the lowest speed " << r.from_m_per_s << " m/s";
      break;
    case StabilityVerdict::critical_speed_found:
      s << "critical speed " << std::fixed << std::setprecision(2) << r.critical_speed_m_per_s
        << " m/s";
      if (r.loss.kind == LossOfStabilityKind::jump)
        s << (r.loss.steady_state_continuous
                  ? " (stability lost by a jump of the eigenvalues on a continuous steady state: "
                    "the Jacobian jumps, no eigenvalue crosses)"
                  : " (stability lost by a jump of the steady state, no eigenvalue crosses)");
      else if (r.loss.kind == LossOfStabilityKind::fold)
        s << (r.loss.fold_smooth ? " (the steady state's branch folds back: a real eigenvalue "
                                   "reaches zero, and no steady state near the one followed "
                                   "exists above it)"
                                 : " (the steady state's branch turns back at a corner, where "
                                   "the Jacobian jumps: no steady state near the one followed "
                                   "exists above it, and no eigenvalue crosses)");
      else if (r.loss.kind == LossOfStabilityKind::aperiodic_crossing)
        s << " (a real eigenvalue crosses zero: divergence or the fold of the steady state)";
      break;
    case StabilityVerdict::stable_in_range:
      s << "stable over the whole range " << r.from_m_per_s << " - " << r.to_m_per_s << " m/s";
      break;
    case StabilityVerdict::stable_below_equilibrium_loss:
      s << "stable from " << r.from_m_per_s << " m/s up to "
        << (r.grid.empty() ? r.from_m_per_s : r.grid.back().speed_m_per_s)
        << " m/s only: no steady state from " << r.equilibrium_lost_at_m_per_s
        << " m/s, so the range up to " << r.to_m_per_s << " m/s is not shown stable";
      break;
  }
  return s.str();
}

}  // namespace railstab
