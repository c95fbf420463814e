#pragma once
// EN 14363's running-stability assessment from a time-domain run
// (docs/assessment.md): per wheelset the rms of the band-passed track shift
// force Sum Y over sliding windows by distance against half Prud'homme's
// limit, per bogie frame the rms of its band-passed lateral acceleration
// against the simplified method's (12 - m_b/5)/2 m/s^2, and the safety
// quantities (Sum Y and Y/Q over 2 m) against Prud'homme and the Y/Q limit.
#include <railstab/ride/ride_history.hpp>
#include <railstab/scene/scene_spec.hpp>
#include <railstab/signals/sliding_window.hpp>

#include <string>
#include <vector>

namespace railstab {

struct AssessedQuantity {
  std::string quantity;  // "sum_y_rms", "bogie_lateral_acceleration_rms", "sum_y_2m", "y_over_q_2m"
  std::string subject;   // wheelset or bogie frame name
  std::string unit;      // "N", "m/s2", ""
  double value = 0.0;    // the largest over the windows
  double limit = 0.0;
  bool passed = false;
  double margin = 0.0;   // 1 - value / limit
  std::vector<WindowValue> windows;  // the rms over distance (stability quantities)
};

struct RunningStabilityAssessment {
  double instability_frequency_Hz = 0.0;  // f0: the peak of the leading wheelset's Sum Y spectrum
  double band_low_Hz = 0.0, band_high_Hz = 0.0;
  double distance_m = 0.0;                // covered by the run
  std::vector<AssessedQuantity> quantities;
  bool passed = false;
  std::string stopped_early;              // the run's, if it did: a fail
  // What could not be judged and why counts as a fail (a wheel that lifted
  // off: its Y/Q is unbounded there, so its 2 m mean is not formed).
  std::vector<std::string> failures_without_value;
};

// The bogie frames of a model: rigid bodies an element connects to a
// wheelset; their mass for the limit is the frame's plus those wheelsets'.
struct BogieFrame {
  int body = 0;
  double mass_kg = 0.0;
};
std::vector<BogieFrame> bogie_frames(const Model& model);

// f0 of a signal sampled at dt: the peak of its Hann-windowed, zero-padded
// periodogram between 0.5 Hz and min(20 Hz, 0.4 / dt), over its second half.
double dominant_frequency_Hz(const std::vector<double>& signal, double dt_s);

// A run that stopped early before one window is a fail with no quantities
// (failures_without_value says why). Throws std::invalid_argument when a
// run that went to its end covers less than one window or
// the band reaches the output's Nyquist frequency.
RunningStabilityAssessment assess_running_stability(const Model& model, const RideHistory& history,
                                                    const AssessmentSpec& spec, const std::string& stopped_early);

}  // namespace railstab
