#pragma once
// Steady curving: the vehicle's steady state on a uniform arc (radius R,
// cant h) at speed V, from cant excess to beyond 300 mm cant deficiency, and
// where no steady state exists physically, the statement why.
//
// Conditions. With D the rail contact distance (track.rail_contact_distance_m)
// and g gravity, the cant deficiency is
//
//   h_d = D V^2 / (g R) - h          (m; < 0: cant excess),
//
// and the lateral acceleration in the track plane that the wheel-rail forces
// carry is a_y = V^2 / R cos(phi) - g sin(phi), sin(phi) = h / D; for the
// whole vehicle, sum over the wheels of the track-plane lateral force of the
// rails = m a_y (= m (V^2 / R - g h / D) to first order in phi).
//
// Model. The scene's model with its track replaced by one arc of constant
// curvature and cant along its whole length (uniform_arc_model): every body
// is on the same arc, whatever the scene's track does elsewhere. The
// suspension preloads are solved on straight level track (setup/build_model),
// so they are unchanged.
//
// Method (docs/steady_curving.md). Newton's method at the target from the
// nearest solution known; where it fails, pseudo-arclength continuation
// (equilibrium/arclength_continuation.hpp) in speed, curvature and cant,
// linearly between a converged condition and the target, which follows the
// branch around the folds where wheelsets move onto the flange root. At
// every converged point the physical limit is checked (physical_limit):
// beyond it the vehicle has no steady state, and the continuation stops
// there with the forces of the last converged point.
#include <railstab/contact_geometry/characteristic_functions.hpp>
#include <railstab/equilibrium/arclength_continuation.hpp>
#include <railstab/model/model.hpp>
#include <railstab/model/wheel_forces.hpp>

#include <Eigen/Dense>

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace railstab {

struct CurvingCondition {
  double curvature_per_m = 0.0;  // 1/R, > 0 turns left
  double cant_m = 0.0;           // > 0 raises the right rail
  double speed_m_per_s = 0.0;
};

// h_d = D V^2 |kappa| / g - h_outer (the cant on the curve's outer rail:
// h in a left-hand curve, -h in a right-hand one; on the straight |h|: a
// canted straight is all cant excess, h_d = -|h|).
double cant_deficiency_m(const CurvingCondition& c, double rail_contact_distance_m,
                         double gravity_m_per_s2);
// V = sqrt(g R (h_d + h_outer) / D); throws std::invalid_argument when the
// condition asks for a speed that is not positive (h_d <= -h_outer) or on
// the straight.
double speed_for_cant_deficiency(double curvature_per_m, double cant_m, double cant_deficiency_m,
                                 double rail_contact_distance_m, double gravity_m_per_s2);
// "V = 57.5 m/s, cant deficiency 187 mm, R = 1500 m (left), cant 150 mm"
std::string describe_condition(const CurvingCondition& c, double rail_contact_distance_m,
                               double gravity_m_per_s2);

// The scene's curvature and cant at its reference point, at speed V.
CurvingCondition condition_at_reference(const Model& model, double speed_m_per_s);

// `model` with its track replaced by one arc of the given curvature and cant
// over the same length (start pose as the scene's track).
Model uniform_arc_model(const Model& model, double curvature_per_m, double cant_m);

// A wheel's contact is on its flange where a loaded contact point's angle
// exceeds kFlangeContactAngle_rad (45 deg, contact_geometry/
// characteristic_functions.hpp: where the rigid contact jumps onto the flange
// face; the S1002/UIC60 tread and its transition stay below ~0.3 rad, the
// flange flank is at 70 deg).
// A wheel that stands this far above a centred wheel is climbing its rail.
inline constexpr double kClimbingLift_m = 1e-3;

// Where the vehicle at (model, V, x) is at or beyond the limit of steady
// curving: a wheel with Y/Q at or beyond Nadal's limit on its flange (a
// loaded contact point beyond kFlangeContactAngle_rad), a wheel lifted by
// more than kClimbingLift_m above a centred wheel's height, or a wheel at
// the edge of its contact table (kTableEdgeFraction of a half range); on a
// flangeless contact (cone, linear conicity) a wheelset past its flange
// clearance (the model's validity limit: no flange is modelled). Empty where
// none is; otherwise the statement with the wheel's forces, e.g.
// "wheelset1 right wheel Y/Q 0.88 reaches Nadal's limit 0.88 (Y 61.2 kN,
// Q 69.6 kN, lift 0.4 mm, lateral shift -7.1 mm): flange climbing".
std::string physical_limit(const Model& model, double speed_m_per_s, const Eigen::VectorXd& x);

// Whether the vehicle stays in a steady state: the eigenvalues of the
// state derivative's Jacobian (every state but the cyclic spin angles) at
// it. A real eigenvalue > 0 is a divergence (the middle branch between two
// folds: a small disturbance runs away from it); a complex pair with a
// positive real part below max_frequency_hz is an oscillation growing from
// it (hunting). Faster modes (wheel-rail contact modes, ~160 Hz, see
// docs/model.md section 13) do not decide, as in the critical-speed search.
struct SteadyStateStability {
  int divergent = 0;             // real eigenvalues > 1e-6 1/s
  int oscillatory = 0;           // complex pairs, Re > 1e-6 1/s, below max_frequency_hz
  double largest_real_part = 0;  // of the eigenvalues below max_frequency_hz (1/s)
  bool stable() const { return divergent == 0 && oscillatory == 0; }
  // "stable" or "unstable: 4 divergent modes (largest real part 61.8 1/s)"
  std::string describe() const;
};
SteadyStateStability steady_state_stability(const Model& model, double speed_m_per_s,
                                            const Eigen::VectorXd& x,
                                            double max_frequency_hz = 20.0);

// A steady curving state.
struct SteadyCurvingState {
  CurvingCondition condition;
  double cant_deficiency_m = 0.0;
  EquilibriumResult equilibrium;
  // "Newton" or "arclength continuation (k steps, f folds) from <condition>".
  std::string method;
  int continuation_steps = 0;
};

// No steady state found. `physical` says the vehicle has none beyond the
// last converged point (physical_limit held there, or the branch turned
// back at a fold with a wheel on its flange); otherwise the solver failed.
// last_converged is empty when no point converged at all.
struct CurvingError : std::runtime_error {
  CurvingError(const std::string& message, bool physical_limit,
               std::optional<SteadyCurvingState> last)
      : std::runtime_error(message), physical(physical_limit), last_converged(std::move(last)) {}
  bool physical = false;
  std::optional<SteadyCurvingState> last_converged;
};

struct SteadyCurvingOptions {
  double acceleration_tolerance = 1e-7;
  // Where no solution is known: the speed of the first solve (on the target
  // arc, from the nominal position), from which the continuation starts.
  double start_speed_m_per_s = 5.0;
  // A march to a far target goes in steps of this many units of the path's
  // length scale (about m/s of speed or cm of cant deficiency).
  double march_step = 2.5;
  ArclengthOptions continuation;  // tolerance and stop are set per call
};

// The steady state at `target` on a uniform arc of `scene_model`'s vehicle.
// `from`: a converged steady state to start from (a sweep's previous point):
// Newton from it, else the continuation from it. Without it: Newton from
// the nominal position, else a march from options.start_speed_m_per_s on
// the target arc (or, where Newton fails there, on the straight) to the
// target in steps of options.march_step, each as with `from`. Throws
// CurvingError.
SteadyCurvingState solve_steady_curving(const Model& scene_model, const CurvingCondition& target,
                                        const std::optional<SteadyCurvingState>& from = {},
                                        const SteadyCurvingOptions& options = {});

// The same on the scene's own model and track at speed V (the `equilibrium`
// command: the reference point need not be on an arc), from a converged
// state at from_speed: continuation in speed. Throws CurvingError.
SteadyCurvingState continue_scene_steady_state(const Model& model, double from_speed_m_per_s,
                                               const Eigen::VectorXd& from_state,
                                               double speed_m_per_s,
                                               const SteadyCurvingOptions& options = {});

// One row of a curving table: the state and what an engineer reads off it.
struct CurvingWheelset {
  int body = 0;
  double lateral_shift_m = 0.0;     // from the nominal position, +y left
  double angle_of_attack_rad = 0.0; // yaw to the track tangent
  double roll_rad = 0.0;
  double sum_y_N = 0.0, prudhomme_limit_N = 0.0;
  WheelForces left, right;
  bool left_flange = false, right_flange = false;  // kFlangeContactAngle_rad
};
struct CurvingPoint {
  SteadyCurvingState state;
  SteadyStateStability stability;
  double lateral_acceleration_m_per_s2 = 0.0;  // a_y in the track plane
  std::vector<CurvingWheelset> wheelsets;
  // Sum over the wheels of the rails' lateral force on them along each
  // wheelset's track y (the force balance's left side), and m a_y.
  double rail_lateral_force_N = 0.0;
  double mass_times_lateral_acceleration_N = 0.0;
  std::string nadal_warning;  // a wheel beyond Nadal's limit (empty: none)
};
CurvingPoint curving_point(const Model& scene_model, const SteadyCurvingState& state,
                           double prudhomme_factor);

// A sweep over cant deficiency at one radius, or over radius at one cant
// deficiency, each point continued from the previous one. Where the state
// continued to is unstable (the branch between two folds), the stable
// steady state the pseudo-transient continuation settles on from the
// nominal position (model.md section 8) replaces it if there is one; the
// sweep goes on from the point kept. An unstable point is kept, and said,
// where no stable one is found.
struct CurvingSweep {
  std::vector<CurvingPoint> points;
  // Where the sweep stopped before its end because the vehicle has no steady
  // state physically beyond its last point: the statement (with the forces).
  std::string physical_limit;
  std::optional<CurvingCondition> limit_condition;  // the first condition not reached
};
enum class CurvingSweepKind { cant_deficiency, radius };
// `values`: cant deficiencies (m) at `fixed` = the radius, or radii (m) at
// `fixed` = the cant deficiency (m). The turn and cant are the scene's at
// its reference point (a straight reference: a left-hand curve). Throws
// CurvingError when the solver fails (not physical) at a point, naming the
// last converged point.
CurvingSweep sweep_steady_curving(const Model& scene_model, CurvingSweepKind kind,
                                  const std::vector<double>& values, double fixed,
                                  double prudhomme_factor, const SteadyCurvingOptions& options = {});

}  // namespace railstab
