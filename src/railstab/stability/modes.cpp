#include <railstab/stability/modes.hpp>

#include <railstab/stability/mode_names.hpp>

#include <algorithm>
#include <cmath>
#include <map>

namespace railstab {

std::string coordinate_word(int coordinate) {
  static const char* words[6] = {"longitudinal", "lateral", "vertical", "roll", "pitch", "yaw"};
  return words[coordinate];
}

namespace {

// A mode in which no body moves (every kinetic share 0: no free body
// coordinate, or one held away from the element): only elements' internal
// states take part, e.g. a series damper relaxing between held bodies
// (lambda = -k_s / c). Named after its largest internal state; the body
// names of mode_name_from_shape would describe a motion that is not there.
bool moves_no_body(const ModeShape& shape) {
  return std::all_of(shape.coordinates.begin(), shape.coordinates.end(),
                     [](const CoordinateMotion& c) { return c.kinetic_share == 0.0; });
}

std::string internal_state_mode_name(const Model& model, const LinearModel& lin,
                                     const Eigen::VectorXcd& vector) {
  int best = -1;
  for (int j = 0; j < int(lin.kept_states.size()) && j < int(vector.size()); ++j) {
    const int state = lin.kept_states[size_t(j)];
    if (!model.is_internal(state)) continue;
    if (best < 0 || std::abs(vector(j)) > std::abs(vector(best))) best = j;
  }
  if (best < 0) return "no body motion";
  return model.state_name(lin.kept_states[size_t(best)]) + " (internal state, no body motion)";
}

}  // namespace

std::vector<int> conjugate_partners(const std::vector<ModeReport>& modes) {
  std::vector<int> partner(modes.size(), -1);
  for (size_t i = 0; i < modes.size(); ++i) {
    if (modes[i].eigenvalue.imag() >= 0.0) continue;
    // A real matrix has exact conjugate pairs; the solvers return them to
    // round-off. ARPACK may return one of a pair only: then there is none.
    double best = 1e-8 * std::max(1.0, std::abs(modes[i].eigenvalue));
    for (size_t j = 0; j < modes.size(); ++j) {
      if (modes[j].eigenvalue.imag() <= 0.0) continue;
      const std::complex<double> diff = modes[j].eigenvalue - std::conj(modes[i].eigenvalue);
      // |diff| >= max(|Re|, |Im|) (hypot rounds to at least the larger
      // component): most candidates are ruled out without the modulus.
      if (std::max(std::abs(diff.real()), std::abs(diff.imag())) > best) continue;
      const double d = std::abs(diff);
      if (d <= best) {
        best = d;
        partner[i] = int(j);
      }
    }
  }
  return partner;
}

std::vector<ModeShape> describe_mode_shapes(const Model& model, const LinearModel& lin,
                                            const std::vector<EigenPair>& pairs) {
  const ModeShapeBasis basis = mode_shape_basis(model, lin);
  std::vector<ModeShape> shapes;
  shapes.reserve(pairs.size());
  for (size_t i = 0; i < pairs.size(); ++i) {
    const EigenPair& p = pairs[i];
    // The exact conjugate of the pair before (eigen_dense returns a complex
    // pair's partner so): its shape is that pair's with the displacements
    // conjugated. Every step of mode_shape maps conjugate input to
    // conjugate output exactly (moduli and kinetic shares are the same, the
    // reference coordinate too; complex products and quotients, with or
    // without fused multiply-add, negate only their imaginary part), so
    // this is what mode_shape would return, bit for bit
    // (tests/stability/test_mode_shapes.cpp), at no cost.
    if (i > 0 && p.value.imag() != 0.0 && p.value == std::conj(pairs[i - 1].value) &&
        p.vector == pairs[i - 1].vector.conjugate()) {
      shapes.push_back(shapes.back());
      for (CoordinateMotion& c : shapes.back().coordinates) c.displacement = std::conj(c.displacement);
    } else {
      shapes.push_back(mode_shape(model, lin, basis, Eigen::MatrixXd(), p.value, p.vector));
    }
  }
  return shapes;
}

std::vector<ModeReport> describe_modes(const Model& model, const LinearModel& lin,
                                       const std::vector<EigenPair>& pairs, double speed_m_per_s) {
  // linearize() sets norm_A (dense or sparse A); a hand-made LinearModel may not.
  const double zero = 1e-9 * std::max(1.0, lin.norm_A > 0.0 ? lin.norm_A : lin.A.norm());
  const BodyRoles roles = body_roles(model);
  const std::vector<ModeShape> shapes = describe_mode_shapes(model, lin, pairs);
  std::vector<ModeReport> modes;
  modes.reserve(pairs.size());
  for (size_t i = 0; i < pairs.size(); ++i) {
    const EigenPair& p = pairs[i];
    ModeReport m;
    m.eigenvalue = p.value;
    const ModeInfo info = mode_info(p.value);
    m.frequency_hz = info.frequency_hz;
    m.damping_ratio = info.damping_ratio;
    m.residual = p.residual;
    m.neutral = std::abs(p.value) <= zero;
    m.vector = p.vector;
    const std::vector<CoordinateMotion>& coords = shapes[i].coordinates;
    std::vector<int> order(coords.size());
    for (size_t k = 0; k < coords.size(); ++k) {
      if (coords[k].coordinate == 1 || coords[k].coordinate == 3 || coords[k].coordinate == 5)
        m.lateral_share += coords[k].kinetic_share;
      order[k] = int(k);
    }
    // The six largest shares, ties in coordinate order (the body names are
    // copied for those six only): a partial sort by (share descending,
    // index ascending) picks exactly what a stable sort would put first.
    const size_t top = std::min<size_t>(6, order.size());
    std::partial_sort(order.begin(), order.begin() + std::ptrdiff_t(top), order.end(),
                      [&](int a, int b) {
                        const double sa = coords[size_t(a)].kinetic_share;
                        const double sb = coords[size_t(b)].kinetic_share;
                        return sa > sb || (sa == sb && a < b);
                      });
    order.resize(top);
    for (int k : order) {
      const CoordinateMotion& c = coords[size_t(k)];
      m.participation.push_back({model.bodies[size_t(c.body)].name, c.coordinate, c.kinetic_share});
    }
    m.shape_name = m.neutral               ? "neutral (rigid-body/cyclic)"
                   : moves_no_body(shapes[i]) ? internal_state_mode_name(model, lin, p.vector)
                                              : mode_name_from_shape(model, roles, shapes[i], p.value,
                                                                     speed_m_per_s);
    m.dominant_body = dominant_body(model, shapes[i]);
    modes.push_back(std::move(m));
  }
  std::vector<std::string> names;
  std::vector<double> damping;
  std::vector<std::vector<std::string>> qualifiers;
  for (const ModeReport& m : modes) {
    names.push_back(m.shape_name);
    damping.push_back(m.damping_ratio);
    qualifiers.push_back(mode_qualifiers(m.dominant_body, m.eigenvalue));
  }
  make_names_unique(names, conjugate_partners(modes), damping, qualifiers);
  for (size_t i = 0; i < modes.size(); ++i) modes[i].name = names[i];
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

int least_damped_mode(const std::vector<ModeReport>& modes, double max_frequency_hz,
                      double min_lateral_share) {
  int best = -1;
  for (int i = 0; i < int(modes.size()); ++i) {
    const ModeReport& m = modes[size_t(i)];
    if (m.neutral || m.frequency_hz > max_frequency_hz || m.eigenvalue.imag() < 0.0 ||
        m.lateral_share < min_lateral_share)
      continue;
    if (best < 0) {
      best = i;
      continue;
    }
    const ModeReport& b = modes[size_t(best)];
    if (m.damping_ratio < b.damping_ratio ||
        (m.damping_ratio == b.damping_ratio && m.eigenvalue.real() > b.eigenvalue.real()))
      best = i;
  }
  return best;
}

int least_stable_lateral_mode(const std::vector<ModeReport>& modes, double max_frequency_hz,
                              double min_lateral_share) {
  return least_stable_where(modes, max_frequency_hz, [&](const ModeReport& m) {
    return m.frequency_hz > 0.0 && m.lateral_share >= min_lateral_share;
  });
}

std::string shape_here_if_different(const ModeReport& m) {
  if (m.shape_name.empty() || m.name.rfind(m.shape_name, 0) == 0) return "";
  return m.shape_name;
}

std::string mode_label_here(const ModeReport& m) {
  const std::string here = shape_here_if_different(m);
  return here.empty() ? m.name : m.name + " (its shape here: " + here + ")";
}

}  // namespace railstab
