#include <railstab/stability/quasi_linear_critical_speed.hpp>

#include <railstab/stability/verdict.hpp>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace railstab {

QuasiLinearModelBuilder::QuasiLinearModelBuilder(const Model& model,
                                                 const Eigen::VectorXd& steady_state)
    : model_(model) {
  if (steady_state.size() != model.state_size())
    throw std::invalid_argument("QuasiLinearModelBuilder: steady state of size " +
                                std::to_string(steady_state.size()) + ", expected " +
                                std::to_string(model.state_size()));
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    const WheelsetKind* w = model.bodies[b].wheelset();
    if (!w) continue;
    const ModelContact& c = model.contacts[size_t(w->contact)];
    if (c.spec.geometry == ContactGeometryKind::table)
      throw std::invalid_argument(
          "contacts." + c.spec.name + ".geometry = \"table\": the quasi-linear critical speed "
          "(--amplitude, --amplitudes) linearises the rigid contact of the wheel and rail "
          "profiles, which a contact table file does not hold; run it on the scene with "
          "geometry = \"profiles\" that the table was written from");
    if (c.spec.geometry != ContactGeometryKind::profiles) continue;
    // y_c: the wheelset's lateral coordinate in its track frame (0 when
    // frozen: the nominal position).
    const int iy = model.bodies[b].state_index[1];
    wheelset_centres_.emplace_back(int(b), iy >= 0 ? steady_state(iy) : 0.0);
    const bool known = std::any_of(contacts_.begin(), contacts_.end(),
                                   [&](const ProfileContactOf& p) { return p.contact == w->contact; });
    if (!known)
      contacts_.push_back({w->contact, std::make_shared<QuasiLinearContact>(c.spec.profile_geometry)});
  }
}

double QuasiLinearModelBuilder::max_amplitude_m() const {
  double a = std::numeric_limits<double>::infinity();
  for (const auto& [b, yc] : wheelset_centres_) {
    const int contact = model_.bodies[size_t(b)].wheelset()->contact;
    for (const ProfileContactOf& p : contacts_)
      if (p.contact == contact) a = std::min(a, p.builder->half_range_m() - std::abs(yc));
  }
  return std::isfinite(a) ? std::max(a, 0.0) : 0.0;
}

double QuasiLinearModelBuilder::flange_contact_amplitude_m() const {
  double flange = std::numeric_limits<double>::infinity(), centre = 0;
  for (const ProfileContactOf& p : contacts_)
    if (p.builder->flange_contact_shift_m() > 0) flange = std::min(flange, p.builder->flange_contact_shift_m());
  for (const auto& [b, yc] : wheelset_centres_) centre = std::max(centre, std::abs(yc));
  return std::isfinite(flange) ? std::max(flange - centre, 0.0) : 0.0;
}

QuasiLinearModel QuasiLinearModelBuilder::at(double amplitude_m) const {
  QuasiLinearModel q{model_, amplitude_m, has_profile_contact(), {}};
  if (!(amplitude_m > 0.0) || !std::isfinite(amplitude_m) ||
      (has_profile_contact() && amplitude_m > max_amplitude_m())) {
    std::ostringstream msg;
    msg << "amplitude " << amplitude_m * 1e3 << " mm: expected 0 < amplitude";
    if (has_profile_contact())
      msg << " <= " << max_amplitude_m() * 1e3
          << " mm (the contact table's lateral range less 1 mm, less the steady shift)";
    throw std::invalid_argument(msg.str());
  }
  // Each profile wheelset gets its own contact (its own centre y_c): a copy
  // of its contact with the quasi-linear geometry, appended to the contacts.
  for (const auto& [b, yc] : wheelset_centres_) {
    Body& body = q.model.bodies[size_t(b)];
    WheelsetKind& w = std::get<WheelsetKind>(body.kind);
    const QuasiLinearContact* builder = nullptr;
    for (const ProfileContactOf& p : contacts_)
      if (p.contact == w.contact) builder = p.builder.get();
    ModelContact c = model_.contacts[size_t(w.contact)];
    c.spec.profile_geometry = builder->equivalent_geometry(yc, amplitude_m);
    const QuasiLinearGains g = builder->gains(yc, amplitude_m);
    w.contact = int(q.model.contacts.size());
    q.model.contacts.push_back(std::move(c));
    QuasiLinearWheelset r;
    r.body = body.name;
    r.centre_m = yc;
    r.equivalent_conicity = g.equivalent_conicity;
    r.rolling_radius_gain = g.gain[size_t(int(RigidFunction::rolling_radius_m))];
    r.contact_angle_gain_per_m = g.gain[size_t(int(RigidFunction::contact_angle_rad))];
    r.roll_gain_per_m = g.gain[size_t(int(RigidFunction::roll_theta_rad))];
    q.wheelsets.push_back(r);
  }
  return q;
}

QuasiLinearCriticalSpeed find_quasi_linear_critical_speed(const Model& model,
                                                          const Eigen::VectorXd& steady_state,
                                                          double speed_m_per_s, double amplitude_m,
                                                          const CriticalSpeedOptions& options) {
  const QuasiLinearModelBuilder builder(model, steady_state);
  const QuasiLinearModel q = builder.at(amplitude_m);
  QuasiLinearCriticalSpeed r;
  r.amplitude_m = amplitude_m;
  r.wheelsets = q.wheelsets;
  r.has_profile_contact = q.has_profile_contact;
  r.result = find_critical_speed(q.model, steady_state, speed_m_per_s, options);
  return r;
}

QuasiLinearCurve quasi_linear_critical_speed_curve(
    const QuasiLinearModelBuilder& builder, const Eigen::VectorXd& steady_state,
    double speed_m_per_s, const std::vector<double>& amplitudes_m,
    const CriticalSpeedOptions& options, const std::function<void(int, int, double)>& progress) {
  const std::clock_t cpu_start = std::clock();
  QuasiLinearCurve curve;
  curve.has_profile_contact = builder.has_profile_contact();
  curve.flange_contact_amplitude_m = builder.flange_contact_amplitude_m();
  CriticalSpeedOptions o = options;
  o.mode_shapes_at_critical = false;
  o.min_damping_ratio = 0.0;
  o.progress = nullptr;
  const int n = int(amplitudes_m.size());
  for (int i = 0; i < n; ++i) {
    const double A = amplitudes_m[size_t(i)];
    const QuasiLinearModel q = builder.at(A);
    const CriticalSpeedResult r = find_critical_speed(q.model, steady_state, speed_m_per_s, o);
    QuasiLinearCurvePoint p;
    p.amplitude_m = A;
    p.equivalent_conicity = q.wheelsets.empty() ? 0.0 : q.wheelsets.front().equivalent_conicity;
    p.critical_speed_found = r.critical_speed_found;
    p.stable_in_range = r.stable_in_range;
    p.unstable_at_start = r.unstable_at_start;
    if (r.critical_speed_found) {
      p.critical_speed_m_per_s = r.critical_speed_m_per_s;
      const StabilityPoint& c = r.at_critical;
      if (c.least_stable >= 0) {
        p.frequency_Hz = c.modes[size_t(c.least_stable)].frequency_hz;
        p.mode = c.modes[size_t(c.least_stable)].name;
      }
    }
    // No speed: the verdict's own words (stability/verdict.hpp), which also
    // tell "stable up to where the steady state was lost" from "stable over
    // the whole range".
    if (r.partial) p.note = r.partial_reason;
    else if (!r.critical_speed_found) p.note = verdict_sentence(r);
    curve.points.push_back(std::move(p));
    if (progress) progress(i + 1, n, A);
  }
  curve.cpu_seconds = double(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  return curve;
}

}  // namespace railstab
