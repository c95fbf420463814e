#include <railstab/check/run_check.hpp>

#include <railstab/contact_geometry/characteristic_functions.hpp>
#include <railstab/contact_geometry/profile_contact_geometry.hpp>

#include <cmath>
#include <sstream>

namespace railstab {

std::vector<ModelWarning> check_run(const Model& model, const Trajectory& trajectory,
                                    const RunCheckLimits& limits) {
  std::vector<ModelWarning> warnings;
  const std::vector<double>& t = trajectory.times_s;
  if (t.size() < 2) return warnings;
  const double from_s = t.back() - limits.flanging_final_fraction * (t.back() - t.front());
  for (const Body& body : model.bodies) {
    if (!body.wheelset()) continue;
    const int k = body.state_index[int(CoordinateIndex::y)];
    const ContactSpec& contact = model.contacts[size_t(body.wheelset()->contact)].spec;
    if (k < 0 || !uses_contact_table(contact.geometry) || !contact.profile_geometry) continue;
    // A table read from a file states its flange contact shift (its pair has
    // no profiles to find it from).
    const ProfileContactGeometry& g = *contact.profile_geometry;
    double y_f = 0.0;
    if (g.has_profiles()) {
      const FlangeContact flange = find_flange_contact(g.pair);
      if (!flange.found) continue;
      y_f = flange.lateral_shift_m;
    } else {
      if (!g.flange_contact_shift_m) continue;
      y_f = *g.flange_contact_shift_m;
    }
    bool beyond = true;
    for (size_t i = 0; i < t.size() && beyond; ++i)
      if (t[i] >= from_s) beyond = std::abs(trajectory.states[i](k)) >= y_f;
    if (!beyond) continue;
    std::ostringstream msg;
    msg << body.name << ": in flange contact (abs(lateral shift) >= " << y_f * 1e3
        << " mm, the flange-contact shift of contacts." << contact.name << ") through the last "
        << t.back() - from_s << " s of the run, " << trajectory.states.back()(k) * 1e3
        << " mm at t = " << t.back()
        << " s: steady flanging (a curve too tight or a cant deficiency too large for the "
           "speed?)";
    warnings.push_back({"flanging_to_the_end", body.name, msg.str()});
  }
  return warnings;
}

}  // namespace railstab
