#include "stability/modes.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace railstab {

std::string coordinate_word(int coordinate) {
  static const char* words[6] = {"longitudinal", "lateral", "vertical", "roll", "pitch", "yaw"};
  return words[coordinate];
}

double neutral_threshold(const Eigen::MatrixXd& A) {
  return 1e-9 * std::max(1.0, A.norm());
}

std::vector<ModeReport> describe_modes(const Model& model, const LinearModel& lin,
                                       const std::vector<EigenPair>& pairs) {
  const double zero = neutral_threshold(lin.A);
  const int n = model.n_coordinates;
  std::vector<ModeReport> modes;
  modes.reserve(pairs.size());
  for (const EigenPair& p : pairs) {
    ModeReport m;
    m.eigenvalue = p.value;
    const ModeInfo info = mode_info(p.value);
    m.frequency_hz = info.frequency_hz;
    m.damping_ratio = info.damping_ratio;
    m.residual = p.residual;
    m.neutral = std::abs(p.value) <= zero;
    m.vector = p.vector;
    // Kinetic energy per (body, coordinate) from the rate part of the vector.
    double total = 0.0;
    std::vector<Participation> parts;
    for (size_t i = 0; i < lin.kept_states.size(); ++i) {
      const int k = lin.kept_states[i];
      if (!model.is_rate(k)) continue;  // positions and element states carry no kinetic energy
      const auto [b, c] = model.coordinate_of_state[k - n];
      const Body& body = model.bodies[b];
      const double inertia = c < 3 ? body.mass_kg : body.inertia_kg_m2(c - 3);
      const double e = inertia * std::norm(p.vector(Eigen::Index(i)));
      total += e;
      if (c == 1 || c == 3 || c == 5) m.lateral_share += e;
      parts.push_back({body.name, c, e});
    }
    if (total > 0.0) {
      for (Participation& q : parts) q.share /= total;
      m.lateral_share /= total;
    }
    std::sort(parts.begin(), parts.end(),
              [](const Participation& a, const Participation& b) { return a.share > b.share; });
    if (parts.size() > 6) parts.resize(6);
    m.participation = parts;
    if (m.neutral) {
      m.name = "neutral (rigid-body/cyclic)";
    } else if (!parts.empty()) {
      // The dominant body, with each of its coordinates holding at least a
      // quarter of the dominant share.
      m.name = parts[0].body + " " + coordinate_word(parts[0].coordinate);
      for (size_t j = 1; j < parts.size(); ++j)
        if (parts[j].body == parts[0].body && parts[j].share >= 0.25 * parts[0].share)
          m.name += "/" + coordinate_word(parts[j].coordinate);
    }
    modes.push_back(std::move(m));
  }
  return modes;
}

namespace {

// Largest real part among the eligible non-neutral modes at or below the
// frequency cap; among equal real parts the oscillatory one.
template <class Eligible>
int least_stable_where(const std::vector<ModeReport>& modes, double max_frequency_hz,
                       Eligible eligible) {
  int best = -1;
  for (int i = 0; i < int(modes.size()); ++i) {
    const ModeReport& m = modes[size_t(i)];
    if (m.neutral || m.frequency_hz > max_frequency_hz || !eligible(m)) continue;
    if (best < 0) {
      best = i;
      continue;
    }
    const double a = m.eigenvalue.real(), b = modes[size_t(best)].eigenvalue.real();
    if (a > b || (a == b && m.eigenvalue.imag() > modes[size_t(best)].eigenvalue.imag())) best = i;
  }
  return best;
}

}  // namespace

int least_stable_mode(const std::vector<ModeReport>& modes, double max_frequency_hz) {
  return least_stable_where(modes, max_frequency_hz, [](const ModeReport&) { return true; });
}

int least_stable_lateral_mode(const std::vector<ModeReport>& modes, double max_frequency_hz,
                              double min_lateral_share) {
  return least_stable_where(modes, max_frequency_hz, [&](const ModeReport& m) {
    return m.frequency_hz > 0.0 && m.lateral_share >= min_lateral_share;
  });
}

}  // namespace railstab
