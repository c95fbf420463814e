#pragma once
// `railstab assess`'s outputs (docs/assessment.md): <stem>_assessment.json,
// <stem>_assessment.md, <stem>_assessment_windows.csv and, with plots,
// <stem>_assessment_rms.png (every stability rms over distance as a
// fraction of its limit) from <stem>_assessment_plots.gp.
#include <railstab/assessment/running_stability.hpp>
#include <railstab/io/output_set.hpp>
#include <railstab/model/model.hpp>

#include <string>

namespace railstab {

struct AssessmentRunConditions {
  double speed_m_per_s = 0.0;
  std::string excitation;  // how the run was disturbed
  std::string integrator;
  double relative_tolerance = 0.0;
  double output_interval_s = 0.0;  // the scene's, or 0.5 m / V if smaller
  double simulated_s = 0.0;
};

// Returns the text for the terminal.
std::string write_assessment_report(const Model& model, const RunningStabilityAssessment& a,
                                    const AssessmentSpec& spec, const AssessmentRunConditions& run,
                                    OutputSet& outputs, const std::string& stem, bool plots);

}  // namespace railstab
