#include <railstab/stability/steady_state_fold.hpp>

#include <railstab/equilibrium/arclength_continuation.hpp>

#include <algorithm>
#include <optional>
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
  out.folds = coarse.folds;
  if (coarse.reached) {
    out.reached = true;
    out.at_target = coarse.end;
  }
  if (coarse.fold_points.empty()) {
    if (!coarse.reached) out.failure = coarse.failure;
    return out;
  }
  // Again with short steps, up to the first fold, keeping the last few
  // points before it; then once more with steps five times shorter from
  // the third point before the fold. The interpolation's error is O(h^3):
  // the last two estimates' difference bounds the last one's error.
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
  std::vector<Point> recent;
  const ArclengthResult refined = up_to_first_fold(path, state, kRefineMaxStep, &recent);
  const ArclengthResult* used = &coarse;
  const SpeedPath* used_path = &path;
  double previous_estimate = 0.0;
  std::optional<SpeedPath> closer_path;
  ArclengthResult closest;
  if (!refined.fold_points.empty()) {
    used = &refined;
    const ArclengthResult::Fold& c = coarse.fold_points.front();
    previous_estimate = path.speed_at(std::max({c.lambda, c.before_lambda, c.after_lambda}));
    // The third point before the fold (recent holds the points up to the
    // one past it, up to four).
    if (recent.size() >= 4) {
      const Point& p = recent[recent.size() - 4];
      closer_path.emplace(model, path.speed_at(p.lambda), to_m_per_s);
      closest = up_to_first_fold(*closer_path, p.state, kRefineMaxStep / 5.0, nullptr);
      if (!closest.fold_points.empty()) {
        const ArclengthResult::Fold& r = refined.fold_points.front();
        previous_estimate = path.speed_at(std::max({r.lambda, r.before_lambda, r.after_lambda}));
        used = &closest;
        used_path = &*closer_path;
      }
    }
  }
  const ArclengthResult::Fold& f = used->fold_points.front();
  // The coarse run alone: its highest converged point bounds the fold from
  // below, the only error estimate there is.
  if (used == &coarse) previous_estimate = path.speed_at(std::max(f.before_lambda, f.after_lambda));
  SteadyStateFold fold;
  // A converged point lies on the branch, so the turning point is at least
  // as fast as both: at a corner (the Jacobian jumps) the quadratic's vertex
  // can fall just below the point past it.
  fold.speed_m_per_s =
      used_path->speed_at(std::max({f.lambda, f.before_lambda, f.after_lambda}));
  fold.coarse_speed_m_per_s = previous_estimate;
  fold.before_speed_m_per_s = used_path->speed_at(f.before_lambda);
  fold.after_speed_m_per_s = used_path->speed_at(f.after_lambda);
  fold.before_state = f.before_state;
  fold.after_state = f.after_state;
  out.fold = std::move(fold);
  return out;
}

}  // namespace railstab
