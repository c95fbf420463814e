#include <railstab/stability/mode_start.hpp>

#include <railstab/stability/speed_analysis.hpp>

#include <railstab/model/leading_wheelset.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace railstab {

namespace {

// A mode whose leading-wheelset lateral entry is below this share of its
// largest lateral entry does not move that wheelset: scaling it to M would
// blow the rest of the vehicle up by the inverse of the share.
constexpr double kMinimumLeadingShare = 1e-3;

}  // namespace

ModeStart mode_start_state(const Model& model, double speed_m_per_s,
                           const Eigen::VectorXd& equilibrium_guess, const std::string& selector,
                           double amplitude_m) {
  StabilityOptions options;
  options.max_frequency_hz = kModeStartBandHz;
  SpeedStability stability(model, equilibrium_guess, speed_m_per_s, options);
  const StabilityPoint point = stability.at(speed_m_per_s);
  int chosen = -1;
  if (selector == kHuntingModeSelector) {
    chosen = least_stable_lateral_mode(point.modes, kModeStartBandHz);
    if (chosen < 0)
      throw std::invalid_argument("--mode hunting: no oscillatory lateral mode at or below " +
                                  std::to_string(kModeStartBandHz) + " Hz at " +
                                  std::to_string(speed_m_per_s) + " m/s");
  } else {
    for (size_t i = 0; i < point.modes.size() && chosen < 0; ++i)
      if (point.modes[i].name == selector && point.modes[i].eigenvalue.imag() >= 0.0) chosen = int(i);
    if (chosen < 0) {
      std::ostringstream msg;
      msg << "--mode '" << selector << "': no mode of that name at " << speed_m_per_s
          << " m/s; expected 'hunting' or one of:";
      std::string last;
      for (const ModeReport& m : point.modes)
        if (m.name != last && m.eigenvalue.imag() >= 0.0) msg << " '" << m.name << "'", last = m.name;
      throw std::invalid_argument(msg.str());
    }
  }
  const ModeReport& mode = point.modes[size_t(chosen)];
  const int lead = leading_wheelset(model);
  if (lead < 0) throw std::invalid_argument("--mode: the model has no wheelset");
  const int lead_y = model.bodies[size_t(lead)].state_index[int(CoordinateIndex::y)];
  Eigen::Index s = -1;
  double largest_lateral = 0.0;
  for (size_t i = 0; i < point.linear.kept_states.size(); ++i) {
    const int k = point.linear.kept_states[i];
    if (k == lead_y) s = Eigen::Index(i);
    if (model.is_position(k) && model.coordinate_of_state[size_t(k)].second == int(CoordinateIndex::y))
      largest_lateral = std::max(largest_lateral, std::abs(mode.vector(Eigen::Index(i))));
  }
  const std::string lead_name = model.bodies[size_t(lead)].name;
  if (s < 0)
    throw std::invalid_argument("--mode: the leading wheelset " + lead_name +
                                " has no free lateral shift to scale the mode by");
  const std::complex<double> v_lead = mode.vector(s);
  if (!(std::abs(v_lead) > kMinimumLeadingShare * largest_lateral)) {
    std::ostringstream msg;
    msg << "--mode '" << selector << "': mode '" << mode.name << "' moves the leading wheelset "
        << lead_name << " laterally by " << std::abs(v_lead) / largest_lateral
        << " of its largest lateral motion (below " << kMinimumLeadingShare
        << "), so --mode-amplitude cannot be its lateral shift; choose a mode that moves it";
    throw std::invalid_argument(msg.str());
  }
  // c = M conj(v_L) / |v_L|^2: c v_L = M, real and positive.
  const std::complex<double> c = amplitude_m * std::conj(v_lead) / std::norm(v_lead);
  ModeStart out;
  out.state = point.equilibrium.state;
  for (size_t i = 0; i < point.linear.kept_states.size(); ++i)
    out.state(point.linear.kept_states[i]) += (c * mode.vector(Eigen::Index(i))).real();
  out.mode_name = mode.name;
  out.eigenvalue = mode.eigenvalue;
  out.leading_wheelset = lead_name;
  out.amplitude_m = amplitude_m;
  return out;
}

std::string mode_start_description(const ModeStart& start) {
  std::ostringstream text;
  text << "mode '" << start.mode_name << "', " << start.leading_wheelset << " lateral "
       << start.amplitude_m << " m";
  return text.str();
}

}  // namespace railstab
