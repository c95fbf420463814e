#pragma once
// A parameter study: the critical speed of one scene for every combination
// of the values of some scene keys (`--vary KEY=FROM:TO:STEP`), on top of
// fixed `--set` values.
//
// Combinations are numbered like nested loops over the varied keys in the
// order given, the first key outermost:
//   index = sum_k i_k * prod_{j>k} n_j,   i_k in [0, n_k)
// so a study's rows, its shards (index % N == I - 1) and its files do not
// depend on how many threads or machines computed them.
#include <railstab/scene_reading/scene_set_values.hpp>

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace railstab {

// "KEY1,KEY2,...=FROM:TO:STEP" links keys: every key takes the same value in
// a combination (front and rear yaw dampers varied together). `key` is the
// text as given (the study's column and identity), `keys` the scene keys.
struct VariedKey {
  std::string key;
  std::vector<std::string> keys;
  double from = 0.0, to = 0.0, step = 0.0;
  std::vector<double> values;  // from, from + step, ..., to (to 12 significant digits)
};

// Bounds a typo (--vary k=0:1e9:1e-9) before anything is allocated.
inline constexpr std::size_t kMaxStudyCombinations = 1000000;

// "KEY=FROM:TO:STEP" or "KEY1,KEY2=FROM:TO:STEP": FROM <= TO, STEP > 0,
// finite; no empty or repeated key; TO must be FROM plus a whole number of
// steps (to 1e-9 of a step; the last value is then TO exactly). Throws
// std::invalid_argument saying what is wrong.
VariedKey parse_varied_key(std::string_view text);
std::string varied_key_text(const VariedKey& varied);  // "KEY=FROM:TO:STEP", exact numbers
// The scene settings of `varied` at `value`: one per linked key, each naming
// its origin ("--vary K=... (at value)") for error messages.
std::vector<SceneValueSetting> varied_settings(const VariedKey& varied, double value);

// The analysis every combination runs (critical-speed's flags).
struct StudyAnalysis {
  double from_m_per_s = 5.0, to_m_per_s = 150.0, grid_step_m_per_s = 2.5;
  std::string solver = "auto";  // a name of eigen_solver_names()
  double hunting_band_hz = 20.0;
};

struct StudyDefinition {
  std::string scene_path;  // as given
  std::string scene_name;  // [scene] name, for titles and file names
  std::string scene_hash;  // FNV-1a 64 of the file's bytes, hex: mixes of studies are caught
  std::vector<SceneValueSetting> fixed;  // --set
  std::vector<VariedKey> varied;
  StudyAnalysis analysis;

  std::size_t combinations() const;
  // The values of combination `index`, one per varied key.
  std::vector<double> values_of(std::size_t index) const;
  // Everything that decides the results, as one line: two shards belong to
  // the same study exactly when these agree.
  std::string identity() const;
};

// Throws std::invalid_argument (naming --vary / --set) for no varied key, a
// key varied twice (alone or linked) or both varied and set, or too many
// combinations.
void check_study_definition(const StudyDefinition& definition);

// FNV-1a 64-bit of `bytes`, 16 hex digits (not cryptographic: it tells
// accidental mixes apart).
std::string fnv1a64_hex(std::string_view bytes);

// --shard I/N: which combinations a run computes.
struct StudyShard {
  std::size_t index = 1, count = 1;  // 1-based I of N
  bool sharded() const { return count > 1; }
  bool holds(std::size_t combination) const { return combination % count == index - 1; }
};
// "I/N" with 1 <= I <= N; throws std::invalid_argument.
StudyShard parse_study_shard(std::string_view text);

}  // namespace railstab
