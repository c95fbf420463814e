#pragma once
// The outcome of a critical-speed search as one decision, so that every
// output that states it (the JSON "verdict", the Markdown report, the
// terminal summary, a study's status column) says the same.
#include <railstab/stability/speed_analysis.hpp>

#include <string>

namespace railstab {

enum class StabilityVerdict {
  unstable_at_start,
  critical_speed_found,
  stable_in_range,                // no crossing over the whole range asked
  stable_below_equilibrium_loss,  // no crossing, but the steady state was lost below the top
};
StabilityVerdict stability_verdict(const CriticalSpeedResult& r);
std::string verdict_key(StabilityVerdict v);                 // the JSON "verdict" value
std::string verdict_sentence(const CriticalSpeedResult& r);  // the words all outputs use

}  // namespace railstab
