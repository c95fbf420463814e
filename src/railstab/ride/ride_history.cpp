#include <railstab/ride/ride_history.hpp>

#include <railstab/signals/sliding_window.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace railstab {

RideHistory ride_history(const Model& model, double speed_m_per_s, const Trajectory& traj,
                         double prudhomme_factor) {
  RideHistory h;
  h.times_s = traj.times_s;
  for (double t : traj.times_s) h.distance_m.push_back(model.distance_at(t, speed_m_per_s));
  h.prudhomme_factor = prudhomme_factor;
  try {
    h.static_loads = static_wheel_loads(model, speed_m_per_s);
  } catch (const std::exception& e) {
    throw std::runtime_error(std::string("static wheel loads (the vehicle on straight, level track, "
                                         "for Delta Q/Q0 and Prud'homme's limit): ") + e.what());
  }
  h.points = acceleration_points(model);
  h.wheelsets.reserve(traj.times_s.size());
  h.accelerations.reserve(traj.times_s.size());
  for (size_t i = 0; i < traj.times_s.size(); ++i) {
    h.wheelsets.push_back(wheelset_forces(model, speed_m_per_s, traj.times_s[i], traj.states[i],
                                          h.static_loads, prudhomme_factor));
    h.accelerations.push_back(
        point_accelerations(model, speed_m_per_s, traj.times_s[i], traj.states[i], h.points));
  }
  return h;
}

std::vector<WheelsetExtremes> wheelset_extremes(const RideHistory& history) {
  std::vector<WheelsetExtremes> extremes;
  for (const StaticWheelLoad& load : history.static_loads) {
    WheelsetExtremes e;
    e.body = load.body;
    e.prudhomme_limit_N = prudhomme_limit_N(load.axle_load_N(), history.prudhomme_factor);
    extremes.push_back(e);
  }
  auto raise = [](std::optional<double>& m, const std::optional<double>& v) {
    if (v && (!m || *v > *m)) m = v;
  };
  for (size_t i = 0; i < history.times_s.size(); ++i)
    for (size_t w = 0; w < extremes.size(); ++w) {
      const WheelsetForces& f = history.wheelsets[i][w];
      WheelsetExtremes& e = extremes[w];
      if (std::abs(f.sum_y_N) > e.max_abs_sum_y_N) {
        e.max_abs_sum_y_N = std::abs(f.sum_y_N);
        e.max_abs_sum_y_time_s = history.times_s[i];
      }
      raise(e.max_y_over_q_left, f.left.y_over_q);
      raise(e.max_y_over_q_right, f.right.y_over_q);
      e.max_delta_q_over_q0 =
          std::max({e.max_delta_q_over_q0, f.left_delta_q_over_q0, f.right_delta_q_over_q0});
    }
  // 2 m means: only where the samples are dense enough and the distance grows.
  const std::vector<double>& s = history.distance_m;
  bool increasing = s.size() >= 2;
  for (size_t i = 1; i < s.size() && increasing; ++i) increasing = s[i] > s[i - 1];
  if (!increasing || s.back() - s.front() < kSafetyMeanWindow_m ||
      (s.back() - s.front()) / double(s.size() - 1) > kSafetyMeanWindow_m / 2.0)
    return extremes;
  for (size_t w = 0; w < extremes.size(); ++w) {
    std::vector<double> sum_y, left, right;
    bool lifted = false;
    for (size_t i = 0; i < s.size(); ++i) {
      const WheelsetForces& f = history.wheelsets[i][w];
      sum_y.push_back(f.sum_y_N);
      lifted = lifted || !f.left.y_over_q || !f.right.y_over_q;
      left.push_back(f.left.y_over_q.value_or(0.0));
      right.push_back(f.right.y_over_q.value_or(0.0));
    }
    double m = 0.0;
    for (const WindowValue& v : sliding_mean(s, sum_y, kSafetyMeanWindow_m, kSafetyMeanStep_m))
      m = std::max(m, std::abs(v.value));
    extremes[w].max_abs_sum_y_2m_N = m;
    if (lifted) continue;
    double q = -1e300;
    for (const std::vector<double>* side : {&left, &right})
      for (const WindowValue& v : sliding_mean(s, *side, kSafetyMeanWindow_m, kSafetyMeanStep_m))
        q = std::max(q, v.value);
    extremes[w].max_y_over_q_2m = q;
  }
  return extremes;
}

}  // namespace railstab
