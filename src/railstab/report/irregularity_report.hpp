#pragma once
// `railstab track`'s outputs (docs/outputs.md, "track"): the irregularity
// channels, their Welch PSDs against the target, a JSON summary and plots.
#include <railstab/io/output_set.hpp>
#include <railstab/irregularity/irregularity_check.hpp>
#include <railstab/irregularity/track_irregularities.hpp>

#include <string>

namespace railstab {

// Writes <stem>_irregularities.csv, <stem>_irregularity_psd.csv,
// <stem>_irregularities.json and, with plots, <stem>_irregularity_plots.gp
// with its two PNGs into `outputs`. Returns the text for the terminal.
std::string write_irregularity_report(const TrackIrregularities& irregularities,
                                      const IrregularityCheck& check, const std::string& scene_name,
                                      OutputSet& outputs, const std::string& stem, bool plots);

}  // namespace railstab
