#pragma once
// Oscillations in a sampled signal y(t_i) (a time-domain run's output
// states): crests and troughs, the peak-to-peak envelope, and whether the
// motion has settled on a limit cycle.
//
// Extrema: a sample above (below) both neighbours is a crest (trough); its
// time and value are refined by the parabola through the three samples,
//   t* = t_i - h (y+ - y-) / (2 (y+ - 2 y_i + y-)),  y* = y_i - (y+ - y-)^2 / (8 (y+ - 2 y_i + y-))
// (equal spacing h; the vertex of the interpolating parabola), which is
// exact to O(h^3) for a smooth signal: at 50 samples per period the crest
// value of a sinusoid is found to ~3e-5 of its amplitude instead of 2e-3.
//
// Peak-to-peak envelope at extremum k: the largest minus the smallest of
// the extrema k-2, k-1, k (crest, trough, crest or the reverse): the motion
// over the last full period.
//
// Settled oscillation (a limit cycle): over the last `periods` full periods
// (crest to crest), every cycle's amplitude A_j = (crest_j - trough_j) / 2
// (the trough after that crest) lies within `amplitude_tolerance` (relative) of their mean, every
// period within `period_tolerance` of theirs, and the mean amplitude is at
// least `min_amplitude_m` (below it the "cycle" is integration noise on a
// steady state).
#include <string>
#include <vector>

namespace railstab {

struct Extremum {
  double time_s = 0.0;
  double value = 0.0;
  bool crest = true;  // false: trough
};

std::vector<Extremum> find_extrema(const std::vector<double>& times_s, const std::vector<double>& values);

// The extremum at the middle of three consecutive samples, if it is one
// (the rule find_extrema applies to every sample): for following a run as
// it goes.
bool extremum_of_three(const double t[3], const double y[3], Extremum& out);

struct EnvelopePoint {
  double time_s = 0.0;           // of the extremum that closes the period
  double peak_to_peak = 0.0;     // signal units (m for a lateral shift)
};
std::vector<EnvelopePoint> peak_to_peak_envelope(const std::vector<Extremum>& extrema);

struct SettledOscillationCriteria {
  int periods = 5;
  double amplitude_tolerance = 0.01;  // relative spread of the cycle amplitudes
  double period_tolerance = 0.01;     // relative spread of the periods
  double min_amplitude_m = 1e-6;
};

struct SettledOscillation {
  bool settled = false;
  std::string reason;  // why not, when not settled
  // Means over the last `periods` cycles (also when not settled, where there
  // are enough cycles to form them; 0 otherwise).
  double amplitude = 0.0;  // half peak-to-peak, signal units
  double period_s = 0.0;
  double amplitude_spread = 0.0;  // (max - min) / mean of the cycle amplitudes
  double period_spread = 0.0;
  int cycles_found = 0;           // full periods (crest to crest) in the signal
};

SettledOscillation settled_oscillation(const std::vector<double>& times_s,
                                       const std::vector<double>& values,
                                       const SettledOscillationCriteria& criteria = {});

}  // namespace railstab
