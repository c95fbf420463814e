#pragma once
// Results of the work-precision study (integrate/work_precision.hpp) as
// files: one CSV row per run, a Markdown report (how error and work are
// measured, every run, the cheapest run per error bound) and the gnuplot
// plot of error against CPU time.
#include <railstab/integrate/work_precision.hpp>
#include <railstab/io/output_set.hpp>
#include <railstab/model/model.hpp>

#include <ostream>
#include <string>
#include <vector>

namespace railstab {

// integrator,relative_tolerance,absolute_tolerance,position_error,cpu_s,...
// (outcome columns empty for a run without a result; the status column says
// why).
void write_work_precision_csv(std::ostream& out, const WorkPrecisionResult& r);

void write_work_precision_markdown(std::ostream& out, const Model& model, double speed_m_per_s,
                                   const WorkPrecisionSettings& s, const WorkPrecisionResult& r);

// The names write_work_precision_plot writes for `stem` (.dat, .gp, .png).
std::vector<std::string> work_precision_plot_file_names(const std::string& stem);

// Adds <stem>_work_precision.dat / .gp to `outputs`, runs gnuplot in its
// staging folder and checks the PNG (throws GnuplotError otherwise).
void write_work_precision_plot(OutputSet& outputs, const std::string& stem, const Model& model,
                               double speed_m_per_s, double t_end,
                               const WorkPrecisionResult& r);

}  // namespace railstab
