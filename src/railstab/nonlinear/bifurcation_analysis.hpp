#pragma once
// The nonlinear critical speed of a vehicle: the linear critical speed and
// its Hopf criticality, then the branch of hunting orbits (shooting +
// pseudo-arclength continuation, orbit_continuation.hpp) from the Hopf point
// and, independently, from a hunting cycle found by a time-domain run at a
// given speed. The nonlinear critical speed is the lowest speed with a stable
// hunting orbit on either branch (its fold).
//
// Profile contact (tabulated wheel-rail geometry, C1 between table points):
// the first Lyapunov coefficient would be the third derivative of the
// table's interpolation, so it is not computed; the branch from the Hopf
// point then starts from the eigenvector alone (V guessed at V_c, corrected
// at fixed excursion) and its first two orbits say on which side of V_c the
// small cycles lie (the Hopf kind as the continuation finds it).
#include <railstab/nonlinear/hopf_criticality.hpp>
#include <railstab/nonlinear/model_orbits.hpp>
#include <railstab/nonlinear/orbit_continuation.hpp>
#include <railstab/stability/speed_analysis.hpp>

#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace railstab {

struct BifurcationOptions {
  CriticalSpeedOptions linear;            // the linear search's range and grid
  ContinuationOptions continuation;       // speed range and amplitude limit set from the run
  std::string wheelset;                   // whose lateral motion is the excursion ("": the first)
  double first_excursion_m = 5e-5;        // of the Hopf branch's first orbit
  double max_amplitude_m = 0.012;         // stop a branch beyond this lateral amplitude
  bool from_hopf = true;
  // > 0: also start a branch from the cycle a time-domain run settles on at
  // this speed, from the steady state with the wheelset displaced by
  // disturbance_m, after settle_time_s.
  double cycle_speed_m_per_s = 0.0;
  double disturbance_m = 0.005;
  double settle_time_s = 6.0;
  double cycle_speed_step_m_per_s = -0.5;  // the second orbit's speed offset (direction)
  std::function<void(const std::string&)> progress;
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
  // The lowest speed with a stable orbit on any branch; NaN when none.
  double nonlinear_critical_speed_m_per_s = std::numeric_limits<double>::quiet_NaN();
  std::vector<int> reduced_states;        // full-state index of every orbit state
  std::vector<std::string> state_names;   // of the reduced states
  OrbitCoordinates coords;
  double cpu_seconds = 0.0;
};

// `equilibrium` is the steady state at `speed_m_per_s` (the scene's).
BifurcationResult analyse_bifurcation(const Model& model, const Eigen::VectorXd& equilibrium,
                                      double speed_m_per_s, const BifurcationOptions& options);

}  // namespace railstab
