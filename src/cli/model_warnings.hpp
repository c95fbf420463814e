#pragma once
// The model check's warnings, printed (stderr) by every command that runs a
// scene before its analysis starts.
#include <railstab/setup/prepare_scene.hpp>
#include <railstab/stability/speed_analysis.hpp>

namespace railstab {

// Runs check_model without the natural frequencies (one linearisation about
// the scene's equilibrium, no extra equilibrium) and prints its warnings to
// stderr. A failing check is reported as a note, never stops the command.
void print_model_warnings_to_stderr(const PreparedScene& scene);

// After a search over speeds: the speed-dependent checks (cant deficiency
// and excess, wheel-load balance, steady shift beyond the flange clearance)
// at every grid speed of `r` with its steady state, and the cant also at the
// top speed asked (`to_m_per_s`) where the grid stopped below it; printed to
// stderr as the start's warnings are (check/model_check.hpp,
// check_speed_range).
void print_speed_range_warnings_to_stderr(const PreparedScene& scene, const CriticalSpeedResult& r,
                                          double to_m_per_s);

}  // namespace railstab
