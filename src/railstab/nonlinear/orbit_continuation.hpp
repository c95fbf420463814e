#pragma once
// The branch of periodic (hunting) orbits over speed: pseudo-arclength
// continuation of single-shooting orbits (periodic_orbit.hpp) with step
// control, through folds, with the Floquet multipliers of every orbit.
//
// The arclength is measured in the plane of the speed V and the leading
// wheelset's lateral excursion a = x0[amplitude_state] (the orbit's start
// lies where that wheelset's lateral velocity is 0, so a is an extremum of
// its lateral motion), scaled by speed_scale_m_per_s and amplitude_scale:
//   s^2 = ((V - V_k) / s_V)^2 + ((a - a_k) / s_a)^2.
// Predictor: the secant through the last two orbits (every unknown
// extrapolated); corrector: Newton on the orbit with the pseudo-arclength
// condition t_V (V - V_p) / s_V + t_a (a - a_p) / s_a = 0, (t_V, t_a) the
// unit secant in the scaled plane. A fold in V (the nonlinear critical
// speed) is a regular point of this plane's curve, so the branch goes
// round it; so is a fold in a, as long as the two do not coincide.
// Near a fold in V that is sharp in the scaled plane (the S1002 vehicle's:
// the branch turns within 0.005 mm of excursion), predictions go past the
// fold and correctors fail; after a failure the step's change of the
// excursion alone is tried at fixed excursion, which is well posed through
// a fold in V (V a function of a there), before the step is halved.
// Step control: the step grows by growth_factor after a corrector that
// converged in <= fast_newton_iterations (or whose orbit lay within
// straight_predictor_error x the step of the prediction), halves after a
// failure, and the
// run stops below min_step.
//
// The branch starts from an orbit of small excursion near the Hopf point
// (start_at_hopf: from the critical eigenvector) or from an orbit found by a
// time-domain run (start_from_orbit), and is followed in one direction.
#include <railstab/nonlinear/periodic_orbit.hpp>

#include <Eigen/Dense>

#include <complex>
#include <functional>
#include <string>
#include <vector>

namespace railstab {

struct ContinuationOptions {
  ShootingOptions shooting;
  double speed_scale_m_per_s = 1.0;
  double amplitude_scale = 1e-3;          // units of the amplitude state (1 mm)
  double initial_step = 0.2;              // scaled arclength
  double min_step = 1e-3;
  double max_step = 2.0;
  double growth_factor = 1.5;
  // After a corrector fails, the same step's change of the excursion alone
  // is tried at fixed excursion (a = a_k + h t_a s_a, every other unknown
  // free; the secant's values there the guess) before the step is halved.
  bool excursion_step_after_failure = true;
  // A fold found from the speed's turn is refined by one more orbit at fixed
  // excursion at its parabola's vertex, and the vertex through that orbit
  // and its neighbours (the orbit is not added to the branch).
  bool refine_folds = true;
  int fast_newton_iterations = 3;
  // The step also grows after a corrector that moved the orbit by at most
  // this fraction of the step from the secant's prediction (scaled plane).
  double straight_predictor_error = 0.05;
  int max_orbits = 200;
  double min_speed_m_per_s = 0.0;         // stop outside [min, max]
  double max_speed_m_per_s = 1e9;
  double max_amplitude = 1e9;             // stop when the excursion exceeds it (flange climbing)
  // Stop two orbits past the branch's first fold (enough for the fold's
  // parabola through the orbits around it): the nonlinear critical speed
  // without the rest of the branch.
  bool stop_at_first_fold = false;
  // Called for every orbit as it joins the branch (the first two included),
  // with its 1-based number on the branch.
  std::function<void(int orbit_number, const PeriodicOrbit& orbit)> progress;
  // Called for every corrector that failed (its orbit is retried with half
  // the step): the step it had (scaled arclength), why it failed, and its
  // CPU seconds (spent without an orbit to show for them).
  std::function<void(double step, const std::string& reason, double cpu_s)> corrector_failed;
};

enum class OrbitBifurcationKind { fold, period_doubling, torus };
std::string orbit_bifurcation_name(OrbitBifurcationKind kind);  // "fold", "period_doubling", "torus"

struct OrbitBifurcation {
  OrbitBifurcationKind kind = OrbitBifurcationKind::fold;
  int after_orbit = 0;                    // between orbits after_orbit and after_orbit + 1
  double speed_m_per_s = 0.0;             // interpolated (fold: the vertex of a parabola)
  double amplitude = 0.0;                 // of the amplitude state (half peak-to-peak)
  std::complex<double> multiplier;        // the crossing multiplier at the second orbit
};

struct OrbitBranch {
  std::vector<PeriodicOrbit> orbits;
  std::vector<OrbitBifurcation> bifurcations;
  std::string stop_reason;                // why the continuation ended
  int failed_correctors = 0;
  double cpu_seconds = 0.0;               // the orbits' solves, the first two included
};

// The Floquet multiplier that crossed the unit circle between two orbits of
// a branch whose counts of non-trivial multipliers outside it (|mu| > 1 +
// tolerance) differ: of the orbit with more, its outside multiplier nearest
// the circle. Not the multiplier nearest the circle overall: on the S1002
// vehicle's branch a weakly damped pair at |mu| 0.996 lies nearer than the
// real multiplier that has just passed +1 at 1.008 (its fold). Its kind
// names the bifurcation: real > 0 a fold, real < 0 a period doubling, a
// complex pair a torus. 0 when neither orbit has a multiplier outside.
std::complex<double> crossing_multiplier(const PeriodicOrbit& a, const PeriodicOrbit& c,
                                         double tolerance);

// Two first orbits from the Hopf point: equilibrium `x_eq` (at V_c), the
// critical eigenvector `q` (A q = i w0 q), and the small cycle's excursion
// law a = amplitude_per_sqrt_speed sqrt(cycle_side (V - V_c)) of the
// amplitude state (hopf_criticality.hpp); the orbits at excursions
// first_excursion and 2 first_excursion, each corrected at fixed excursion
// (V free). cycle_side 0 (no prediction): the first guess is V_c, the
// second the first orbit with its offset from x_eq and from V_c doubled.
struct HopfStart {
  Eigen::VectorXd equilibrium;
  double critical_speed_m_per_s = 0.0;
  std::complex<double> eigenvalue;
  Eigen::VectorXcd eigenvector;
  int cycle_side = 0;
  double amplitude_per_sqrt_speed = 0.0;
};
OrbitBranch continue_from_hopf(const FlowSystem& system, const OrbitCoordinates& coords,
                               const HopfStart& start, double first_excursion,
                               const ContinuationOptions& options);

// From a converged orbit: a second orbit at speed first.speed + speed_step
// (fixed speed) gives the direction, then the continuation.
OrbitBranch continue_from_orbit(const FlowSystem& system, const OrbitCoordinates& coords,
                                const PeriodicOrbit& first, double speed_step_m_per_s,
                                const ContinuationOptions& options);

// From two converged orbits (the direction from first to second).
OrbitBranch continue_branch(const FlowSystem& system, const OrbitCoordinates& coords,
                            std::vector<PeriodicOrbit> first_two, const ContinuationOptions& options);

// The lowest speed at which the branch has a stable orbit: a stable orbit's
// speed or, where the stable part ends at a fold, the fold's speed. NaN when
// no orbit of the branch is stable.
double lowest_stable_speed(const OrbitBranch& branch);

}  // namespace railstab
