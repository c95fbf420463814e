#pragma once
// Axis titles and tick marks for plots over scene parameters: a `--set` /
// `--vary` key path in words with its unit, and a palette.
#include <string>
#include <vector>

namespace railstab {

// "elements.yaw_damper_front.damping_N_s_per_m" -> "yaw damper front: damping [N s/m]";
// "bodies.carbody.mass_kg" -> "carbody: mass [kg]";
// "elements.primary.stiffness_N_per_m[1]" -> "primary: stiffness, y [N/m]";
// "contacts.textbook_linear.conicity" -> "textbook linear: conicity".
// Linked keys "K1,K2" get both titles joined by " = ".
// The unit is the key's trailing unit words (the scene format's rule:
// units in the name, "per" for a division); a key without one gets none.
std::string parameter_axis_title(const std::string& key);

// A gnuplot tic list "(\"2e6\" 2e6, ...)" with a tick at every value, or at
// every k-th when there are more than `max_ticks` (the first and last kept).
std::string gnuplot_value_tics(const std::vector<double>& values, size_t max_ticks = 12);

// A perceptually uniform palette for gnuplot's `set palette defined`:
// viridis at nine equally spaced stops (the matplotlib colour map's values).
extern const char* const kViridisPalette;

}  // namespace railstab
