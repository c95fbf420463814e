#include <railstab/stability/steady_state_fold.hpp>

#include <railstab/equilibrium/arclength_continuation.hpp>

#include <algorithm>
#include <vector>

namespace railstab {

LostSteadyState continue_past_lost_steady_state(const Model& model, const Eigen::VectorXd& state,
                                                double from_m_per_s, double to_m_per_s,
                                                double time_s) {
  LostSteadyState out;
  SpeedPath path(model, from_m_per_s, to_m_per_s);
  ArclengthOptions options;
  options.time_s = time_s;
  const ArclengthResult coarse = continue_by_arclength(path, state, options);
  if (coarse.reached) {
    out.reached = true;
    out.at_target = coarse.end;
  }
  if (coarse.fold_points.empty()) {
    if (!coarse.reached) out.failure = coarse.failure;
    return out;
  }
  // Again with short steps up to the first fold, keeping the last points
  // before it; then once more with steps five times shorter from the third
  // point before the fold. The interpolation's error is O(h^3): the last
  // two estimates' difference bounds the last one's error.
  struct Point {
    double lambda;
    Eigen::VectorXd state;
  };
  auto up_to_first_fold = [&](SpeedPath& on, const Eigen::VectorXd& from_state, double max_step,
                              std::vector<Point>* recent) {
    ArclengthOptions fine = options;
    fine.max_step = max_step;
    fine.initial_step = max_step;
    fine.max_steps = 4000;
    double highest = -1.0;
    fine.stop = [&](double lambda, const Eigen::VectorXd& x) -> std::string {
      if (lambda < highest) return "past the fold";
      highest = lambda;
      if (recent) {
        recent->push_back({lambda, x});
        if (recent->size() > 4) recent->erase(recent->begin());
      }
      return "";
    };
    return continue_by_arclength(on, from_state, fine);
  };
  const ArclengthResult::Fold& c = coarse.fold_points.front();
  SteadyStateFold fold;
  // The default steps alone: the highest converged point bounds the fold
  // from below, the only error estimate there is.
  auto take = [&](const SpeedPath& on, const ArclengthResult::Fold& f, double previous_m_per_s) {
    fold.speed_m_per_s = on.speed_at(f.lambda);
    fold.coarse_speed_m_per_s = previous_m_per_s;
    fold.before_speed_m_per_s = on.speed_at(f.before_lambda);
    fold.after_speed_m_per_s = on.speed_at(f.after_lambda);
    fold.before_state = f.before_state;
    fold.after_state = f.after_state;
  };
  take(path, c, path.speed_at(std::max(c.before_lambda, c.after_lambda)));
  std::vector<Point> recent;
  const ArclengthResult refined = up_to_first_fold(path, state, kRefineMaxStep, &recent);
  if (!refined.fold_points.empty()) {
    const ArclengthResult::Fold& r = refined.fold_points.front();
    take(path, r, path.speed_at(c.lambda));
    if (recent.size() >= 4) {  // the third point before the fold
      const Point& p = recent[recent.size() - 4];
      SpeedPath closer(model, path.speed_at(p.lambda), to_m_per_s);
      const ArclengthResult closest = up_to_first_fold(closer, p.state, kRefineMaxStep / 5.0, nullptr);
      if (!closest.fold_points.empty())
        take(closer, closest.fold_points.front(), path.speed_at(r.lambda));
    }
  }
  out.fold = std::move(fold);
  return out;
}

}  // namespace railstab
