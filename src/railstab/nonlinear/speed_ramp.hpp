#pragma once
// The speed-ramp ("ramp-down") method for the speed where hunting dies away:
// one time-domain run that starts hunting above the linear critical speed
// and decelerates at a constant rate a,
//   V(t) = V0 - a t,
// while the peak-to-peak envelope of the leading wheelset's lateral shift
// (integrate/oscillation.hpp: largest minus smallest of the last three
// extrema, the motion over one period) is followed. The hunting end speed
// is V at the time the envelope falls through the threshold for good
// (log-linear interpolation between the last envelope point at or above the
// threshold and the next one below it).
//
// The answer depends on the rate and on the start: the amplitude lags the
// branch of limit cycles it follows (by ~ a / (2 l A^2) in speed, l the
// Landau coefficient), and through a supercritical Hopf point the motion,
// once the steady state is stable, decays only at Re(lambda) ~
// Re(lambda)'(V - Vc), so the threshold is crossed below Vc by
// ~ sqrt(2 a ln(A_c / A_threshold) / Re(lambda)') (docs/speed_ramp.md).
// A report of it therefore gives two rates.
//
// The model equations with a ramp (the track frames' speed and tangential
// acceleration, the creepages over V(t), a frozen spin V(t)/r0) are the
// model's speed law (model/model.hpp speed_rate_m_per_s2); a free wheelset
// spin follows V(t)/r0 through its longitudinal creep forces.
#include <railstab/integrate/integrator.hpp>
#include <railstab/model/model.hpp>

#include <Eigen/Dense>

#include <string>
#include <vector>

namespace railstab {

struct SpeedRampOptions {
  double start_speed_m_per_s = 0.0;   // V0
  double ramp_rate_m_per_s2 = 0.0;    // a >= 0 (a deceleration)
  // a > 0: the run ends where V reaches this speed (0 < end < V0).
  double end_speed_m_per_s = 0.0;
  // a = 0: the run's length (s); unused otherwise.
  double duration_s = 0.0;
  double amplitude_threshold_m = 1e-4;  // peak-to-peak of the leading wheelset's lateral shift
  // Once the envelope has been below the threshold this many hunting
  // periods after hunting was seen, the run stops (0: run to the end).
  double periods_below_to_stop = 3.0;
  // Integrator, tolerances, output interval, progress; t_start_s must be 0
  // (the speed law starts there) and t_end_s is set from the ramp.
  IntegrationOptions integration;
};

struct RampEnvelopePoint {
  double time_s = 0.0;
  double speed_m_per_s = 0.0;
  double peak_to_peak_m = 0.0;
};

struct SpeedRampResult {
  SpeedRampOptions options;
  std::string signal;  // e.g. "wheelset1.y_m"
  Trajectory trajectory;
  std::vector<RampEnvelopePoint> envelope;
  bool hunting_seen = false;  // the envelope reached the threshold at some point
  bool vanished = false;      // and fell below it for good before the run ended
  double hunting_end_speed_m_per_s = 0.0;  // when vanished
  double hunting_end_time_s = 0.0;
  double largest_peak_to_peak_m = 0.0;
  double final_speed_m_per_s = 0.0;  // V at the run's last output
  std::string outcome;               // one sentence
};

// The run from x0 (a state of the constant-speed model at V0, e.g. a start
// on the hunting mode). Throws std::invalid_argument naming the option for a
// bad rate, end speed or duration, and when the model has no wheelset with a
// free lateral shift.
SpeedRampResult run_speed_ramp(const Model& model, const Eigen::VectorXd& x0,
                               const SpeedRampOptions& options);

}  // namespace railstab
