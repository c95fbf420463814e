#include <railstab/stability/speed_analysis.hpp>

#include <railstab/model/wheel_forces.hpp>
#include <railstab/eigen/band_eigen.hpp>
#include <railstab/equilibrium/speed_continuation.hpp>
#include <railstab/linear/jacobian.hpp>
#include <railstab/model/equations_of_motion.hpp>
#include <railstab/setup/model_error_context.hpp>

#include <railstab/stability/mode_names.hpp>
#include <railstab/stability/point_mode_shapes.hpp>
#include <railstab/stability/steady_state_fold.hpp>

#include <algorithm>
#include <map>
#include <chrono>
#include <cmath>
#include <numbers>
#include <optional>
#include <sstream>
#include <stdexcept>

namespace railstab {

namespace {
constexpr std::pair<EigenSolverKind, const char*> kEigenSolverNames[] = {
    {EigenSolverKind::automatic, "auto"},
    {EigenSolverKind::dense, "dense"},
    {EigenSolverKind::sparse, "sparse"},
    {EigenSolverKind::arpack, "arpack"},
};
}  // namespace

std::string eigen_solver_name(EigenSolverKind kind) {
  for (const auto& [k, name] : kEigenSolverNames)
    if (k == kind) return name;
  return "unknown";
}

std::vector<std::string> eigen_solver_names() {
  std::vector<std::string> names;
  for (const auto& entry : kEigenSolverNames) names.push_back(entry.second);
  return names;
}

EigenSolverKind eigen_solver_from_name(const std::string& name) {
  for (const auto& [k, n] : kEigenSolverNames)
    if (name == n) return k;
  std::string expected;
  for (const std::string& n : eigen_solver_names()) expected += (expected.empty() ? "" : ", ") + n;
  throw std::invalid_argument("eigen-solver '" + name + "': expected one of " + expected);
}

EigenSolverKind resolved_solver(EigenSolverKind kind, int n_states) {
  if (kind != EigenSolverKind::automatic) return kind;
  return n_states >= kSparseFromStates ? EigenSolverKind::sparse : EigenSolverKind::dense;
}

static BandCoverOptions band_cover_options(const StabilityOptions& options) {
  BandCoverOptions b;
  b.min_real_part_per_s = options.sparse_min_real_part_per_s;
  b.max_real_part_per_s = options.sparse_max_real_part_per_s;
  b.max_frequency_hz = options.max_frequency_hz;
  b.eigenvalues_per_shift = options.sparse_eigenvalues_per_shift;
  return b;
}

std::vector<EigenPair> solve_eigen(const Eigen::MatrixXd& A, const StabilityOptions& options) {
  const EigenSolverKind kind = resolved_solver(options.solver, int(A.rows()));
  if (kind == EigenSolverKind::dense) return eigen_dense(A);
  if (kind == EigenSolverKind::sparse)
    return eigen_sparse_band(A.sparseView(), band_cover_options(options)).pairs;
  ArpackOptions a;
  a.shift = options.arpack_shift;
  a.n_eigenvalues = std::min(options.arpack_eigenvalues, int(A.rows()) - 3);
  return eigen_arpack_shift_invert(A, a);
}

SpeedStability::SpeedStability(const Model& model, const Eigen::VectorXd& equilibrium_guess,
                               double guess_speed_m_per_s, StabilityOptions options)
    : model_(model), options_(options), last_equilibrium_(equilibrium_guess),
      last_speed_(guess_speed_m_per_s), jacobian_plan_(plan_rhs_jacobian(model)),
      equilibrium_plan_(equilibrium_jacobian_plan(model)) {}

// Natural continuation in speed from the last steady state
// (equilibrium/speed_continuation.hpp: halved steps where Newton misses, so
// it follows the branch the sweep is on); only where that fails,
// pseudo-transient continuation at the target speed (which converges to
// whatever steady state the motion leads to, possibly another branch).
EquilibriumResult SpeedStability::steady_state_at(double speed_m_per_s) {
  EquilibriumOptions newton;
  newton.time_s = options_.time_s;
  newton.jacobian_plan = &equilibrium_plan_;
  if (last_speed_ > 0.0) {
    try {
      return continue_equilibrium_in_speed(model_, last_speed_, last_equilibrium_, speed_m_per_s,
                                           newton);
    } catch (const EquilibriumError&) {
    }
  }
  EquilibriumOptions settle = newton;
  settle.pseudo_transient_fallback = true;
  return solve_equilibrium(model_, speed_m_per_s,
                           rescaled_to_speed(model_, last_equilibrium_, last_speed_, speed_m_per_s), settle);
}

StabilityPoint SpeedStability::at(double speed_m_per_s) { return covering(speed_m_per_s, nullptr); }

StabilityPoint SpeedStability::at_steady_state(double speed_m_per_s, const Eigen::VectorXd& state) {
  return covering(speed_m_per_s, &state);
}

void SpeedStability::restart_from(const Eigen::VectorXd& state, double speed_m_per_s) {
  last_equilibrium_ = state;
  last_speed_ = speed_m_per_s;
}

StabilityPoint SpeedStability::covering(double speed_m_per_s, const Eigen::VectorXd* given_state) {
  const bool sparse =
      resolved_solver(options_.solver, model_.state_size()) == EigenSolverKind::sparse;
  return evaluate(speed_m_per_s, sparse, [&](StabilityPoint& p) {
    if (!sparse) return describe_modes(model_, p.linear, solve_eigen(p.linear.A, options_), p.speed_m_per_s);
    const BandEigenResult band =
        eigen_sparse_band(p.linear.A_sparse, band_cover_options(options_), last_band_discs_);
    last_band_discs_ = band.discs;
    p.band_discs = band.discs;
    p.eigen_shifts = int(band.discs.size());
    if (!band.covered) {
      std::ostringstream w;
      w << "sparse eigen-analysis: " << band.discs.size()
        << " shifts did not cover the hunting band's box (Re in ["
        << options_.sparse_min_real_part_per_s << ", " << options_.sparse_max_real_part_per_s
        << "] 1/s, 0 to " << options_.max_frequency_hz
        << " Hz): a mode there may be missing (use --solver dense)";
      p.eigen_warning = w.str();
    }
    return describe_modes(model_, p.linear, band.pairs, p.speed_m_per_s);
  }, given_state);
}

void SpeedStability::plan_band_solve_from(const StabilityPoint& near) {
  if (!near.band_discs.empty()) last_band_discs_ = near.band_discs;
}

StabilityPoint SpeedStability::tracking(double speed_m_per_s, std::complex<double> shift,
                                        int modes) {
  return evaluate(speed_m_per_s, true, [&](StabilityPoint& p) {
    const int k = std::min(modes, int(p.linear.A_sparse.rows()) - 2);
    NearestEigenpairs near = eigen_sparse_nearest(p.linear.A_sparse, shift, k);
    p.tracked = true;
    p.tracked_shift = near.disc.shift;
    p.tracked_radius_per_s = near.disc.radius;
    p.eigen_shifts = 1;
    if (!(near.disc.radius > 0.0))
      p.eigen_warning = "tracked eigen-analysis: the Krylov-Schur solve did not converge the modes nearest the "
                        "tracked one";
    return describe_modes(model_, p.linear, near.pairs, p.speed_m_per_s);
  });
}

template <class Eigen_>
StabilityPoint SpeedStability::evaluate(double speed_m_per_s, bool sparse,
                                        Eigen_&& eigen_analysis, const Eigen::VectorXd* given_state) {
  const auto start = std::chrono::steady_clock::now();
  const Model& model = model_;
  StabilityPoint p;
  p.speed_m_per_s = speed_m_per_s;
  p.time_s = options_.time_s;
  // Each stage names itself, the speed and the place in its errors
  // (setup/model_error_context.hpp).
  const double t = options_.time_s;
  if (given_state) {
    p.equilibrium.state = *given_state;
    const Eigen::VectorXd f = rhs(model, speed_m_per_s, t, *given_state);
    for (int k = model.n_coordinates; k < model.state_size(); ++k)
      if (std::abs(f(k)) > p.equilibrium.max_acceleration) {
        p.equilibrium.max_acceleration = std::abs(f(k));
        p.equilibrium.worst_state = model.state_name(k);
      }
  } else {
    p.equilibrium = with_model_context(model, {"steady state", speed_m_per_s, t},
                                       [&] { return steady_state_at(speed_m_per_s); });
  }
  last_equilibrium_ = p.equilibrium.state;
  last_speed_ = speed_m_per_s;
  LinearizationOptions lin_opt;
  lin_opt.time_s = options_.time_s;
  lin_opt.jacobian_plan = &jacobian_plan_;
  // The model's state count decides the solver (before the Jacobian, which
  // is stored dense or sparse accordingly; the cyclic coordinates it removes
  // are a handful).
  p.solver_used = sparse ? EigenSolverKind::sparse : resolved_solver(options_.solver, model.state_size());
  lin_opt.sparse = sparse;
  p.linear = with_model_context(
      model, {"linearisation", speed_m_per_s, t, &p.equilibrium.state},
      [&] { return linearize(model, speed_m_per_s, p.equilibrium.state, lin_opt); });
  EvaluationPlace eigen_place{"eigen-analysis", speed_m_per_s, t, &p.equilibrium.state};
  if (!lin_opt.sparse) eigen_place.matrix = &p.linear.A;
  eigen_place.matrix_state_names = &p.linear.state_names;
  p.modes = with_model_context(model, eigen_place, [&] { return eigen_analysis(p); });
  p.least_stable = least_stable_mode(p.modes, options_.max_frequency_hz);
  p.least_damped = least_damped_mode(p.modes, options_.max_frequency_hz);
  for (int i = 0; i < int(p.modes.size()); ++i)
    if (!p.modes[i].neutral && p.modes[i].frequency_hz > options_.max_frequency_hz &&
        p.modes[i].eigenvalue.real() > 0.0 && p.modes[i].eigenvalue.imag() >= 0.0)
      p.unstable_above_band.push_back(i);
  p.max_real_part = p.least_stable >= 0 ? p.modes[p.least_stable].eigenvalue.real() : -INFINITY;
  bool has_profiles = false;
  for (const Body& b : model.bodies) {
    const int k = b.state_index[int(CoordinateIndex::y)];
    if (!b.wheelset() || k < 0) continue;
    const ContactSpec& contact = model.contacts[b.wheelset()->contact].spec;
    if (uses_contact_table(contact.geometry)) {  // has its flange
      has_profiles = true;
      continue;
    }
    const double clearance = contact.flange_clearance_m;
    if (std::abs(p.equilibrium.state(k)) > clearance && p.validity_warning.empty()) {
      std::ostringstream w;
      w << b.name << " steady lateral shift " << p.equilibrium.state(k) * 1e3
        << " mm exceeds the flange clearance " << clearance * 1e3
        << " mm: flange contact, outside the model's validity";
      p.validity_warning = w.str();
    }
  }
  // Real profiles guide the wheelset by its flange: the limit is flange
  // climbing, Y/Q against Nadal's limit (model/wheel_forces.hpp).
  if (has_profiles && p.validity_warning.empty())
    if (const auto w = wheel_beyond_nadal_limit(
            wheel_forces(model, speed_m_per_s, t, p.equilibrium.state)))
      p.validity_warning = nadal_warning(model, *w);
  p.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return p;
}

namespace {

// What a speed sweep keeps of a point: the eigenvalues, eigenvectors (mode
// tracking, mode shapes) and the linear model's state bookkeeping, not the
// state matrix (dense: states^2 doubles, 14 MB per point for a 16-car train;
// nothing reads it once the modes are known).
void release_state_matrix(StabilityPoint& p) {
  p.linear.A = Eigen::MatrixXd();
  p.linear.A_sparse = Eigen::SparseMatrix<double>();
}

// Smallest damping ratio in the hunting band minus the limit: negative below it.
double damping_margin(const StabilityPoint& p, double limit) {
  return p.least_damped >= 0 ? p.modes[size_t(p.least_damped)].damping_ratio - limit : INFINITY;
}

// Bisection of [lo, hi] on the sign of margin(p) (negative at hi) down to
// the speed tolerance, each point reported. A midpoint without a steady state
// ends it with the bracket found so far (the change of sign lies between two
// speeds that both have one, only less tightly bracketed), marked partial in
// r. Returns the final bracket and the speed where the margin, interpolated
// linearly inside it, vanishes (hi if the margins do not allow it).
struct SpeedBracket {
  StabilityPoint lo, hi;
  double zero_m_per_s = 0.0;
};
//
// Tracking (track, sparse solver, a crossing mode known at hi): a midpoint is
// a tracked point (SpeedStability::tracking), the options.tracked_modes
// eigenpairs nearest the least stable eigenvalue of the bracket's unstable
// end, and its margin is that of the modes found. That proves the sign only
// for the modes in its disc, so the final bracket's tracked ends are
// evaluated again with the full covering solve: where the full margin agrees
// the bracket is proven as by a bisection without tracking; where not (a
// mode outside the tracked disc decided), the bisection goes on without
// tracking inside the part of the bracket the full solves left.
template <class Margin, class Report>
SpeedBracket bisect_speed(const Model& model, const CriticalSpeedOptions& options,
                          StabilityPoint lo, StabilityPoint hi, const char* what, Margin&& margin,
                          CriticalSpeedResult& r, Report& report, bool track = false) {
  track = track && options.tracked_modes > 0 && hi.solver_used == EigenSolverKind::sparse &&
          hi.least_stable >= 0;
  const StabilityPoint grid_lo = lo, grid_hi = track ? hi : StabilityPoint{};
  SpeedStability refine(model, lo.equilibrium.state, lo.speed_m_per_s, options.stability);
  // The midpoints' band solves start from the stable end's discs (the
  // unstable end's where that one is a tracked point without discs).
  refine.plan_band_solve_from(hi);
  refine.plan_band_solve_from(lo);
  while (hi.speed_m_per_s - lo.speed_m_per_s > options.tolerance_m_per_s) {
    const double mid = 0.5 * (lo.speed_m_per_s + hi.speed_m_per_s);
    StabilityPoint p;
    try {
      bool done = false;
      if (track) {
        try {
          p = refine.tracking(mid, hi.modes[size_t(hi.least_stable)].eigenvalue,
                              options.tracked_modes);
          done = p.tracked_radius_per_s > 0.0 && p.least_stable >= 0;
        } catch (const std::runtime_error&) {
        }
      }
      if (!done) p = refine.at(mid);  // also where tracking found nothing to follow
      release_state_matrix(p);
    } catch (const std::runtime_error& e) {
      std::ostringstream why;
      why << "the " << what << " bisection stopped at " << mid
          << " m/s (no steady state there) with the change bracketed in [" << lo.speed_m_per_s
          << ", " << hi.speed_m_per_s << "] m/s instead of " << options.tolerance_m_per_s
          << " m/s: " << e.what();
      r.partial = true;
      r.partial_reason += (r.partial_reason.empty() ? "" : "; ") + why.str();
      if (options.progress) options.progress("  bisection stopped: " + why.str());
      break;
    }
    report(p);
    (margin(p) < 0.0 ? hi : lo) = std::move(p);
  }
  if (track) {
    // The full covering solve at each tracked end of the final bracket.
    auto covering = [&](const StabilityPoint& q, const StabilityPoint& grid_end) {
      SpeedStability at_q(model, q.equilibrium.state, q.speed_m_per_s, options.stability);
      at_q.plan_band_solve_from(grid_end);
      StabilityPoint f = at_q.at(q.speed_m_per_s);
      release_state_matrix(f);
      report(f);
      return f;
    };
    if (lo.tracked) {
      lo = covering(lo, grid_lo);
      if (margin(lo) < 0.0)  // a mode outside the tracked disc crossed below
        return bisect_speed(model, options, grid_lo, std::move(lo), what, margin, r, report);
    }
    if (hi.tracked) {
      hi = covering(hi, grid_hi);
      if (!(margin(hi) < 0.0))  // the tracked crossing was not the full decision's
        return bisect_speed(model, options, std::move(hi), grid_hi, what, margin, r, report);
    }
  }
  const double a = margin(lo), b = margin(hi);
  SpeedBracket out;
  out.zero_m_per_s = std::isfinite(a) && std::isfinite(b) && b != a
                         ? lo.speed_m_per_s + (hi.speed_m_per_s - lo.speed_m_per_s) * (-a) / (b - a)
                         : hi.speed_m_per_s;
  out.lo = std::move(lo);
  out.hi = std::move(hi);
  return out;
}

// The damping-ratio criterion on the grid of r, then bisection inside the
// first bracket where the margin changes sign (as for the real part).
template <class Report>
void find_damping_limit(const Model& model, const CriticalSpeedOptions& options,
                        CriticalSpeedResult& r, Report& report) {
  const double limit = options.min_damping_ratio;
  r.min_damping_ratio = limit;
  int below = -1;
  for (size_t i = 0; i < r.grid.size() && below < 0; ++i)
    if (damping_margin(r.grid[i], limit) < 0.0) below = int(i);
  if (below < 0) return;
  if (below == 0) {
    r.damping_below_at_start = true;
    r.at_damping_limit = r.grid.front();
    return;
  }
  SpeedBracket b = bisect_speed(
      model, options, r.grid[size_t(below - 1)], r.grid[size_t(below)], "damping-ratio",
      [limit](const StabilityPoint& p) { return damping_margin(p, limit); }, r, report);
  r.damping_limit_speed_m_per_s = b.zero_m_per_s;
  r.at_damping_limit = std::move(b.lo);
  r.damping_limit_found = true;
}

// The sparse solver's box must hold the modes the damping-ratio limit looks
// at: a ratio below the limit in the band means Re > -limit |lambda|.
CriticalSpeedOptions with_damping_box(CriticalSpeedOptions options) {
  if (options.min_damping_ratio > 0.0)
    options.stability.sparse_min_real_part_per_s =
        std::min(options.stability.sparse_min_real_part_per_s,
                 -options.min_damping_ratio * 2.0 * std::numbers::pi *
                     options.stability.max_frequency_hz);
  return options;
}

}  // namespace

CriticalSpeedResult find_critical_speed(const Model& model, const Eigen::VectorXd& equilibrium_guess,
                                        double guess_speed_m_per_s,
                                        const CriticalSpeedOptions& requested) {
  const CriticalSpeedOptions options = with_damping_box(requested);
  if (!(options.from_m_per_s > 0.0) || !(options.to_m_per_s > options.from_m_per_s) ||
      !(options.grid_step_m_per_s > 0.0) || !(options.tolerance_m_per_s > 0.0))
    throw std::invalid_argument(
        "critical speed: expected 0 < from < to, step > 0 and tolerance > 0 (m/s)");
  const auto start = std::chrono::steady_clock::now();
  CriticalSpeedResult r;
  r.from_m_per_s = options.from_m_per_s;
  r.to_m_per_s = options.to_m_per_s;
  r.speed_tolerance_m_per_s = options.tolerance_m_per_s;
  r.requested_tolerance_m_per_s = options.tolerance_m_per_s;
  SpeedStability stability(model, equilibrium_guess, guess_speed_m_per_s, options.stability);
  auto report = [&](const StabilityPoint& p) {
    ++r.evaluations;
    if (options.progress) {
      std::ostringstream s;
      s << "  V = " << p.speed_m_per_s << " m/s: max real part " << p.max_real_part << " 1/s";
      if (p.least_stable >= 0) s << " (" << p.modes[p.least_stable].name << ")";
      options.progress(s.str());
    }
  };
  // Bracketing grid.
  const int n_grid = int(std::ceil((options.to_m_per_s - options.from_m_per_s) /
                                   options.grid_step_m_per_s - 1e-9));
  int crossing = -1;
  std::optional<SteadyStateFold> fold;
  for (int i = 0; i <= n_grid; ++i) {
    const double v =
        std::min(options.to_m_per_s, options.from_m_per_s + i * options.grid_step_m_per_s);
    try {
      r.grid.push_back(stability.at(v));
      release_state_matrix(r.grid.back());
    } catch (const std::runtime_error& e) {
      // Follow the branch by arclength from the last point: it goes on
      // (resume the grid on it) or folds back (the sweep ends there).
      std::string why = e.what();
      if (!r.grid.empty()) {
        const StabilityPoint& last = r.grid.back();
        if (options.progress) {
          std::ostringstream s;
          s << "  no steady state at " << v
            << " m/s by continuation in speed: following the branch by arclength";
          options.progress(s.str());
        }
        LostSteadyState lost = continue_past_lost_steady_state(
            model, last.equilibrium.state, last.speed_m_per_s, v, options.stability.time_s);
        if (!lost.fold && lost.reached) {
          stability.restart_from(lost.at_target.state, v);
          try {
            r.grid.push_back(stability.at(v));
            release_state_matrix(r.grid.back());
            report(r.grid.back());
            if (crossing < 0 && r.grid.back().max_real_part > 0.0) crossing = i;
            continue;
          } catch (const std::runtime_error& again) {
            why = again.what();
          }
        } else if (lost.fold) {
          fold = std::move(lost.fold);
          std::ostringstream s;
          s.precision(6);
          s << "the steady state's branch folds back at " << fold->speed_m_per_s
            << " m/s: beyond it no steady state near the one followed from below exists ("
            << why << ")";
          why = s.str();
        } else {
          std::ostringstream s;
          s << "; arclength continuation from " << last.speed_m_per_s << " m/s: " << lost.failure;
          why += s.str();
        }
      }
      r.equilibrium_lost_at_m_per_s = v;
      r.equilibrium_error = why;
      if (options.progress) options.progress("  stopped: " + why);
      break;
    }
    report(r.grid.back());
    if (crossing < 0 && r.grid.back().max_real_part > 0.0) crossing = i;
  }
  if (r.grid.empty())
    throw std::runtime_error("critical speed: no steady state even at the lowest speed: " +
                             r.equilibrium_error);
  if (r.equilibrium_lost_at_m_per_s > 0.0) {
    std::ostringstream why;
    why << "the speed grid stopped at " << r.equilibrium_lost_at_m_per_s
        << " m/s (no steady state there), below the requested " << options.to_m_per_s
        << " m/s: " << r.equilibrium_error;
    r.partial = true;
    r.partial_reason = why.str();
  }
  if (fold) r.steady_state_fold_m_per_s = fold->speed_m_per_s;
  bool lost_at_fold = false;
  if (crossing < 0 && fold) {
    // Stable at the last grid speed: the branch may still lose stability
    // before its fold (an eigenvalue crossing on the way: the point next to
    // the fold, on the branch from below, joins the grid as its last point
    // and the bisection finds the crossing as anywhere else); otherwise it
    // is lost at the fold itself (saddle-node: the fold mode's real
    // eigenvalue through zero). The two sides are the continuation's points:
    // Newton cannot polish them, its basin shrinks to nothing at the fold.
    SpeedStability sides(model, fold->before_state, fold->before_speed_m_per_s, options.stability);
    if (!r.grid.empty()) sides.plan_band_solve_from(r.grid.back());
    StabilityPoint before = sides.at_steady_state(fold->before_speed_m_per_s, fold->before_state);
    release_state_matrix(before);
    report(before);
    if (before.max_real_part > 0.0) {
      r.grid.push_back(std::move(before));
      crossing = int(r.grid.size()) - 1;
    } else {
      StabilityPoint after = sides.at_steady_state(fold->after_speed_m_per_s, fold->after_state);
      release_state_matrix(after);
      report(after);
      lost_at_fold = true;
      r.stable_in_range = false;
      r.critical_speed_found = true;
      r.critical_speed_m_per_s = fold->speed_m_per_s;
      r.speed_tolerance_m_per_s = std::max(
          options.tolerance_m_per_s, std::abs(fold->speed_m_per_s - fold->coarse_speed_m_per_s));
      r.loss = fold_loss_of_stability(before, after, *fold);
      // The mode that reaches zero is the one unstable past the fold (on
      // the stable side it need not be the least stable: its eigenvalue
      // grows as sqrt(V_fold - V)): the unstable side's modes are shown, as
      // for a jump.
      r.at_critical = std::move(after);
    }
  }
  if (lost_at_fold) {
    // decided above: the critical speed is the fold's
  } else if (crossing < 0) {
    r.stable_in_range = r.equilibrium_lost_at_m_per_s == 0.0;
  } else if (crossing == 0) {
    r.stable_in_range = false;
    r.unstable_at_start = true;
    r.at_critical = r.grid.front();
  } else {
    r.stable_in_range = false;
    // Bisection on the largest real part: robust when the least stable mode
    // changes inside the bracket; 0.01 m/s from a 5 m/s bracket is 9 steps.
    // The margin is minus the largest real part (negative: unstable).
    SpeedBracket b = bisect_speed(
        model, options, r.grid[crossing - 1], r.grid[crossing], "critical-speed",
        [](const StabilityPoint& p) { return -p.max_real_part; }, r, report,
        options.track_in_bisection);
    r.speed_tolerance_m_per_s =
        std::max(options.tolerance_m_per_s, b.hi.speed_m_per_s - b.lo.speed_m_per_s);
    r.critical_speed_m_per_s = b.zero_m_per_s;
    // The modes (hunting frequency, mode shape) at the critical speed itself,
    // one more evaluation from the stable side's steady state; where that
    // speed has none, the stable side of the bracket.
    r.at_critical = b.lo;
    if (r.critical_speed_m_per_s > r.at_critical.speed_m_per_s &&
        r.critical_speed_m_per_s < b.hi.speed_m_per_s) {
      try {
        SpeedStability at_zero(model, r.at_critical.equilibrium.state,
                               r.at_critical.speed_m_per_s, options.stability);
        at_zero.plan_band_solve_from(b.hi);
        at_zero.plan_band_solve_from(b.lo);
        StabilityPoint p = at_zero.at(r.critical_speed_m_per_s);
        release_state_matrix(p);
        report(p);
        if (p.least_stable >= 0) r.at_critical = std::move(p);
      } catch (const std::runtime_error&) {
      }
    }
    r.critical_speed_found = true;
    r.loss = classify_loss_of_stability(model, r.grid[crossing - 1], r.grid[crossing], b.lo, b.hi,
                                        r.at_critical);
    // No eigenvalue crossed: the modes worth showing are the unstable side's.
    if (r.loss.kind == LossOfStabilityKind::jump) r.at_critical = std::move(b.hi);
  }
  if (options.min_damping_ratio > 0.0) find_damping_limit(model, options, r, report);
  r.mode_tracks = track_modes(r.grid);
  name_tracked_modes(r.grid, r.mode_tracks);
  if (r.critical_speed_found || r.unstable_at_start) inherit_mode_names(r.at_critical, r.grid);
  if ((r.loss.kind == LossOfStabilityKind::jump || r.loss.kind == LossOfStabilityKind::fold) &&
      r.at_critical.least_stable >= 0)
    r.loss.unstable_mode = r.at_critical.modes[size_t(r.at_critical.least_stable)].name;
  if (r.damping_limit_found || r.damping_below_at_start)
    inherit_mode_names(r.at_damping_limit, r.grid);
  if (options.mode_shapes_at_critical && r.critical_speed_found)
    r.shapes_at_critical = full_mode_shapes(model, r.at_critical);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

std::vector<std::vector<int>> track_modes(const std::vector<StabilityPoint>& grid) {
  std::vector<std::vector<int>> ids(grid.size());
  int next_id = 0;
  auto is_tracked = [](const ModeReport& m) { return !m.neutral && m.eigenvalue.imag() > 0.0; };
  for (size_t i = 0; i < grid.size(); ++i) {
    const auto& modes = grid[i].modes;
    ids[i].assign(modes.size(), -1);
    if (i > 0) {
      std::vector<EigenPair> prev, cur;
      for (const ModeReport& m : grid[i - 1].modes) prev.push_back({m.eigenvalue, m.vector, 0.0});
      for (const ModeReport& m : modes) cur.push_back({m.eigenvalue, m.vector, 0.0});
      const std::vector<int> match = match_modes(prev, cur);
      for (size_t j = 0; j < match.size(); ++j)
        if (match[j] >= 0 && ids[i - 1][j] >= 0 && is_tracked(modes[match[j]]))
          ids[i][match[j]] = ids[i - 1][j];
    }
    for (size_t j = 0; j < modes.size(); ++j)
      if (ids[i][j] < 0 && is_tracked(modes[j])) ids[i][j] = next_id++;
  }
  return ids;
}

}  // namespace railstab

namespace railstab {

void name_tracked_modes(std::vector<StabilityPoint>& grid, const std::vector<std::vector<int>>& ids) {
  // Votes per track: shape name -> count; the smallest damping ratio along
  // the track orders the suffixes (the least damped keeps the plain name).
  // Per track also the dominant body's votes and the mean eigenvalue: the
  // words that tell equal names apart (make_names_unique).
  std::map<int, std::map<std::string, int>> votes, body_votes;
  std::map<int, double> min_damping;
  std::map<int, std::pair<std::complex<double>, int>> eigenvalue_sum;
  for (size_t i = 0; i < grid.size(); ++i)
    for (size_t j = 0; j < grid[i].modes.size(); ++j) {
      const int id = ids[i][j];
      if (id < 0) continue;
      ++votes[id][grid[i].modes[j].shape_name];
      ++body_votes[id][grid[i].modes[j].dominant_body];
      eigenvalue_sum[id].first += grid[i].modes[j].eigenvalue;
      ++eigenvalue_sum[id].second;
      const auto [it, fresh] = min_damping.emplace(id, grid[i].modes[j].damping_ratio);
      if (!fresh) it->second = std::min(it->second, grid[i].modes[j].damping_ratio);
    }
  std::vector<int> tracks;
  std::vector<std::string> names;
  std::vector<double> damping;
  std::vector<std::vector<std::string>> qualifiers;
  const auto most_voted = [](const std::map<std::string, int>& v) {
    // Most votes; among equal votes the name seen first in the map order
    // (alphabetical), so a run always picks the same one.
    return std::max_element(v.begin(), v.end(), [](const auto& a, const auto& b) {
             return a.second < b.second;
           })->first;
  };
  for (const auto& [id, v] : votes) {
    tracks.push_back(id);
    names.push_back(most_voted(v));
    damping.push_back(min_damping[id]);
    const auto& [sum, n] = eigenvalue_sum[id];
    qualifiers.push_back(mode_qualifiers(most_voted(body_votes[id]), sum / double(n)));
  }
  make_names_unique(names, {}, damping, qualifiers);
  std::map<int, std::string> track_name;
  for (size_t k = 0; k < tracks.size(); ++k) track_name[tracks[k]] = names[k];
  for (size_t i = 0; i < grid.size(); ++i) {
    auto& modes = grid[i].modes;
    const std::vector<int> partner = conjugate_partners(modes);
    std::vector<std::string> own;
    std::vector<int> copies(modes.size(), -1);
    std::vector<double> damping_ratio;
    std::vector<std::vector<std::string>> own_qualifiers;
    for (size_t j = 0; j < modes.size(); ++j) {
      own.push_back(modes[j].shape_name);
      damping_ratio.push_back(modes[j].damping_ratio);
      own_qualifiers.push_back(mode_qualifiers(modes[j].dominant_body, modes[j].eigenvalue));
      if (ids[i][j] >= 0 || partner[j] >= 0) copies[j] = int(j);  // not counted here
    }
    make_names_unique(own, copies, damping_ratio, own_qualifiers);
    for (size_t j = 0; j < modes.size(); ++j)
      if (ids[i][j] >= 0) modes[j].name = track_name[ids[i][j]];
      else if (partner[j] < 0) modes[j].name = own[j];
    for (size_t j = 0; j < modes.size(); ++j)
      if (partner[j] >= 0) modes[j].name = modes[size_t(partner[j])].name;
  }
}

void inherit_mode_names(StabilityPoint& point, const std::vector<StabilityPoint>& grid) {
  if (grid.empty()) return;
  size_t nearest = 0;
  for (size_t i = 1; i < grid.size(); ++i)
    if (std::abs(grid[i].speed_m_per_s - point.speed_m_per_s) <
        std::abs(grid[nearest].speed_m_per_s - point.speed_m_per_s))
      nearest = i;
  std::vector<EigenPair> prev, cur;
  for (const ModeReport& m : grid[nearest].modes) prev.push_back({m.eigenvalue, m.vector, 0.0});
  for (const ModeReport& m : point.modes) cur.push_back({m.eigenvalue, m.vector, 0.0});
  const std::vector<int> match = match_modes(prev, cur);
  for (size_t j = 0; j < match.size(); ++j)
    if (match[j] >= 0) point.modes[size_t(match[j])].name = grid[nearest].modes[j].name;
}

}  // namespace railstab
