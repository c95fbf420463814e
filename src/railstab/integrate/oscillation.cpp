#include <railstab/integrate/oscillation.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace railstab {

bool extremum_of_three(const double t[3], const double y[3], Extremum& e) {
  const double ym = y[0], y0 = y[1], yp = y[2];
  const bool crest = y0 > ym && y0 >= yp;
  const bool trough = y0 < ym && y0 <= yp;
  if (!crest && !trough) return false;
  // The parabola's vertex (spacing taken as the mean of the two intervals:
  // the output times are equally spaced but for a final shortened one).
  const double h = 0.5 * (t[2] - t[0]);
  const double curvature = yp - 2.0 * y0 + ym;
  e.crest = crest;
  e.time_s = t[1];
  e.value = y0;
  if (curvature != 0.0) {
    const double shift = -0.5 * (yp - ym) / curvature;  // in samples, |shift| <= 1/2
    e.time_s = t[1] + shift * h;
    e.value = y0 - (yp - ym) * (yp - ym) / (8.0 * curvature);
  }
  return true;
}

std::vector<Extremum> find_extrema(const std::vector<double>& t, const std::vector<double>& y) {
  std::vector<Extremum> out;
  const size_t n = std::min(t.size(), y.size());
  for (size_t i = 1; i + 1 < n; ++i) {
    Extremum e;
    if (!extremum_of_three(&t[i - 1], &y[i - 1], e)) continue;
    const bool crest = e.crest, trough = !e.crest;
    // A flat stretch (equal samples) gives one extremum, not one per sample.
    if (!out.empty() && out.back().crest == e.crest) {
      if ((crest && e.value > out.back().value) || (trough && e.value < out.back().value)) out.back() = e;
      continue;
    }
    out.push_back(e);
  }
  return out;
}

std::vector<EnvelopePoint> peak_to_peak_envelope(const std::vector<Extremum>& e) {
  std::vector<EnvelopePoint> out;
  for (size_t k = 2; k < e.size(); ++k) {
    const double hi = std::max({e[k - 2].value, e[k - 1].value, e[k].value});
    const double lo = std::min({e[k - 2].value, e[k - 1].value, e[k].value});
    out.push_back({e[k].time_s, hi - lo});
  }
  return out;
}

SettledOscillation settled_oscillation(const std::vector<double>& times_s,
                                       const std::vector<double>& values,
                                       const SettledOscillationCriteria& c) {
  SettledOscillation s;
  const std::vector<Extremum> e = find_extrema(times_s, values);
  // Cycles crest to crest; its amplitude from the crest and the trough that
  // follows it.
  std::vector<double> amplitude, period;
  size_t last_crest = e.size();
  for (size_t k = 0; k < e.size(); ++k) {
    if (!e[k].crest) continue;
    if (last_crest < e.size() && k == last_crest + 2 && !e[last_crest + 1].crest) {
      amplitude.push_back(0.5 * (e[last_crest].value - e[last_crest + 1].value));
      period.push_back(e[k].time_s - e[last_crest].time_s);
    }
    last_crest = k;
  }
  s.cycles_found = int(period.size());
  if (s.cycles_found < c.periods) {
    std::ostringstream msg;
    msg << "no settled oscillation: " << s.cycles_found << " full periods in the run, "
        << c.periods << " needed";
    s.reason = msg.str();
    return s;
  }
  const auto first_a = amplitude.end() - c.periods;
  const auto first_p = period.end() - c.periods;
  const auto [a_lo, a_hi] = std::minmax_element(first_a, amplitude.end());
  const auto [p_lo, p_hi] = std::minmax_element(first_p, period.end());
  double a_sum = 0.0, p_sum = 0.0;
  for (auto it = first_a; it != amplitude.end(); ++it) a_sum += *it;
  for (auto it = first_p; it != period.end(); ++it) p_sum += *it;
  s.amplitude = a_sum / c.periods;
  s.period_s = p_sum / c.periods;
  s.amplitude_spread = s.amplitude > 0.0 ? (*a_hi - *a_lo) / s.amplitude : 0.0;
  s.period_spread = s.period_s > 0.0 ? (*p_hi - *p_lo) / s.period_s : 0.0;
  std::ostringstream msg;
  msg << "no settled oscillation over the last " << c.periods << " periods: ";
  if (!(s.amplitude >= c.min_amplitude_m)) {
    msg << "amplitude " << s.amplitude << " below " << c.min_amplitude_m;
    s.reason = msg.str();
  } else if (!(s.amplitude_spread <= c.amplitude_tolerance)) {
    msg << "amplitude varies by " << s.amplitude_spread << " (relative; at most "
        << c.amplitude_tolerance << ")";
    s.reason = msg.str();
  } else if (!(s.period_spread <= c.period_tolerance)) {
    msg << "period varies by " << s.period_spread << " (relative; at most " << c.period_tolerance
        << ")";
    s.reason = msg.str();
  } else {
    s.settled = true;
  }
  return s;
}

}  // namespace railstab
