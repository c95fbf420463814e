#pragma once
// Results of the speed analysis as files: eigenvalues over speed (CSV),
// tracked modes (gnuplot data), root-locus / damping / frequency plots,
// the critical-speed JSON and the Markdown report that links the plots.
#include <railstab/io/output_set.hpp>
#include <railstab/model/model.hpp>
#include <railstab/nonlinear/hopf_assessment.hpp>
#include <railstab/stability/quasi_linear_critical_speed.hpp>
#include <railstab/stability/speed_analysis.hpp>
#include <railstab/stability/verdict.hpp>

#include <ostream>
#include <string>
#include <vector>

namespace railstab {

// File names in the output folder.
struct StabilityFiles {
  std::string csv, json, markdown;
  std::vector<std::string> plots;
};

// Adds every file, named <stem>_..., to `outputs` (staged; the caller
// commits): eigenvalue CSV, JSON, Markdown and, with `plots`, the gnuplot
// data, script, PNGs and SVGs (gnuplot run and checked; throws GnuplotError).
// `max_plot_frequency_hz` keeps the stiff contact modes off the plots and
// bounds the JSON's modes_at_critical_speed (each with its shape). `hopf`:
// the Hopf criticality at the critical speed (assess_hopf), written when
// given (the JSON's first_lyapunov_coefficient and hopf_kind are null
// without it).
// `quasi_linear`: the result is the quasi-linear model's at an amplitude
// (stability/quasi_linear_critical_speed.hpp): the JSON gets its
// "quasi_linear" object, the Markdown its section.
StabilityFiles write_stability_results(const Model& model, const CriticalSpeedResult& result,
                                       OutputSet& outputs, const std::string& stem,
                                       const std::string& eigen_solver_name, bool plots = true,
                                       double max_plot_frequency_hz = 20.0,
                                       const HopfAssessment* hopf = nullptr,
                                       const QuasiLinearCriticalSpeed* quasi_linear = nullptr);

// The outcome for the terminal: the critical speed (or stable / unstable
// over the range), where the steady state was lost, the first validity
// warning, the first unstable mode above the hunting band
// (`hunting_band_hz`), the number of speed evaluations and their time.
void print_critical_speed_summary(std::ostream& out, const Model& model,
                                  const CriticalSpeedResult& r, double hunting_band_hz,
                                  const HopfAssessment* hopf = nullptr);

// Every name write_stability_results may write for `stem`.
std::vector<std::string> stability_file_names(const std::string& stem);

}  // namespace railstab
