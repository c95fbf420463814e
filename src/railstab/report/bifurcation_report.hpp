#pragma once
// The bifurcation analysis (nonlinear/bifurcation_analysis.hpp) as files:
// the JSON (linear and nonlinear critical speeds, their ratio, the Hopf
// kind, every branch with its orbits and bifurcations and why it stopped),
// the CSV of the branch points, the Markdown report with the scene's run
// conditions and what was (and was not) computed, and the bifurcation
// diagram (the leading wheelset's lateral amplitude against speed; stable
// orbits solid, unstable dashed, the steady state on the axis, both
// critical speeds marked) as PNG and SVG. Names: docs/outputs.md.
#include <railstab/io/output_set.hpp>
#include <railstab/model/model.hpp>
#include <railstab/nonlinear/bifurcation_analysis.hpp>

#include <ostream>
#include <string>
#include <vector>

namespace railstab {

struct BifurcationFiles {
  std::string json, csv, markdown;
  std::vector<std::string> plots;  // the PNGs (empty without plots)
};

// What the run was asked for, stated in the report beside the result.
struct BifurcationRunInfo {
  std::string eigen_solver;        // of the linear search
  double hunting_band_hz = 20.0;
};

// Adds every file, named <stem>_bifurcation..., to `outputs` (staged; the
// caller commits). With `plots`, the diagram's data and gnuplot script and
// its PNG and SVG (gnuplot run and checked; throws GnuplotError).
BifurcationFiles write_bifurcation_results(const Model& model, const BifurcationResult& result,
                                           const BifurcationRunInfo& info, OutputSet& outputs,
                                           const std::string& stem, bool plots = true);

// Every name write_bifurcation_results may write for `stem`.
std::vector<std::string> bifurcation_file_names(const std::string& stem);

// The outcome for the terminal: both critical speeds and their ratio, the
// Hopf kind, one line per branch.
void print_bifurcation_summary(std::ostream& out, const Model& model, const BifurcationResult& r);

// Nonlinear over linear critical speed; NaN when either is missing (the
// JSON then writes null).
double nonlinear_to_linear_ratio(const BifurcationResult& r);

}  // namespace railstab
