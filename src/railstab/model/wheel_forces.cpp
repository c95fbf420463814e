#include <railstab/model/wheel_forces.hpp>

#include <railstab/contact_geometry/profile_contact_geometry.hpp>
#include <railstab/model/equations_of_motion.hpp>
#include <railstab/model/workspace.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <type_traits>
#include <variant>

namespace railstab {

namespace {

// The friction coefficient of a creep law, where it has one.
std::optional<double> friction_coefficient_of(const CreepLawTpl<double>& law) {
  return std::visit(
      [](const auto& l) -> std::optional<double> {
        if constexpr (requires { l.friction_coefficient; })
          return double(l.friction_coefficient);
        else
          return std::nullopt;
      },
      law);
}

}  // namespace

std::string WheelForces::name(const Model& model) const {
  return model.bodies[size_t(body)].name + (side > 0 ? " left wheel" : " right wheel");
}

std::vector<WheelForces> wheel_forces(const Model& model, double speed_m_per_s, double t_s,
                                      const Eigen::VectorXd& x) {
  // One evaluation gives the contacts and leaves every body's motion (its
  // frame rotations) in the workspace.
  EvaluationDetails details;
  Workspace<double> ws(model);
  Eigen::VectorXd xdot;
  evaluate_rhs<double>(model, ws, t_s, speed_m_per_s, x, xdot, &details);
  std::vector<WheelForces> wheels;
  auto wheel_of = [&](int body, int side) -> WheelForces& {
    for (WheelForces& w : wheels)
      if (w.body == body && w.side == side) return w;
    WheelForces w;
    w.body = body;
    w.side = side;
    const ModelContact& contact =
        model.contacts[size_t(model.bodies[size_t(body)].wheelset()->contact)];
    if (uses_contact_table(contact.spec.geometry) && contact.spec.profile_geometry) {
      w.flange_angle_rad = contact.spec.profile_geometry->flange_angle_rad;
      w.nadal_friction_coefficient =
          friction_coefficient_of(contact.creep_law).value_or(kNadalDefaultFrictionCoefficient);
      w.nadal_limit = nadal_limit(w.flange_angle_rad, w.nadal_friction_coefficient);
    }
    wheels.push_back(w);
    return wheels.back();
  };
  for (const ContactSnapshot& c : details.contacts) {
    WheelForces& w = wheel_of(c.body, c.wheel.side);
    // The rail's force on the wheel, from the wheelset's frame I into its
    // track frame T; the wheel's on the rail is its opposite.
    const Eigen::Vector3d on_wheel_T = ws.motions[size_t(c.body)].R_TI * c.wheel.force_I;
    w.Q_N += on_wheel_T.z();
    w.Y_N += -double(c.wheel.side) * on_wheel_T.y();
    if (c.wheel.normal_force_N > 0.0)
      w.max_contact_angle_rad = std::max(w.max_contact_angle_rad, std::abs(c.wheel.contact_angle_rad));
  }
  for (WheelForces& w : wheels)
    if (w.Q_N > 0.0) w.y_over_q = w.Y_N / w.Q_N;
  return wheels;
}

std::optional<WheelForces> wheel_beyond_nadal_limit(const std::vector<WheelForces>& wheels) {
  std::optional<WheelForces> worst;
  double worst_excess = 1.0;
  for (const WheelForces& w : wheels) {
    if (!w.y_over_q || !w.nadal_limit || !(*w.nadal_limit > 0.0)) continue;
    const double excess = *w.y_over_q / *w.nadal_limit;
    if (excess > worst_excess) {
      worst_excess = excess;
      worst = w;
    }
  }
  return worst;
}

std::string nadal_warning(const Model& model, const WheelForces& w) {
  std::ostringstream s;
  s.precision(3);
  s << w.name(model) << " Y/Q " << w.y_over_q.value_or(0.0) << " exceeds Nadal's limit "
    << w.nadal_limit.value_or(0.0) << " (flange angle " << w.flange_angle_rad * 180.0 / M_PI
    << " deg, mu " << w.nadal_friction_coefficient << "; Y " << w.Y_N << " N, Q " << w.Q_N
    << " N): flange climbing, derailment risk";
  return s.str();
}

}  // namespace railstab
