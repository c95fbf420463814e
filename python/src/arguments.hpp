#pragma once
// The Python functions' arguments, checked as the command line checks its
// flags (the same ranges: cli/numeric_flags.hpp), with messages that name
// the Python keyword, e.g.
//   step: expected a finite number in [0.01, 300] m/s, got 1e-12
#include "cli/numeric_flags.hpp"
#include <railstab/setup/prepare_scene.hpp>
#include <railstab/stability/speed_analysis.hpp>

#include <optional>
#include <string>
#include <vector>

namespace railstab::python {

// Throws std::invalid_argument unless `value` lies in `range`.
void check_in(const char* keyword, double value, const FlagRange& range);
void check_in(const char* keyword, const std::optional<double>& value, const FlagRange& range);

// from_ < to and at most kMaxSpeedGridPoints grid speeds (check_speed_grid,
// with the Python keywords in the message).
void check_speed_grid(double from_m_per_s, double to_m_per_s, double step_m_per_s);

// The scene's overrides from the Python side: `set` as "KEY=VALUE" texts
// (the --set form; the Python layer writes each number in its shortest
// exact form), `offset` as "BODY.COORDINATE=VALUE" texts.
SceneOverrides scene_overrides(const std::vector<std::string>& settings,
                               const std::optional<double>& speed_m_per_s,
                               const std::optional<double>& arc_length_m,
                               const std::vector<std::string>& offsets = {});

// The eigen-solver by name (auto, dense, sparse, arpack).
EigenSolverKind solver_named(const std::string& name);

}  // namespace railstab::python
