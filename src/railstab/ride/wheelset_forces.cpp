#include <railstab/ride/wheelset_forces.hpp>

#include <railstab/equilibrium/equilibrium.hpp>
#include <railstab/equilibrium/speed_continuation.hpp>

#include <algorithm>
#include <stdexcept>

namespace railstab {

namespace {

const WheelForces* find_wheel(const std::vector<WheelForces>& wheels, int body, int side) {
  for (const WheelForces& w : wheels)
    if (w.body == body && w.side == side) return &w;
  return nullptr;
}

}  // namespace

std::vector<StaticWheelLoad> static_wheel_loads(const Model& model, double speed_m_per_s) {
  Model straight = model;
  TrackSpec tangent;
  tangent.rail_contact_distance_m = model.track.spec().rail_contact_distance_m;
  // Long enough for every body's track position of the model's track.
  tangent.segments.push_back(
      {TrackSegmentKind::tangent, std::max(model.track.length_m(), 1.0) + 1e4, 0.0, 0.0});
  straight.track = Track(tangent);
  straight.speed_rate_m_per_s2 = 0.0;
  EquilibriumResult eq;
  try {
    // From the nominal position (as the scene's set-up), not the scene's
    // initial offsets: a run's disturbance (5 mm on S1002) is no guess for
    // the steady state.
    eq = solve_equilibrium(straight, speed_m_per_s, lowered_nominal_state(straight, speed_m_per_s));
  } catch (const EquilibriumError&) {
    // Above the critical speed the steady state is unstable, so the solver's
    // pseudo-transient fallback cannot reach it from the nominal position
    // (the S1002 bogie at 41 m/s): solve where it is stable, at
    // kStaticLoadStartSpeed_m_per_s (or half the speed), and continue in
    // speed along the branch.
    const double start = std::min(kStaticLoadStartSpeed_m_per_s, 0.5 * speed_m_per_s);
    const EquilibriumResult slow = solve_equilibrium(straight, start, lowered_nominal_state(straight, start));
    eq = continue_equilibrium_in_speed(straight, start, slow.state, speed_m_per_s, {});
  }
  const std::vector<WheelForces> wheels = wheel_forces(straight, speed_m_per_s, 0.0, eq.state);
  std::vector<StaticWheelLoad> loads;
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    if (!model.bodies[b].wheelset()) continue;
    StaticWheelLoad load;
    load.body = int(b);
    if (const WheelForces* w = find_wheel(wheels, int(b), +1)) load.left_N = w->Q_N;
    if (const WheelForces* w = find_wheel(wheels, int(b), -1)) load.right_N = w->Q_N;
    loads.push_back(load);
  }
  return loads;
}

double prudhomme_limit_N(double static_axle_load_N, double prudhomme_factor) {
  return prudhomme_factor * (10e3 + static_axle_load_N / 3.0);
}

std::vector<WheelsetForces> wheelset_forces(const Model& model, double speed_m_per_s, double t_s,
                                            const Eigen::VectorXd& x,
                                            const std::vector<StaticWheelLoad>& loads,
                                            double prudhomme_factor) {
  const std::vector<WheelForces> wheels = wheel_forces(model, speed_m_per_s, t_s, x);
  Eigen::MatrixXd q6, qd6;
  model.full_coordinates(t_s, speed_m_per_s, x, q6, qd6);
  std::vector<WheelsetForces> result;
  for (const StaticWheelLoad& load : loads) {
    WheelsetForces f;
    f.body = load.body;
    f.left.body = f.right.body = load.body;
    f.left.side = +1;
    f.right.side = -1;
    if (const WheelForces* w = find_wheel(wheels, load.body, +1)) f.left = *w;
    if (const WheelForces* w = find_wheel(wheels, load.body, -1)) f.right = *w;
    f.sum_y_N = f.left.Y_N - f.right.Y_N;
    f.axle_load_N = f.left.Q_N + f.right.Q_N;
    f.angle_of_attack_rad = q6(int(CoordinateIndex::yaw), load.body);
    if (!(load.left_N > 0.0) || !(load.right_N > 0.0))
      throw std::runtime_error(model.bodies[size_t(load.body)].name +
                               ": a static wheel load is not positive; no wheel unloading");
    f.left_static_load_N = load.left_N;
    f.right_static_load_N = load.right_N;
    f.left_delta_q_over_q0 = (load.left_N - f.left.Q_N) / load.left_N;
    f.right_delta_q_over_q0 = (load.right_N - f.right.Q_N) / load.right_N;
    f.static_axle_load_N = load.axle_load_N();
    f.prudhomme_limit_N = prudhomme_limit_N(f.static_axle_load_N, prudhomme_factor);
    result.push_back(f);
  }
  return result;
}

}  // namespace railstab
