#include <railstab/stability/mode_names.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

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

}  // namespace

std::string mode_name_from_shape(const Model& model, const BodyRoles& roles, const ModeShape& shape,
                                 std::complex<double> lambda) {
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
    // Units by energy.
    std::map<int, double> unit_energy;
    for (size_t b = 0; b < nb; ++b)
      if (roles.unit[b] >= 0) unit_energy[roles.unit[b]] += body_energy(b);
    std::vector<std::pair<double, int>> units;
    for (const auto& [u, en] : unit_energy) units.push_back({en, u});
    std::sort(units.rbegin(), units.rend());
    auto motion_word = [&](bool on_wheelset) -> std::string {
      switch (m) {
        case hunting_motion: return oscillatory ? "hunting" : "lateral/yaw";
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
      name = kind + " " + motion_word(!frames) + ", " + kind + "s ";
      size_t sharing = 0;
      for (const auto& un : units)
        if (un.first >= 0.1 * gear) ++sharing;
      if (sharing > 2) {
        name += "coupled";
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
        name += (std::conj(q[a][size_t(c)]) * q[b][size_t(c)]).real() >= 0.0 ? "in phase"
                                                                           : "anti-phase";
      }
    }
  }
  if (!oscillatory) name += ", aperiodic";
  return name;
}

void make_names_unique(std::vector<std::string>& names, const std::vector<int>& copies_of,
                       const std::vector<double>& order_key) {
  std::vector<size_t> order(names.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  if (order_key.size() == names.size())
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t a, size_t b) { return order_key[a] < order_key[b]; });
  std::map<std::string, int> seen;
  for (size_t i : order) {
    if (i < copies_of.size() && copies_of[i] >= 0) continue;
    const int k = ++seen[names[i]];
    if (k > 1) names[i] += " (" + std::to_string(k) + ")";
  }
  for (size_t i = 0; i < names.size() && i < copies_of.size(); ++i)
    if (copies_of[i] >= 0) names[i] = names[size_t(copies_of[i])];
}

}  // namespace railstab
