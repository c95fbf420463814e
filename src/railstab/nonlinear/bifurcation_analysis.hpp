#pragma once
// The nonlinear critical speed of a vehicle: the linear critical speed and
// its Hopf criticality, then the branch of hunting orbits (shooting +
// pseudo-arclength continuation, orbit_continuation.hpp) from the Hopf point
// and, independently, from a hunting cycle found by a time-domain run at a
// given speed. The nonlinear critical speed is the lowest speed with a stable
// hunting orbit on either branch (its fold), nonlinear_critical_speed below.
//
// Profile contact (tabulated wheel-rail geometry, C1 between table points):
// the first Lyapunov coefficient would be the third derivative of the
// table's interpolation, so it is not computed; the branch from the Hopf
// point then starts from the eigenvector alone (V guessed at V_c, corrected
// at fixed excursion) and its first two orbits say on which side of V_c the
// small cycles lie (the Hopf kind as the continuation finds it).
#include <railstab/nonlinear/hopf_assessment.hpp>
#include <railstab/nonlinear/hopf_criticality.hpp>
#include <railstab/nonlinear/model_orbits.hpp>
#include <railstab/nonlinear/orbit_continuation.hpp>
#include <railstab/stability/speed_analysis.hpp>

#include <functional>
#include <string>
#include <vector>

namespace railstab {

// 1.03: on the thesis bogie on S1002/UIC60 (V_c 39.80 m/s) a run from 5 mm
// at 41 m/s settles on the flange-hunting cycle whose branch folds at
// 34.99 m/s; at 36 m/s (below V_c) the same start decays.
inline constexpr double kDefaultCycleSpeedRatio = 1.03;

// A time-domain start whose settled cycles differ by more than this
// (OrbitGuess::spread: periods over their mean, principal maxima over the
// half range) is said to be not periodic, before the first orbit and with
// its failure. Measured on the S1002 thesis vehicle, 6 s from 5 mm, over
// the run's second half (15-20 cycles): at most 0.3 % (periods) and 0.2 %
// (maxima) at 100 and 104.7 m/s, where periodic orbits exist; 1.6-2.6 % and
// 0.9-1.2 % at 110 m/s, 12.6 % and 2.2 % at 122 m/s, where the hunting is
// not periodic (docs/nonlinear.md). Over the last second alone 110 m/s
// could pass (0.7 %): the motion is irregular over longer than a second.
inline constexpr double kSettledCycleSpreadLimit = 0.01;
// Where the default start's settled run is not periodic, it is tried again
// at 0.95 x the speed, up to 6 runs in all (122.1 m/s down to at most
// 94.5 m/s on the S1002 vehicle; each run 3-4 s CPU there, against minutes
// of Newton iterations on a motion with no periodic orbit).
inline constexpr double kDefaultStartLowering = 0.95;
inline constexpr int kDefaultStartTries = 6;

struct BifurcationOptions {
  CriticalSpeedOptions linear;            // the linear search's range and grid
  // Speed range and amplitude limit set from the run. On profile contact the
  // orbits' variational equations are integrated in a second pass
  // (FlowOptions::Variational::second_pass: 1.7 times faster on the S1002
  // thesis vehicle's orbits, the same multipliers to 6 digits); elsewhere
  // as continuation.shooting.flow says (alongside: on the smooth models'
  // small orbits near a Hopf point, whose speed is set by cubic terms to
  // 1e-6 m/s, only the alongside flow's finer steps meet the sqrt law
  // to 1 %, docs/nonlinear.md).
  ContinuationOptions continuation;
  std::string wheelset;                   // whose lateral motion is the excursion ("": the first)
  double first_excursion_m = 5e-5;        // of the Hopf branch's first orbit
  double max_amplitude_m = 0.012;         // stop a branch beyond this lateral amplitude
  bool from_hopf = true;
  // > 0: also start a branch from the cycle a time-domain run settles on at
  // this speed, from the steady state with the wheelset displaced by
  // disturbance_m, after settle_time_s.
  double cycle_speed_m_per_s = 0.0;
  // Profile contact without a cycle speed: start the time-domain branch at
  // kDefaultCycleSpeedRatio x the linear critical speed (an oscillatory
  // crossing; at most the top of the range). The Hopf start on a tabulated
  // contact finds only micrometre cycles (docs/nonlinear.md), and the
  // flange-hunting cycle that sets the nonlinear critical speed is reached
  // from a disturbance where the steady state is unstable or nearly so.
  bool default_cycle_start = true;
  double disturbance_m = 0.005;
  double settle_time_s = 6.0;
  // The time-domain branch's second orbit: at the cycle speed plus this
  // (m/s); its sign is the direction the branch is followed in speed first
  // (downwards: towards the fold below a flange-hunting cycle; upwards: to
  // higher speeds). Non-zero, |step| <= 5 m/s.
  double cycle_speed_step_m_per_s = -0.5;
  // One line per orbit (branch, speed, amplitude, largest multiplier,
  // stability, steps, Newton iterations, CPU) and per stage.
  std::function<void(const std::string&)> progress;
};

// Where a wheelset's lateral displacement and yaw sit in the reduced state
// (-1: not a free coordinate): the report's amplitudes per orbit.
struct WheelsetOrbitStates {
  std::string name;
  int lateral_state = -1;  // "<name>.y_m"
  int yaw_state = -1;      // "<name>.yaw_rad"
};

// How the lowest stable orbit speed is bounded below (nonlinear_critical_speed):
// - fold: the stable part of a branch ends at a fold (the branch turns back
//   to higher speeds, unstable): below it no orbit of that branch exists;
// - hopf_point: the stable part starts at the Hopf point (supercritical):
//   the nonlinear critical speed is the linear one;
// - period_doubling, torus: the stable part ends where a multiplier leaves
//   the unit circle at -1 or as a complex pair (orbits go on, unstable);
// - speed_range_end: the branch left the speed range still stable;
// - branch_end: the branch stopped (step-size floor, orbit limit, amplitude
//   limit) at a stable orbit: what lies beyond is not known.
// The first four determine the speed (found); the last two only bound it
// from above (not found: the report says so and gives the bound).
enum class StableBound { none, fold, hopf_point, period_doubling, torus, speed_range_end, branch_end };
std::string stable_bound_name(StableBound bound);  // "fold", "hopf_point", ...

struct NonlinearCriticalSpeed {
  bool found = false;                      // a determined lower end of the stable orbits
  double speed_m_per_s = 0.0;              // when found
  StableBound bound = StableBound::none;   // of the lowest stable orbit (none: no stable orbit)
  // The lowest speed of a stable orbit or fold next to one on any branch,
  // found or not (an upper bound when !found); 0 with bound none.
  double lowest_stable_speed_m_per_s = 0.0;
  int branch = -1;                         // index into BifurcationResult::branches
  std::string explanation;                 // one sentence: what the number is, or why none
};

struct BranchResult {
  std::string origin;                     // "hopf" or "time_domain"
  OrbitBranch branch;
  std::string error;                      // non-empty: the branch could not be started
};

struct BifurcationResult {
  CriticalSpeedResult linear;
  bool profile_contact = false;
  bool hopf_computed = false;             // l1 from the exact derivatives (smooth contact only)
  HopfCriticality hopf;
  // The kind as reported: from l1, or (profile contact) from the side of V_c
  // where the Hopf branch's first orbits lie; "" when neither is known.
  std::string hopf_kind;
  std::vector<BranchResult> branches;
  // The Hopf criticality as the critical-speed command assesses it (the same
  // l1 and kind, or why not computed): its description in the report.
  HopfAssessment hopf_assessment;
  NonlinearCriticalSpeed nonlinear;
  std::vector<int> reduced_states;        // full-state index of every orbit state
  std::vector<std::string> state_names;   // of the reduced states
  OrbitCoordinates coords;
  std::string amplitude_state_name;       // the excursion state ("wheelset1.y_m")
  std::vector<WheelsetOrbitStates> wheelsets;
  // The speed range and limits the branches ran with.
  double from_m_per_s = 0.0, to_m_per_s = 0.0, max_amplitude_m = 0.0;
  // The time-domain branch's start speed (0: none), and whether it is the
  // profile-contact default (BifurcationOptions::default_cycle_start) or
  // was given; where the default could not apply, why (no branch then).
  double cycle_speed_m_per_s = 0.0;
  bool cycle_speed_default = false;
  // The default start's speeds whose settled run was not periodic, tried
  // and left for cycle_speed_m_per_s (kDefaultStartLowering).
  std::vector<double> cycle_speeds_not_periodic_m_per_s;
  bool cycle_branch_upwards = false;      // the sign of cycle_speed_step_m_per_s
  std::string no_default_cycle_reason;
  double cpu_seconds = 0.0;
};

// The lowest stable orbit of the branches and what bounds it below (see
// StableBound); `r.branches`, `r.linear` and `r.hopf_kind` set.
NonlinearCriticalSpeed nonlinear_critical_speed(const BifurcationResult& r);

// The time-domain branch's first speed step for a direction named "down"
// or "up" (BifurcationOptions::cycle_speed_step_m_per_s): -0.5 or +0.5 m/s.
// Throws std::invalid_argument naming `option` (the front end's flag or
// keyword) for another name.
double cycle_speed_step_for(const std::string& direction, const std::string& option);

// Whether `options` start any branch on `model`: the Hopf branch, a given
// cycle speed, or the profile-contact default (default_cycle_start). The
// front ends refuse a run without one, each naming its own flags.
bool starts_a_branch(const Model& model, const BifurcationOptions& options);

// `equilibrium` is the steady state at `speed_m_per_s` (the scene's).
BifurcationResult analyse_bifurcation(const Model& model, const Eigen::VectorXd& equilibrium,
                                      double speed_m_per_s, const BifurcationOptions& options);

}  // namespace railstab
