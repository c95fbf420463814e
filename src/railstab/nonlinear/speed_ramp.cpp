#include <railstab/nonlinear/speed_ramp.hpp>

#include <railstab/integrate/oscillation.hpp>
#include <railstab/model/leading_wheelset.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace railstab {

namespace {

std::string number_text(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

void check_options(const SpeedRampOptions& o) {
  if (!(std::isfinite(o.start_speed_m_per_s) && o.start_speed_m_per_s > 0.0))
    throw std::invalid_argument("speed ramp: start speed: expected a positive speed (m/s), got " +
                                number_text(o.start_speed_m_per_s));
  if (!(std::isfinite(o.ramp_rate_m_per_s2) && o.ramp_rate_m_per_s2 >= 0.0))
    throw std::invalid_argument(
        "speed ramp: ramp rate: expected a deceleration >= 0 m/s^2, got " +
        number_text(o.ramp_rate_m_per_s2));
  if (o.ramp_rate_m_per_s2 > 0.0 &&
      !(o.end_speed_m_per_s > 0.0 && o.end_speed_m_per_s < o.start_speed_m_per_s))
    throw std::invalid_argument("speed ramp: end speed: expected a speed in (0, " +
                                number_text(o.start_speed_m_per_s) + ") m/s, got " +
                                number_text(o.end_speed_m_per_s));
  if (o.ramp_rate_m_per_s2 == 0.0 && !(std::isfinite(o.duration_s) && o.duration_s > 0.0))
    throw std::invalid_argument("speed ramp: duration: expected a positive time (s) at rate 0, got " +
                                number_text(o.duration_s));
  if (!(std::isfinite(o.amplitude_threshold_m) && o.amplitude_threshold_m > 0.0))
    throw std::invalid_argument("speed ramp: amplitude threshold: expected a positive length (m), got " +
                                number_text(o.amplitude_threshold_m));
  if (o.integration.t_start_s != 0.0)
    throw std::invalid_argument("speed ramp: the run starts at t = 0 (the speed law's origin)");
}

// Follows the leading wheelset's lateral shift output by output: extrema,
// the envelope, and whether the hunting has died away.
class EnvelopeTracker {
 public:
  EnvelopeTracker(int state, const SpeedRampOptions& o) : state_(state), o_(o) {}

  // Returns a stop reason once the envelope has stayed below the threshold
  // for periods_below_to_stop periods after hunting was seen.
  std::string add(double t, const Eigen::VectorXd& x) {
    t3_[0] = t3_[1], t3_[1] = t3_[2], t3_[2] = t;
    y3_[0] = y3_[1], y3_[1] = y3_[2], y3_[2] = x(state_);
    if (++samples_ >= 3) {
      Extremum e;
      if (extremum_of_three(t3_, y3_, e)) add_extremum(e);
    }
    if (!seen_ || o_.periods_below_to_stop <= 0.0 || period_s_ <= 0.0) return {};
    if (envelope_.back().peak_to_peak_m >= o_.amplitude_threshold_m) return {};
    if (t - last_above_s_ < o_.periods_below_to_stop * period_s_) return {};
    std::ostringstream msg;
    msg << "hunting below the threshold " << o_.amplitude_threshold_m << " m peak-to-peak for "
        << o_.periods_below_to_stop << " periods at t = " << t << " s";
    return msg.str();
  }

  const std::vector<RampEnvelopePoint>& envelope() const { return envelope_; }

 private:
  void add_extremum(const Extremum& e) {
    // A flat stretch gives one extremum of a kind (as find_extrema).
    if (!extrema_.empty() && extrema_.back().crest == e.crest) {
      if ((e.crest && e.value > extrema_.back().value) || (!e.crest && e.value < extrema_.back().value))
        extrema_.back() = e;
      return;
    }
    extrema_.push_back(e);
    const size_t k = extrema_.size();
    if (k < 3) return;
    const std::vector<Extremum> last(extrema_.end() - 3, extrema_.end());
    const EnvelopePoint p = peak_to_peak_envelope(last).front();
    period_s_ = 2.0 * (extrema_[k - 1].time_s - extrema_[k - 2].time_s);
    const double V = o_.start_speed_m_per_s - o_.ramp_rate_m_per_s2 * p.time_s;
    envelope_.push_back({p.time_s, V, p.peak_to_peak});
    if (p.peak_to_peak >= o_.amplitude_threshold_m) {
      seen_ = true;
      last_above_s_ = p.time_s;
    }
  }

  int state_;
  const SpeedRampOptions& o_;
  double t3_[3] = {0, 0, 0}, y3_[3] = {0, 0, 0};
  long samples_ = 0;
  std::vector<Extremum> extrema_;
  std::vector<RampEnvelopePoint> envelope_;
  bool seen_ = false;
  double last_above_s_ = 0.0, period_s_ = 0.0;
};

}  // namespace

SpeedRampResult run_speed_ramp(const Model& model, const Eigen::VectorXd& x0,
                               const SpeedRampOptions& options) {
  check_options(options);
  const int signal = leading_wheelset_lateral_state(model);
  if (signal < 0)
    throw std::invalid_argument("speed ramp: the model has no wheelset with a free lateral shift to follow");
  Model ramp_model = model;  // the same model with the speed law V0 - a t
  ramp_model.speed_rate_m_per_s2 = -options.ramp_rate_m_per_s2;
  const double a = options.ramp_rate_m_per_s2, V0 = options.start_speed_m_per_s;

  IntegrationOptions io = options.integration;
  io.t_end_s = a > 0.0 ? (V0 - options.end_speed_m_per_s) / a : options.duration_s;
  // The hunting of one stretch of track: the run ends where the first body
  // leaves the uniform stretch (tangent, or arc at constant cant) it starts
  // on, after s = V0 t - a t^2 / 2 = D.
  double track_limit_s = std::numeric_limits<double>::infinity();
  std::string first_out;
  for (int b = 0; b < int(model.bodies.size()); ++b) {
    const double s0 = model.arc_length_of(b, 0.0, V0);
    const double D = model.track.uniform_stretch_end_m(s0) - s0;
    const double t_b = a > 0.0 ? (V0 * V0 > 2.0 * a * D ? (V0 - std::sqrt(V0 * V0 - 2.0 * a * D)) / a
                                                        : std::numeric_limits<double>::infinity())
                               : D / V0;
    if (t_b < track_limit_s) track_limit_s = t_b, first_out = model.bodies[size_t(b)].name;
  }
  const bool track_limited = track_limit_s < io.t_end_s;
  if (track_limited) io.t_end_s = track_limit_s;
  EnvelopeTracker tracker(signal, options);
  tracker.add(0.0, x0);
  io.stop_at_output = [&](double t, const Eigen::VectorXd& x) { return tracker.add(t, x); };

  SpeedRampResult r;
  r.options = options;
  r.signal = model.state_name(signal);
  r.trajectory = integrate(ramp_model, V0, x0, io);
  r.envelope = tracker.envelope();
  r.final_speed_m_per_s = V0 - a * r.trajectory.times_s.back();

  // The last envelope point at or above the threshold, and the one after it.
  int last_above = -1;
  for (size_t k = 0; k < r.envelope.size(); ++k) {
    r.largest_peak_to_peak_m = std::max(r.largest_peak_to_peak_m, r.envelope[k].peak_to_peak_m);
    if (r.envelope[k].peak_to_peak_m >= options.amplitude_threshold_m) last_above = int(k);
  }
  r.hunting_seen = last_above >= 0;
  const double threshold = options.amplitude_threshold_m;
  std::ostringstream outcome;
  if (!r.hunting_seen) {
    outcome << "no hunting to follow: the leading wheelset's peak-to-peak motion never reached "
            << threshold << " m (largest " << r.largest_peak_to_peak_m << " m)";
  } else if (size_t(last_above) + 1 < r.envelope.size()) {
    const RampEnvelopePoint& p = r.envelope[size_t(last_above)];
    const RampEnvelopePoint& q = r.envelope[size_t(last_above) + 1];
    // log(pp) linear in time between them.
    const double f = q.peak_to_peak_m > 0.0
                         ? std::log(p.peak_to_peak_m / threshold) /
                               std::log(p.peak_to_peak_m / q.peak_to_peak_m)
                         : 0.0;
    r.vanished = true;
    r.hunting_end_time_s = p.time_s + std::clamp(f, 0.0, 1.0) * (q.time_s - p.time_s);
    r.hunting_end_speed_m_per_s = V0 - a * r.hunting_end_time_s;
    outcome << "hunting fell below " << threshold << " m peak-to-peak at "
            << r.hunting_end_speed_m_per_s << " m/s (t = " << r.hunting_end_time_s << " s)";
  } else {
    outcome << "still hunting at the end of the run, " << r.final_speed_m_per_s << " m/s";
    if (track_limited && r.trajectory.stopped_early.empty())
      outcome << ", where " << first_out
              << " leaves the uniform stretch of track it started on (start further back "
                 "with a longer tangent, e.g. --set track.segments[0].length_m=...)";
  }
  if (!r.trajectory.stopped_early.empty() && !r.vanished)
    outcome << "; the run stopped early: " << r.trajectory.stopped_early;
  r.outcome = outcome.str();
  return r;
}

}  // namespace railstab
