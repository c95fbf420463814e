#include <railstab/nonlinear/hopf_assessment.hpp>

#include <algorithm>
#include <cstdio>
#include <exception>

namespace railstab {

bool has_profile_contact(const Model& model) {
  for (const ModelContact& c : model.contacts)
    if (uses_contact_table(c.spec.geometry)) return true;
  return false;
}

HopfAssessment assess_hopf(const Model& model, const CriticalSpeedResult& r) {
  HopfAssessment a;
  if (!r.critical_speed_found) {
    a.not_computed_reason = "no critical speed in the range";
    return a;
  }
  if (r.loss.kind != LossOfStabilityKind::oscillatory_crossing) {
    a.not_computed_reason = "the stability is not lost by a complex pair crossing the imaginary "
                            "axis (no Hopf point)";
    return a;
  }
  if (has_profile_contact(model)) {
    a.not_computed_reason =
        "profile contact: the contact tables are only C1 (interpolated between table points), "
        "so the third derivatives would be the interpolation's; the kind follows from the "
        "branch of periodic orbits instead (docs/nonlinear.md)";
    return a;
  }
  try {
    a.result = hopf_criticality(model, r);
    a.computed = true;
  } catch (const std::exception& e) {
    a.not_computed_reason = std::string("the Hopf analysis failed: ") + e.what();
    return a;
  }
  for (size_t b = 0; b < model.bodies.size(); ++b)
    if (model.bodies[b].wheelset()) {
      a.amplitude_state = model.bodies[b].name + ".y_m";
      break;
    }
  const auto& names = a.result.state_names;
  const auto it = std::find(names.begin(), names.end(), a.amplitude_state);
  if (it != names.end() && a.result.amplitude_per_sqrt_speed.size() == Eigen::Index(names.size()))
    a.amplitude_coefficient_m_per_sqrt_m_per_s =
        a.result.amplitude_per_sqrt_speed(Eigen::Index(it - names.begin()));
  else
    a.amplitude_state.clear();
  return a;
}

std::string describe_hopf(const HopfAssessment& h) {
  if (!h.computed) return "not computed: " + h.not_computed_reason;
  char l1[64];
  std::snprintf(l1, sizeof l1, "%.4g", h.result.first_lyapunov_coefficient);
  std::string s = hopf_kind_name(h.result.kind) + " (first Lyapunov coefficient " + l1 + ")";
  if (h.result.kind == HopfKind::degenerate) return s + ": the cubic order does not decide";
  const bool above = h.result.cycle_side > 0;
  if (h.result.kind == HopfKind::supercritical)
    s += above ? ": a stable hunting cycle grows from zero above the critical speed"
               : ": a stable cycle exists below the critical speed";
  else
    s += h.result.cycle_side < 0
             ? ": an unstable cycle exists below the critical speed, so the vehicle can hunt "
               "below it after a large enough disturbance"
             : ": an unstable cycle exists above the critical speed";
  if (!h.amplitude_state.empty() && h.amplitude_coefficient_m_per_sqrt_m_per_s > 0.0) {
    char a[96];
    std::snprintf(a, sizeof a, "; %s amplitude about %.3g mm x sqrt(|V - V_c| in m/s)",
                  h.amplitude_state.c_str(), 1e3 * h.amplitude_coefficient_m_per_sqrt_m_per_s);
    s += a;
  }
  return s;
}

}  // namespace railstab
