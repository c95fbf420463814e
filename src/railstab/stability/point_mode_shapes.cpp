#include <railstab/stability/point_mode_shapes.hpp>

namespace railstab {

std::vector<ModeShape> full_mode_shapes(const Model& model, const StabilityPoint& p) {
  const Eigen::MatrixXd K =
      suspension_stiffness(model, p.speed_m_per_s, p.time_s, p.equilibrium.state);
  std::vector<ModeShape> shapes;
  shapes.reserve(p.modes.size());
  for (const ModeReport& m : p.modes)
    shapes.push_back(mode_shape(model, p.linear, K, m.eigenvalue, m.vector));
  return shapes;
}

}  // namespace railstab
