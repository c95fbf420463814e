#include <railstab/stability/mode_names.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <sstream>

namespace railstab {

BodyRoles body_roles(const Model& model) {
  const size_t nb = model.bodies.size();
  BodyRoles r;
  r.role.assign(nb, BodyRole::car_body);
  r.unit.assign(nb, -1);
  for (size_t b = 0; b < nb; ++b)
    if (model.bodies[b].wheelset()) r.role[b] = BodyRole::wheelset;
  // Frames: rigid bodies joined to a wheelset; the wheelset's unit is the
  // first frame it is joined to.
  for (const ElementTpl<double>& e : model.elements) {
    const ElementEnds& ends = ends_of(e);
    if (ends.body1 == kTrackBody) continue;
    for (const auto& [w, f] : {std::pair{ends.body1, ends.body2}, std::pair{ends.body2, ends.body1}}) {
      if (r.role[size_t(w)] != BodyRole::wheelset || model.bodies[size_t(f)].wheelset()) continue;
      r.role[size_t(f)] = BodyRole::bogie_frame;
      if (r.unit[size_t(w)] < 0) r.unit[size_t(w)] = f;
    }
  }
  for (size_t b = 0; b < nb; ++b) {
    if (r.role[b] == BodyRole::bogie_frame) r.unit[b] = int(b);
    if (r.role[b] == BodyRole::wheelset && r.unit[b] < 0) r.unit[b] = int(b);
    if (r.role[b] == BodyRole::car_body) ++r.n_car_bodies;
  }
  return r;
}

namespace {

// Running-gear motions (rule 3), in the order used for ties.
enum Motion { hunting_motion, roll_motion, vertical_motion, pitch_motion, spin_motion, longitudinal_motion, n_motions };

Motion gear_motion(BodyRole role, int coordinate) {
  switch (coordinate) {
    case 0: return longitudinal_motion;
    case 1: case 5: return hunting_motion;
    case 2: return vertical_motion;
    case 3: return roll_motion;
    default: return role == BodyRole::wheelset ? spin_motion : pitch_motion;
  }
}

std::string car_body_motion(const std::array<double, 6>& e, std::complex<double> y,
                            std::complex<double> roll) {
  const double lon = e[0], vert = e[2] + e[4], lat = e[1] + e[3] + e[5];
  if (lon > vert && lon > lat) return "longitudinal";
  if (vert >= lat) return e[2] >= e[4] ? "bounce" : "pitch";
  if (e[5] >= e[1] + e[3]) return "yaw";
  if (e[1] < 0.1 * (e[1] + e[3]) || std::abs(roll) == 0.0) return e[1] > e[3] ? "lateral" : "roll";
  const double roll_centre_height = (y / roll).real();
  return roll_centre_height > 0.0 ? "lower sway" : "upper sway";
}

// Kinematic hunting (rule 3): psi / y = i omega / V on the wheelset with the
// most lateral + yaw energy, within the phase and ratio tolerances. z is
// psi / y over i omega / V, so z = 1 exactly for a rolling wheelset; the sign
// of omega is kept, so a conjugate shape (Im lambda < 0) judges the same.
bool kinematic_hunting(const BodyRoles& roles, const std::vector<std::array<double, 6>>& e,
                       const std::vector<std::array<std::complex<double>, 6>>& q,
                       std::complex<double> lambda, double speed_m_per_s) {
  if (!(speed_m_per_s > 0.0) || lambda.imag() == 0.0) return false;
  int w = -1;
  for (size_t b = 0; b < e.size(); ++b)
    if (roles.role[b] == BodyRole::wheelset &&
        (w < 0 || e[b][1] + e[b][5] > e[size_t(w)][1] + e[size_t(w)][5]))
      w = int(b);
  if (w < 0) return false;
  const std::complex<double> y = q[size_t(w)][1], psi = q[size_t(w)][5];
  if (std::abs(y) == 0.0 || std::abs(psi) == 0.0) return false;
  const std::complex<double> z =
      (psi / y) / std::complex<double>(0.0, lambda.imag() / speed_m_per_s);
  const double phase_deg = std::abs(std::arg(z)) * 180.0 / M_PI;
  return phase_deg <= kKinematicPhaseToleranceDeg && std::abs(z) >= 1.0 / kKinematicRatioFactor &&
         std::abs(z) <= kKinematicRatioFactor;
}

// The phase words of two units (rule 3): a first in scene order.
std::string phase_words(const Model& model, size_t a, size_t b, std::complex<double> qa,
                        std::complex<double> qb, std::complex<double> lambda,
                        const std::string& plural) {
  if (a > b) {
    std::swap(a, b);
    std::swap(qa, qb);
  }
  double theta = std::arg(std::conj(qa) * qb) * 180.0 / M_PI;
  if (lambda.imag() < 0.0) theta = -theta;  // the conjugate shape: the same motion
  if (std::abs(theta) <= kPhaseToleranceDeg) return plural + " in phase";
  if (std::abs(theta) >= 180.0 - kPhaseToleranceDeg) return plural + " anti-phase";
  const int rounded = int(std::lround(std::abs(theta) / 10.0)) * 10;
  return model.bodies[b].name + " " + std::to_string(rounded) + " deg " +
         (theta < 0.0 ? "behind " : "ahead of ") + model.bodies[a].name;
}

}  // namespace

std::string dominant_body(const Model& model, const ModeShape& shape) {
  std::vector<double> energy(model.bodies.size(), 0.0);
  for (const CoordinateMotion& c : shape.coordinates) energy[size_t(c.body)] += c.kinetic_share;
  if (energy.empty()) return "";
  const size_t best = size_t(std::max_element(energy.begin(), energy.end()) - energy.begin());
  return energy[best] > 0.0 ? model.bodies[best].name : "";
}

std::vector<std::string> mode_qualifiers(const std::string& body, std::complex<double> lambda) {
  std::vector<std::string> q;
  if (!body.empty()) q.push_back("mostly " + body);
  std::ostringstream f;
  f.precision(3);
  if (lambda.imag() != 0.0)
    f << std::abs(lambda.imag()) / (2.0 * M_PI) << " Hz";
  else
    f << "rate " << lambda.real() << " 1/s";
  q.push_back(f.str());
  return q;
}

std::string mode_name_from_shape(const Model& model, const BodyRoles& roles, const ModeShape& shape,
                                 std::complex<double> lambda, double speed_m_per_s) {
  const size_t nb = model.bodies.size();
  std::vector<std::array<double, 6>> e(nb, std::array<double, 6>{});
  std::vector<std::array<std::complex<double>, 6>> q(nb, std::array<std::complex<double>, 6>{});
  for (const CoordinateMotion& c : shape.coordinates) {
    e[size_t(c.body)][size_t(c.coordinate)] = c.kinetic_share;
    q[size_t(c.body)][size_t(c.coordinate)] = c.displacement;
  }
  auto body_energy = [&](size_t b) {
    double s = 0.0;
    for (double v : e[b]) s += v;
    return s;
  };
  double car = 0.0, gear = 0.0;
  for (size_t b = 0; b < nb; ++b) (roles.role[b] == BodyRole::car_body ? car : gear) += body_energy(b);
  const bool oscillatory = lambda.imag() != 0.0;
  std::string name;
  if (car > gear) {
    size_t best = 0;
    double best_e = -1.0;
    for (size_t b = 0; b < nb; ++b)
      if (roles.role[b] == BodyRole::car_body && body_energy(b) > best_e) best_e = body_energy(best = b);
    const std::string who = roles.n_car_bodies == 1 ? "car body" : model.bodies[best].name;
    name = who + " " + car_body_motion(e[best], q[best][1], q[best][3]);
  } else {
    // The running gear's dominant motion.
    std::array<double, n_motions> motion{};
    for (size_t b = 0; b < nb; ++b)
      if (roles.role[b] != BodyRole::car_body)
        for (int c = 0; c < 6; ++c) motion[gear_motion(roles.role[b], c)] += e[b][size_t(c)];
    const Motion m = Motion(std::max_element(motion.begin(), motion.end()) - motion.begin());
    const bool kinematic = m == hunting_motion && kinematic_hunting(roles, e, q, lambda, speed_m_per_s);
    // Units by energy.
    std::map<int, double> unit_energy;
    for (size_t b = 0; b < nb; ++b)
      if (roles.unit[b] >= 0) unit_energy[roles.unit[b]] += body_energy(b);
    std::vector<std::pair<double, int>> units;
    for (const auto& [u, en] : unit_energy) units.push_back({en, u});
    std::sort(units.rbegin(), units.rend());
    auto motion_word = [&](bool on_wheelset) -> std::string {
      switch (m) {
        case hunting_motion: return kinematic ? "hunting" : "lateral/yaw";
        case roll_motion: return "roll";
        case vertical_motion: return on_wheelset ? "vertical" : "bounce";
        case pitch_motion: return "pitch";
        case spin_motion: return "spin";
        default: return "longitudinal";
      }
    };
    if (!units.empty() && units[0].first >= 0.75 * gear) {
      const int u = units[0].second;
      int subject = u;
      for (size_t b = 0; b < nb; ++b)
        if (roles.unit[b] == u && roles.role[b] == BodyRole::wheelset &&
            body_energy(b) >= 0.75 * units[0].first)
          subject = int(b);
      const bool frame = roles.role[size_t(subject)] == BodyRole::bogie_frame;
      // A bogie whose wheelsets move and whose frame hardly does.
      const bool wheelsets_of_frame = frame && body_energy(size_t(subject)) < 0.25 * units[0].first;
      name = model.bodies[size_t(subject)].name + (wheelsets_of_frame ? " wheelsets " : " ") +
             motion_word(!frame || wheelsets_of_frame);
    } else {
      // Shared by several units: their phase in the motion's main coordinate.
      const bool frames = roles.role[size_t(units[0].second)] == BodyRole::bogie_frame;
      const std::string kind = frames ? "bogie" : "wheelset";
      name = kind + " " + motion_word(!frames) + ", ";
      size_t sharing = 0;
      for (const auto& un : units)
        if (un.first >= 0.1 * gear) ++sharing;
      if (sharing > 2) {
        name += kind + "s coupled";
      } else {
        const size_t a = size_t(units[0].second), b = size_t(units[1].second);
        int c = 0;
        switch (m) {
          case hunting_motion: c = e[a][1] >= e[a][5] ? 1 : 5; break;
          case roll_motion: c = 3; break;
          case vertical_motion: c = 2; break;
          case longitudinal_motion: c = 0; break;
          default: c = 4; break;
        }
        name += phase_words(model, a, b, q[a][size_t(c)], q[b][size_t(c)], lambda, kind + "s");
      }
    }
  }
  if (!oscillatory) name += ", aperiodic";
  return name;
}

void make_names_unique(std::vector<std::string>& names, const std::vector<int>& copies_of,
                       const std::vector<double>& order_key,
                       const std::vector<std::vector<std::string>>& qualifiers) {
  const auto counted = [&](size_t i) { return !(i < copies_of.size() && copies_of[i] >= 0); };
  // Qualifiers, level by level, for the groups of equal names.
  if (qualifiers.size() == names.size()) {
    size_t levels = 0;
    for (const auto& q : qualifiers) levels = std::max(levels, q.size());
    std::map<std::string, std::vector<size_t>> groups;
    for (size_t i = 0; i < names.size(); ++i)
      if (counted(i)) groups[names[i]].push_back(i);
    for (const auto& [base, members] : groups) {
      if (members.size() < 2) continue;
      for (size_t level = 1; level <= levels; ++level) {
        std::map<std::string, int> count;
        std::vector<std::string> trial;
        for (size_t i : members) {
          std::string n = base;
          for (size_t k = 0; k < level && k < qualifiers[i].size(); ++k) n += ", " + qualifiers[i][k];
          trial.push_back(n);
          ++count[n];
        }
        const bool distinct = std::all_of(count.begin(), count.end(),
                                          [](const auto& c) { return c.second == 1; });
        if (distinct || level == levels) {
          for (size_t k = 0; k < members.size(); ++k) names[members[k]] = trial[k];
          break;
        }
      }
    }
  }
  std::vector<size_t> order(names.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  if (order_key.size() == names.size())
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t a, size_t b) { return order_key[a] < order_key[b]; });
  std::map<std::string, int> seen;
  for (size_t i : order) {
    if (!counted(i)) continue;
    const int k = ++seen[names[i]];
    if (k > 1) names[i] += " (" + std::to_string(k) + ")";
  }
  for (size_t i = 0; i < names.size() && i < copies_of.size(); ++i)
    if (copies_of[i] >= 0) names[i] = names[size_t(copies_of[i])];
}

}  // namespace railstab
