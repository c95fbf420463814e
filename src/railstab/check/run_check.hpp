#pragma once
// Plausibility of a time-domain run (`simulate`): a wheelset that stays in
// flange contact to the end of the run. On real profiles flange contact is
// modelled and a run goes on through it; a wheelset beyond its flange-contact
// shift for the whole last part of the run is steady flanging, i.e. a curve
// too tight or a cant deficiency too large for the speed, which the run's
// numbers do not say by themselves. (Flangeless contacts stop the run at
// their flange_clearance_m instead: Trajectory::stopped_early.)
#include <railstab/check/model_check.hpp>
#include <railstab/integrate/integrator.hpp>

#include <vector>

namespace railstab {

struct RunCheckLimits {
  // The last part of the run (fraction of the simulated time) through which
  // a wheelset must stay beyond its flange-contact shift to be reported:
  // a quarter excludes the transients of a run's start and of a curve entry
  // that pass, and keeps a run that settles on the flange.
  double flanging_final_fraction = 0.25;
};

// Warnings (kind "flanging_to_the_end") for every profile-contact wheelset
// whose lateral shift abs(y) is at least the pair's flange-contact shift
// (find_flange_contact: where the rigid contact jumps to the flange) at
// every output of the last `flanging_final_fraction` of the run.
std::vector<ModelWarning> check_run(const Model& model, const Trajectory& trajectory,
                                    const RunCheckLimits& limits = {});

}  // namespace railstab
