#include <railstab/equilibrium/speed_continuation.hpp>

#include <railstab/core/coordinates.hpp>

#include <algorithm>
#include <cmath>

namespace railstab {

Eigen::VectorXd rescaled_to_speed(const Model& model, const Eigen::VectorXd& x,
                                  double from_m_per_s, double to_m_per_s) {
  Eigen::VectorXd guess = x;
  if (!(from_m_per_s > 0.0)) return guess;
  const int n = model.n_coordinates;
  for (int k = 0; k < n; ++k) {
    const auto [b, c] = model.coordinate_of_state[size_t(k)];
    if (model.bodies[size_t(b)].wheelset() && c == int(CoordinateIndex::pitch))
      guess(n + k) *= to_m_per_s / from_m_per_s;
  }
  return guess;
}

EquilibriumResult continue_equilibrium_in_speed(const Model& model, double from_m_per_s,
                                                const Eigen::VectorXd& state, double to_m_per_s,
                                                EquilibriumOptions options, int max_halvings) {
  options.pseudo_transient_fallback = false;
  const double smallest = std::min(kSmallestSpeedStep_m_per_s,
                                   std::ldexp(std::abs(to_m_per_s - from_m_per_s), -max_halvings));
  double from = from_m_per_s;
  Eigen::VectorXd x = state;
  double step = to_m_per_s - from;
  for (;;) {
    const bool last = std::abs(to_m_per_s - from) <= std::abs(step);
    const double next = last ? to_m_per_s : from + step;
    try {
      EquilibriumResult r = solve_equilibrium(model, next, rescaled_to_speed(model, x, from, next), options);
      if (last) return r;
      x = r.state;
      from = next;
      step *= 2.0;  // back up towards the whole step once past the hard part
    } catch (const EquilibriumError&) {
      if (std::abs(step) * 0.5 < smallest * (1.0 - 1e-12)) throw;
      step *= 0.5;
    }
  }
}

}  // namespace railstab
