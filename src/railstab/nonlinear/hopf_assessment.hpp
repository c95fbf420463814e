#pragma once
// What the critical-speed report says about its Hopf point: the first
// Lyapunov coefficient and the kind (hopf_criticality.hpp), with the
// small-amplitude law of the leading wheelset's lateral cycle, or why they
// were not computed. Not computed:
// - with profile contact: the contact tables are C1 (interpolated between
//   table points), so a third derivative would be the interpolation's, not
//   the profiles'; the kind then comes from the branch of periodic orbits
//   (bifurcation_analysis.hpp: the side of V_c its first orbits lie on);
// - without an oscillatory crossing at the critical speed (a jump of the
//   Jacobian, an aperiodic crossing): there is no Hopf pair.
#include <railstab/nonlinear/hopf_criticality.hpp>

#include <string>

namespace railstab {

struct HopfAssessment {
  bool computed = false;
  std::string not_computed_reason;  // when !computed
  HopfCriticality result;           // when computed
  std::string amplitude_state;      // "<first wheelset>.y_m"
  // a = coefficient * sqrt(|V - V_c|) on the cycle's side (m / sqrt(m/s)).
  double amplitude_coefficient_m_per_sqrt_m_per_s = 0.0;
};

// True when a contact of the model uses profile tables (C1 geometry).
bool has_profile_contact(const Model& model);

// Never throws for a model it cannot assess: the reason says why.
HopfAssessment assess_hopf(const Model& model, const CriticalSpeedResult& result);

// "supercritical (first Lyapunov coefficient -0.0062): a stable hunting
// cycle grows above the critical speed, wheelset1 lateral amplitude about
// 26 mm x sqrt(V - V_c in m/s)", or "not computed: <reason>".
std::string describe_hopf(const HopfAssessment& hopf);

}  // namespace railstab
