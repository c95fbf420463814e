#include <railstab/assessment/running_stability.hpp>

#include <railstab/signals/band_pass.hpp>

#include <unsupported/Eigen/FFT>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace railstab {

std::vector<BogieFrame> bogie_frames(const Model& model) {
  std::vector<BogieFrame> frames;
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    if (model.bodies[b].wheelset()) continue;
    std::vector<int> wheelsets;
    for (const ElementTpl<double>& e : model.elements) {
      const ElementEnds& ends = ends_of(e);
      for (const auto& [mine, other] : {std::pair{ends.body1, ends.body2}, std::pair{ends.body2, ends.body1}})
        if (mine == int(b) && other >= 0 && model.bodies[size_t(other)].wheelset() &&
            std::find(wheelsets.begin(), wheelsets.end(), other) == wheelsets.end())
          wheelsets.push_back(other);
    }
    if (wheelsets.empty()) continue;
    BogieFrame f{int(b), model.bodies[b].mass_kg};
    for (int w : wheelsets) f.mass_kg += model.bodies[size_t(w)].mass_kg;
    frames.push_back(f);
  }
  return frames;
}

double dominant_frequency_Hz(const std::vector<double>& signal, double dt) {
  const size_t first = signal.size() / 2;
  const size_t n = signal.size() - first;
  if (n < 16) throw std::invalid_argument("dominant_frequency_Hz: fewer than 32 samples");
  double mean = 0.0;
  for (size_t i = first; i < signal.size(); ++i) mean += signal[i] / double(n);
  size_t padded = 1;
  while (padded < 8 * n) padded *= 2;
  std::vector<double> x(padded, 0.0);
  for (size_t i = 0; i < n; ++i)
    x[i] = (signal[first + i] - mean) * 0.5 * (1.0 - std::cos(2.0 * std::numbers::pi * double(i) / double(n)));
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> X;
  fft.fwd(X, x);
  const double df = 1.0 / (double(padded) * dt), f_max = std::min(20.0, 0.4 / dt);
  double best = 0.0, best_f = 0.0;
  for (size_t k = 1; k < padded / 2; ++k) {
    const double f = double(k) * df;
    if (f < 0.5 || f > f_max) continue;
    if (std::norm(X[k]) > best) {
      best = std::norm(X[k]);
      best_f = f;
    }
  }
  return best_f;
}

RunningStabilityAssessment assess_running_stability(const Model& model, const RideHistory& h,
                                                    const AssessmentSpec& spec, const std::string& stopped_early) {
  RunningStabilityAssessment a;
  a.stopped_early = stopped_early;
  if (h.times_s.size() < 32 || h.static_loads.empty())
    throw std::invalid_argument("assessment: the run has fewer than 32 outputs or no wheelset");
  a.distance_m = h.distance_m.back() - h.distance_m.front();
  // A run that stopped (at the flange clearance, the table's edge) before
  // one window has failed: nothing is formed, and that is the verdict.
  if (a.distance_m < spec.stability_window_m && !stopped_early.empty()) {
    std::ostringstream msg;
    msg << "the run stopped after " << a.distance_m << " m, before one " << spec.stability_window_m
        << " m window: no rms formed";
    a.failures_without_value.push_back(msg.str());
    a.passed = false;
    return a;
  }
  if (a.distance_m < spec.stability_window_m) {
    std::ostringstream msg;
    msg << "assessment: the run covers " << a.distance_m << " m, less than one window of "
        << "assessment.stability_window_m = " << spec.stability_window_m
        << " m (run longer: --t-end, or a shorter window)";
    throw std::invalid_argument(msg.str());
  }
  const double dt = (h.times_s.back() - h.times_s.front()) / double(h.times_s.size() - 1);
  std::vector<double> leading;
  for (const auto& at : h.wheelsets) leading.push_back(at[0].sum_y_N);
  a.instability_frequency_Hz = dominant_frequency_Hz(leading, dt);
  a.band_low_Hz = std::max(0.1, a.instability_frequency_Hz - spec.stability_band_half_width_Hz);
  a.band_high_Hz = a.instability_frequency_Hz + spec.stability_band_half_width_Hz;
  if (!(a.band_high_Hz < 0.5 / dt)) {
    std::ostringstream msg;
    msg << "assessment: the band up to " << a.band_high_Hz << " Hz reaches the outputs' Nyquist frequency "
        << 0.5 / dt << " Hz (simulation.output_interval_s = " << dt << " s): choose a smaller interval";
    throw std::invalid_argument(msg.str());
  }
  const BandPassFilter filter =
      butterworth_band_pass(dt, a.band_low_Hz, a.band_high_Hz, spec.stability_filter_order);
  // A quantity with its value and limit judged; `windows` the rms over
  // distance (stability quantities) or none (the 2 m safety quantities).
  auto judge = [&](const std::string& quantity, const std::string& subject, const std::string& unit,
                   double value, double limit, std::vector<WindowValue> windows = {}) {
    AssessedQuantity q;
    q.quantity = quantity, q.subject = subject, q.unit = unit;
    q.value = value, q.limit = limit;
    q.passed = value <= limit;
    q.margin = 1.0 - value / limit;
    q.windows = std::move(windows);
    a.quantities.push_back(std::move(q));
  };
  auto rms_quantity = [&](const std::string& quantity, const std::string& subject, const std::string& unit,
                          const std::vector<double>& signal, double limit) {
    std::vector<WindowValue> windows = sliding_rms(h.distance_m, filter_signal(filter, signal),
                                                   spec.stability_window_m, spec.stability_window_step_m);
    double largest = 0.0;
    for (const WindowValue& w : windows) largest = std::max(largest, w.value);
    judge(quantity, subject, unit, largest, limit, std::move(windows));
  };
  const std::vector<WheelsetExtremes> extremes = wheelset_extremes(h);
  for (size_t w = 0; w < h.static_loads.size(); ++w) {
    const std::string& name = model.bodies[size_t(h.static_loads[w].body)].name;
    std::vector<double> sum_y;
    for (const auto& at : h.wheelsets) sum_y.push_back(at[w].sum_y_N);
    // Half Prud'homme's limit: alpha (10 kN + P0/3) / 2.
    rms_quantity("sum_y_rms", name, "N", sum_y,
                 prudhomme_limit_N(h.static_loads[w].axle_load_N(), spec.prudhomme_factor) / 2.0);
    if (extremes[w].max_abs_sum_y_2m_N)
      judge("sum_y_2m", name, "N", *extremes[w].max_abs_sum_y_2m_N, extremes[w].prudhomme_limit_N);
    if (extremes[w].max_y_over_q_2m)
      judge("y_over_q_2m", name, "", *extremes[w].max_y_over_q_2m, spec.y_over_q_limit);
    for (size_t i = 0; i < h.times_s.size(); ++i)
      if (!h.wheelsets[i][w].left.y_over_q || !h.wheelsets[i][w].right.y_over_q) {
        std::ostringstream msg;
        msg << name << ": a wheel lifted off (Q = 0) at t = " << h.times_s[i]
            << " s: Y/Q is unbounded there (y_over_q_2m not formed)";
        a.failures_without_value.push_back(msg.str());
        break;
      }
  }
  for (const BogieFrame& frame : bogie_frames(model)) {
    size_t point = h.points.size();
    for (size_t p = 0; p < h.points.size(); ++p)
      if (h.points[p].body == frame.body && h.points[p].position_B_m.isZero()) point = p;
    if (point == h.points.size()) continue;
    std::vector<double> lateral;
    for (const auto& at : h.accelerations) lateral.push_back(at[point](1));
    // The simplified method: (12 - m_b / 5) / 2 m/s^2, m_b in t.
    rms_quantity("bogie_lateral_acceleration_rms", model.bodies[size_t(frame.body)].name, "m/s2", lateral,
                 (12.0 - frame.mass_kg / 1000.0 / 5.0) / 2.0);
  }
  a.passed = stopped_early.empty() && a.failures_without_value.empty();
  for (const AssessedQuantity& q : a.quantities) a.passed = a.passed && q.passed;
  return a;
}

}  // namespace railstab
