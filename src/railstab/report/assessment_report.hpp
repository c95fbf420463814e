#pragma once
// `railstab assess`'s outputs (docs/assessment.md): <stem>_assessment.json,
// <stem>_assessment.md, <stem>_assessment_windows.csv and, with plots,
// <stem>_assessment_rms.png (every stability rms over distance as a
// fraction of its limit) from <stem>_assessment_plots.gp.
#include <railstab/assessment/assessment_run.hpp>
#include <railstab/assessment/running_stability.hpp>
#include <railstab/io/output_set.hpp>
#include <railstab/model/model.hpp>

#include <string>

namespace railstab {

// Returns the text for the terminal.
std::string write_assessment_report(const Model& model, const RunningStabilityAssessment& a,
                                    const AssessmentSpec& spec, const AssessmentRunConditions& run,
                                    OutputSet& outputs, const std::string& stem, bool plots);

}  // namespace railstab
