#pragma once
// File names derived from user text (scene names, body names) so that an
// output can never leave the output folder or fail late on a long name.
//
// The rule (documented in README "Outputs"): every byte outside
// [A-Za-z0-9._-] becomes '_', a leading '.' becomes '_' (no hidden files,
// no "." or ".." component), the result is cut to kMaxFileStemLength bytes,
// and an empty result becomes "unnamed". The stem therefore never holds a
// '/', a control character or a ".." component, so "<out>/<stem>_<suffix>"
// is always a file directly inside <out>.
#include <cstddef>
#include <string>
#include <string_view>

namespace railstab {

// Long enough for any real scene name, short enough that stem + the longest
// suffix ("_stability_plots.gp", "_verify_150mps_fit.png") stays far below
// the 255-byte NAME_MAX of common file systems.
inline constexpr std::size_t kMaxFileStemLength = 80;

std::string file_stem(std::string_view name);

// The stem every command's outputs start with: the scene file's name without
// its folder and its last extension ("cases/coach_k6.toml" -> "coach_k6"),
// made safe by file_stem. The file, not the scene's `name`: two copies of a
// scene that differ in one value keep their own outputs in one folder.
std::string scene_file_stem(std::string_view scene_path);

// "<V>mps" with V the speed rounded to 0.01 m/s, trailing zeros dropped
// ("30mps", "36.9mps", "12.35mps"), for names like <stem>_eigen_36.9mps.json; throws std::invalid_argument for a
// non-finite speed or one beyond 1e6 m/s.
std::string speed_file_tag(double speed_m_per_s);

// True when `file_name` is a single path component that file_stem-derived
// names may take: non-empty, at most 255 bytes, only [A-Za-z0-9._-], not
// starting with '.'. Used to refuse anything else before it reaches the disk.
bool is_safe_file_name(std::string_view file_name);

}  // namespace railstab
