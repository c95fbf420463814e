#pragma once
// The ride quantities of a time-domain run at every output time, computed
// once from the trajectory (the CSV writers, the plots and the run summary
// read this; none evaluates the model again): each wheelset's forces on the
// track (wheelset_forces.hpp) and the accelerations of the rigid bodies'
// points (point_acceleration.hpp). docs/ride_quantities.md.
#include <railstab/integrate/integrator.hpp>
#include <railstab/ride/point_acceleration.hpp>
#include <railstab/ride/wheelset_forces.hpp>

#include <optional>
#include <vector>

namespace railstab {

struct RideHistory {
  std::vector<double> times_s;
  std::vector<double> distance_m;  // travelled since t = 0 at each output time
  std::vector<StaticWheelLoad> static_loads;
  double prudhomme_factor = 1.0;
  std::vector<std::vector<WheelsetForces>> wheelsets;        // [time][wheelset]
  std::vector<AccelerationPoint> points;
  std::vector<std::vector<Eigen::Vector3d>> accelerations;  // [time][point], in T
};

RideHistory ride_history(const Model& model, double speed_m_per_s, const Trajectory& traj,
                         double prudhomme_factor);

// EN 14363's means over 2 m of track, stepped by 0.5 m (signals/sliding_window.hpp).
inline constexpr double kSafetyMeanWindow_m = 2.0, kSafetyMeanStep_m = 0.5;

// The extremes of a run (for the run summary): per wheelset the largest
// |Sum Y| and its time, per wheel the largest Y/Q and the largest Delta Q/Q0;
// and the largest 2 m means of |Sum Y| and Y/Q, EN 14363's quantities
// (none when the run covers less than 2 m or a window holds a lifted wheel's
// sample, or when a 2 m window holds fewer than 2 output samples: then the
// output interval is too coarse for the mean and it is not given).
struct WheelsetExtremes {
  int body = 0;
  double max_abs_sum_y_N = 0.0, max_abs_sum_y_time_s = 0.0;
  double prudhomme_limit_N = 0.0;
  std::optional<double> max_y_over_q_left, max_y_over_q_right;
  double max_delta_q_over_q0 = 0.0;  // of either wheel
  std::optional<double> max_abs_sum_y_2m_N;    // max over windows of |mean of Sum Y|
  std::optional<double> max_y_over_q_2m;       // max over windows and both wheels of the mean Y/Q
};
std::vector<WheelsetExtremes> wheelset_extremes(const RideHistory& history);

}  // namespace railstab
