#pragma once
// Results of `verify` (verify/verification.hpp) as files and text: the JSON
// of the comparison eigenvalue / fitted damped sinusoid, the gnuplot data,
// script and PNG of the fit, and the summary for the terminal.
#include <railstab/io/output_set.hpp>
#include <railstab/model/model.hpp>
#include <railstab/verify/verification.hpp>

#include <ostream>
#include <string>
#include <vector>

namespace railstab {

// The comparison as one JSON object (scene, speed, eigenvalue, fit, window,
// integration error and settings).
void write_verification_json(std::ostream& out, const Model& model, const VerificationResult& r);

// The names write_verification_plot writes for `stem`: <stem>_fit.dat,
// <stem>_fit.gp, <stem>_fit.png.
std::vector<std::string> verification_plot_file_names(const std::string& stem);

// Adds <stem>_fit.dat (time, signal and fit in mm) and <stem>_fit.gp to
// `outputs`, runs gnuplot in its staging folder and checks the PNG
// (throws GnuplotError otherwise).
void write_verification_plot(const VerificationResult& r, OutputSet& outputs,
                             const std::string& stem, const Model& model);

// The table eigenvalue / time domain / difference and the fit quality.
void print_verification_summary(std::ostream& out, const Model& model,
                                const VerificationResult& r);

}  // namespace railstab
