#pragma once
// Sliding windows by distance over a signal sampled along the track
// (EN 14363's processing: the 2 m sliding mean of Sum Y and Y/Q, the 100 m
// sliding rms of the band-passed stability signals; docs/ride_quantities.md, "EN 14363 signal processing").
// Window j covers [s_0 + j step, s_0 + j step + length) and takes the
// samples inside it with equal weight (the samples are equally spaced);
// windows run while they end at or before the last sample.
#include <vector>

namespace railstab {

struct WindowValue {
  double start_m = 0.0, end_m = 0.0;
  double value = 0.0;
  int samples = 0;
};

// Throws std::invalid_argument if s is not increasing, the sizes differ, or
// length or step is not positive.
std::vector<WindowValue> sliding_rms(const std::vector<double>& s_m, const std::vector<double>& x,
                                     double length_m, double step_m);
std::vector<WindowValue> sliding_mean(const std::vector<double>& s_m, const std::vector<double>& x,
                                      double length_m, double step_m);

}  // namespace railstab
