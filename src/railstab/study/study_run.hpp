#pragma once
// Running a parameter study: one critical-speed search per combination,
// spread over a pool of threads. Every combination is computed from the
// scene file alone (its own model, equilibrium and search), and its result
// is stored at its index, so the results do not depend on --jobs or on the
// order the threads finish. A combination that fails (no steady state, a
// value the scene check refuses) is a row with its error, not the end of
// the study.
#include <railstab/study/study_definition.hpp>

#include <functional>
#include <string>
#include <vector>

namespace railstab {

struct StudyPoint {
  std::size_t index = 0;
  std::vector<double> values;  // one per varied key
  // The verdict of the search (stability/verdict.hpp verdict_key:
  // critical_speed_found, stable_in_range, unstable_at_start,
  // stable_below_equilibrium_loss), or "error".
  std::string status;
  bool critical_speed_found = false;
  double critical_speed_m_per_s = 0.0;  // when found
  double frequency_hz = 0.0;            // of the hunting mode at the critical speed
  std::string mode;                     // its name
  std::string message;                  // the error, or why a search is partial
};

struct StudyRunOptions {
  unsigned jobs = 1;  // threads
  StudyShard shard;   // which combinations
  // Called (serialised) after each combination with a line for stderr.
  std::function<void(const std::string&)> progress;
};

// The points of `definition` that `options.shard` holds, in index order.
std::vector<StudyPoint> run_study(const StudyDefinition& definition, const StudyRunOptions& options);

// Fills in what a study takes from its scene file, from `definition`'s
// scene_path, fixed values and varied keys (check_study_definition first):
// the scene's name and the hash of its bytes, after checking every key at
// once: the scene with the fixed values is read and built as a run would
// (profile contact tables included), and each varied key is applied at both
// ends of its range, so that a bad key or profile file stops the study here,
// not in every row. Throws SceneError naming the file and key. The command
// line and the Python module both start a study through this.
void complete_study_definition(StudyDefinition& definition);

// One combination (what each thread runs).
StudyPoint run_study_point(const StudyDefinition& definition, std::size_t index);

}  // namespace railstab
