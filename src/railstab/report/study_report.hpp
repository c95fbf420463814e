#pragma once
// The files of a parameter study (study/study_run.hpp):
//   <stem>_study.csv          one row per combination: index, the varied values,
//                             status, critical speed, hunting frequency and mode,
//                             message (the error of a failed combination)
//   <stem>_study.json         the same with the study's definition
//   <stem>_study_record.toml  every number exactly, for `railstab merge`
//   plots (complete studies only): critical speed against each varied key
//   (one curve per combination of the other keys), and for two keys the
//   stability map (critical speed over both), PNG and SVG, with their
//   gnuplot script and data.
// Nothing in them depends on the number of threads or shards: a merged
// study writes the same bytes as the study run in one go.
#include <railstab/io/output_set.hpp>
#include <railstab/study/study_run.hpp>

#include <ostream>
#include <string>
#include <vector>

namespace railstab {

// `points` in index order: all combinations, or the shard's. Plots only for
// a complete study (`plots` and not shard.sharded()); throws GnuplotError
// when gnuplot fails. Returns the names written, in order.
std::vector<std::string> write_study_results(const StudyDefinition& definition,
                                             const StudyShard& shard,
                                             const std::vector<StudyPoint>& points,
                                             OutputSet& outputs, const std::string& stem, bool plots);

// Every name write_study_results may write for `stem` and `keys` varied keys.
std::vector<std::string> study_file_names(const std::string& stem, std::size_t keys);

// For the terminal: how many combinations found a critical speed, were
// stable or unstable throughout, failed; the lowest and highest critical
// speed with their values.
void print_study_summary(std::ostream& out, const StudyDefinition& definition,
                         const std::vector<StudyPoint>& points);

}  // namespace railstab
