#pragma once
// Stability over speed: at each speed the steady state (rolling on tangent
// track, curving in an arc: the same equilibrium solver), its exact
// linearisation, the eigenvalues and the least stable non-neutral mode; the
// critical (hunting) speed where that mode's real part crosses zero.
#include <railstab/eigen/band_eigen.hpp>
#include <railstab/equilibrium/equilibrium.hpp>
#include <railstab/linear/linearization.hpp>
#include <railstab/stability/loss_of_stability.hpp>
#include <railstab/stability/modes.hpp>

#include <complex>
#include <functional>
#include <string>
#include <vector>

namespace railstab {

// automatic: dense (all modes) below kSparseFromStates states, sparse
// (every mode in the hunting band's box, eigen/band_eigen.hpp) from there on:
// the crossover of a 12-speed critical-speed search with bisection on the
// thesis train (CPU, stop 17: 3 cars, 246 states, dense 0.67 s / sparse
// 0.91 s; 4 cars, 328 states, 1.40 / 1.46 s at a third of the memory;
// 6 cars 4.45 / 2.79 s; README, issue 11).
// arpack: the arpack_eigenvalues modes nearest one shift, dense LU (only
// when asked: it decides nothing about the modes it did not compute).
enum class EigenSolverKind { automatic, dense, arpack, sparse };
inline constexpr int kSparseFromStates = 300;
// The solvers' names, one table for the command line (--solver), a study's
// record and every report: "auto", "dense", "arpack", "sparse".
std::string eigen_solver_name(EigenSolverKind kind);
// The kind of a name from that table; throws std::invalid_argument naming the
// names it takes.
EigenSolverKind eigen_solver_from_name(const std::string& name);
std::vector<std::string> eigen_solver_names();
// The solver `kind` resolves to for an n-state linear model.
EigenSolverKind resolved_solver(EigenSolverKind kind, int n_states);

struct StabilityOptions {
  EigenSolverKind solver = EigenSolverKind::automatic;
  // ARPACK: eigenvalues nearest this shift (1/s); default near a few Hz
  // hunting with slight damping.
  std::complex<double> arpack_shift{-0.5, 2.0 * 3.14159265358979 * 3.0};
  int arpack_eigenvalues = 16;
  double time_s = 0.0;  // where on the track (frames at s(t))
  // Hunting band: the stability decision looks at modes up to this
  // frequency. Faster modes (wheel-rail contact vertical/roll, ~150 Hz,
  // undamped by the Hertz law) are reported when unstable but do not set the
  // critical speed.
  double max_frequency_hz = 20.0;
  // sparse: the box searched (with max_frequency_hz) and the solves' size;
  // every eigenvalue in it is found (eigen/band_eigen.hpp). Its real-part
  // range holds the crossing of a hunting mode; find_critical_speed widens
  // the lower end to hold the damping-ratio limit's modes when that is
  // asked (-min_damping_ratio 2 pi max_frequency_hz).
  double sparse_min_real_part_per_s = -2.0;
  double sparse_max_real_part_per_s = 2.0;
  int sparse_eigenvalues_per_shift = 16;
};

struct StabilityPoint {
  double speed_m_per_s = 0.0;
  EquilibriumResult equilibrium;
  LinearModel linear;
  std::vector<ModeReport> modes;  // dense: all; arpack: the ones found
  EigenSolverKind solver_used = EigenSolverKind::dense;
  double time_s = 0.0;            // where on the track (StabilityOptions::time_s)
  int least_stable = -1;          // index into modes, -1 if none: largest real part (decides stability)
  int least_damped = -1;          // index into modes, -1 if none: smallest damping ratio of
                                  // the lateral-plane modes (tables, damping criterion)
  double max_real_part = 0.0;     // of the non-neutral modes (1/s)
  // Non-empty when a wheelset's steady lateral shift exceeds its flange
  // clearance (the flangeless contact model is outside its validity there)
  // or, on real profiles, a wheel's Y/Q exceeds Nadal's limit (flange
  // climbing: model/wheel_forces.hpp).
  std::string validity_warning;
  // Unstable non-neutral modes above the hunting band (indices into modes).
  std::vector<int> unstable_above_band;
  // sparse: how many shifts, and whether their discs covered the box (if
  // not, eigen_warning says so and the decision may have missed a mode).
  int eigen_shifts = 0;
  std::string eigen_warning;
  // The covering solve's discs (sparse, not tracked; empty otherwise): a
  // fresh SpeedStability near this speed starts its band solve from them
  // (SpeedStability::plan_band_solve_from).
  std::vector<ShiftDisc> band_discs;
  // A tracked point (a critical-speed bisection's midpoint, sparse solver):
  // only the modes nearest the mode that crosses, one shift-invert solve at
  // its eigenvalue at the bracket's unstable end (SpeedStability::tracking);
  // every eigenvalue within tracked_radius_per_s of tracked_shift is among
  // `modes`, nothing is known of the rest of the box.
  bool tracked = false;
  std::complex<double> tracked_shift;
  double tracked_radius_per_s = 0.0;
  double seconds = 0.0;           // wall time of this point
};

// Evaluates speeds in sequence on one model, each equilibrium starting from
// the previous one (continuation). The model must outlive this object.
class SpeedStability {
 public:
  // `guess_speed_m_per_s`: the speed the guess is an equilibrium of (its
  // wheelset spin rates are scaled from it).
  SpeedStability(const Model& model, const Eigen::VectorXd& equilibrium_guess,
                 double guess_speed_m_per_s, StabilityOptions options = {});
  StabilityPoint at(double speed_m_per_s);
  // As at(), but the eigen-analysis only the `modes` eigenpairs nearest
  // `shift` (sparse shift-invert, eigen/band_eigen.hpp eigen_sparse_nearest):
  // a point with tracked = true. For following a known mode a short way in
  // speed; it proves nothing about the box outside its disc.
  StabilityPoint tracking(double speed_m_per_s, std::complex<double> shift, int modes);
  // The first covering sparse solve starts from the discs of `near` (a point
  // at a nearby speed, e.g. a bisection bracket's end) instead of placing
  // its shifts from nothing: guesses only, coverage is still proven. No
  // effect when `near` has no discs (dense, tracked).
  void plan_band_solve_from(const StabilityPoint& near);
  // As at(), at a steady state found elsewhere (a continuation's point, e.g.
  // next to a fold, where Newton's basin is too narrow to polish it): no
  // solve, the state is linearised as given (equilibrium.max_acceleration
  // says how well it solves the equations).
  StabilityPoint at_steady_state(double speed_m_per_s, const Eigen::VectorXd& state);
  // The next at() continues from this steady state instead of the last one.
  void restart_from(const Eigen::VectorXd& state, double speed_m_per_s);

 private:
  template <class Eigen_>
  StabilityPoint evaluate(double speed_m_per_s, bool sparse, Eigen_&& eigen_analysis,
                          const Eigen::VectorXd* given_state = nullptr);
  StabilityPoint covering(double speed_m_per_s, const Eigen::VectorXd* given_state);
  EquilibriumResult steady_state_at(double speed_m_per_s);
  const Model& model_;
  StabilityOptions options_;
  Eigen::VectorXd last_equilibrium_;
  double last_speed_;
  // Coloured-Jacobian plans, made once for every speed.
  RhsJacobianPlan jacobian_plan_, equilibrium_plan_;
  // The last covering sparse solve's discs: the next speed's shifts and k
  // start from them (eigen_sparse_band's plan; coverage is still proven).
  std::vector<ShiftDisc> last_band_discs_;
};

std::vector<EigenPair> solve_eigen(const Eigen::MatrixXd& A, const StabilityOptions& options);

struct CriticalSpeedResult {
  double from_m_per_s = 0.0, to_m_per_s = 0.0;
  bool stable_in_range = true;       // no crossing and stable throughout
  bool unstable_at_start = false;    // already unstable at the lowest speed
  bool critical_speed_found = false; // a crossing was bracketed and refined
  double critical_speed_m_per_s = 0.0;
  double speed_tolerance_m_per_s = 0.0;    // reached (wider where a bisection stopped)
  double requested_tolerance_m_per_s = 0.0;  // CriticalSpeedOptions::tolerance_m_per_s
  // At the critical speed itself (its least stable mode's real part ~0);
  // the stable side of the final bracket where that speed has no steady
  // state. at_critical.speed_m_per_s says which.
  StabilityPoint at_critical;
  // How the stability is lost there (stability/loss_of_stability.hpp): an
  // oscillatory or aperiodic crossing, or a jump of the steady state (then
  // at_critical is the unstable side of the final bracket).
  LossOfStability loss;
  // Damping-ratio criterion (CriticalSpeedOptions::min_damping_ratio): the
  // lowest speed where the least damped mode's ratio falls below the limit,
  // bisected like the critical speed on (smallest ratio - limit).
  double min_damping_ratio = 0.0;    // the limit; 0: criterion not asked
  bool damping_limit_found = false;
  bool damping_below_at_start = false;
  double damping_limit_speed_m_per_s = 0.0;
  StabilityPoint at_damping_limit;   // the side above the limit of the final bracket
  // The whole speed grid (for root locus and plots). Its points, and the
  // bisection's, keep modes and eigenvectors but not the state matrix
  // (linear.A and A_sparse released: memory per point bounded).
  std::vector<StabilityPoint> grid;
  // Modes followed across the grid (track_modes(grid)): mode_tracks[i][j] is
  // the track of grid[i].modes[j], -1 where untracked. The plots' lines and
  // the eigenvalue CSV's mode_track column.
  std::vector<std::vector<int>> mode_tracks;
  // The full shape of every mode of at_critical (stability/
  // point_mode_shapes.hpp), in the order of at_critical.modes; empty when no
  // critical speed was found or CriticalSpeedOptions::mode_shapes_at_critical
  // is off.
  std::vector<ModeShape> shapes_at_critical;
  int evaluations = 0;
  double seconds = 0.0;
  // The grid stops at the first speed without a steady state (e.g. a cant
  // deficiency the flangeless contact cannot carry); the analysis covers
  // the speeds below it.
  double equilibrium_lost_at_m_per_s = 0.0;  // 0: never lost
  // Where the lost steady state's branch folds back in speed
  // (stability/steady_state_fold.hpp); 0: no fold found.
  double steady_state_fold_m_per_s = 0.0;
  std::string equilibrium_error;
  // The run could not finish what it was asked (the grid stopped below the
  // top speed, or a bisection midpoint had no steady state): what was found
  // is kept and reported, marked partial, with the reason.
  bool partial = false;
  std::string partial_reason;
};

struct CriticalSpeedOptions {
  double from_m_per_s = 5.0, to_m_per_s = 100.0, grid_step_m_per_s = 5.0;
  double tolerance_m_per_s = 0.01;
  StabilityOptions stability;
  // Sparse solver: the critical-speed bisection's midpoints follow the
  // crossing mode (tracked points, `tracked_modes` eigenpairs at its last
  // eigenvalue) instead of covering the whole box; the final bracket's ends
  // are evaluated again with the full covering solve, so the bracket is
  // proven as without tracking (see find_critical_speed). Grid points always
  // cover the box.
  bool track_in_bisection = true;
  int tracked_modes = 12;
  // > 0: also find the lowest speed where a lateral-plane mode in the
  // hunting band (least_damped_mode) has a damping ratio below this (e.g.
  // 0.05); 0: off.
  double min_damping_ratio = 0.0;
  // Form CriticalSpeedResult::shapes_at_critical (two AD Jacobians at the
  // critical speed's steady state): what the reports show; a study's many
  // searches need only the speed.
  bool mode_shapes_at_critical = true;
  std::function<void(const std::string&)> progress;
};

// Modes followed across the speed grid by eigenvector continuity (MAC), not
// by sort order: track_id[i][j] is the track of grid[i].modes[j] (-1 for
// non-oscillatory or neutral modes and for Im < 0 partners).
std::vector<std::vector<int>> track_modes(const std::vector<StabilityPoint>& grid);

// One name per tracked mode over the whole grid (the shape name it has at
// most speeds, made unique across tracks with suffixes in ascending smallest
// damping ratio along the track), written into every grid point's modes; untracked modes (real,
// neutral) keep their shape names, unique within their speed. `ids` from
// track_modes(grid).
void name_tracked_modes(std::vector<StabilityPoint>& grid, const std::vector<std::vector<int>>& ids);

// Names of a point off the grid (a bisection point) from the grid point
// nearest in speed, by eigenvector continuity (match_modes); modes that match
// none keep their own names.
void inherit_mode_names(StabilityPoint& point, const std::vector<StabilityPoint>& grid);

CriticalSpeedResult find_critical_speed(const Model& model, const Eigen::VectorXd& equilibrium_guess,
                                        double guess_speed_m_per_s,
                                        const CriticalSpeedOptions& options);

}  // namespace railstab
