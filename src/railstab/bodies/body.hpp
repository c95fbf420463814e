#pragma once
// A body of the model and its kind. The kinds are types in one variant, so
// every place that treats kinds differently is a std::visit the compiler
// checks for completeness when a kind is added:
//   - rigid_body: attachments and inertia in the body frame B;
//   - wheelset: axisymmetric, spins about its axle (pitch = spin angle); its
//     attachments (axle boxes) live in the non-spinning frame I = Bz Bx and
//     it rolls on the rails through a wheel-rail contact model.
// Parameters that sensitivities may differentiate (mass, inertia) have the
// model's parameter scalar S (double, or an AD type: ModelTpl::cast).
#include <railstab/core/scalar.hpp>

#include <array>
#include <string>
#include <type_traits>
#include <variant>

namespace railstab {

struct RigidBodyKind {
  static constexpr const char* kName = "rigid_body";
  // Attachment frame F = B: the whole body turns with its pitch.
  static constexpr bool kAttachedInSpinningFrame = true;
};

struct WheelsetKind {
  static constexpr const char* kName = "wheelset";
  // Attachment frame F = I: the axle boxes do not spin, their moments do no
  // work on the spin, and the inertia in I does not depend on the spin angle.
  static constexpr bool kAttachedInSpinningFrame = false;
  int contact = -1;                     // index into Model::contacts
  double nominal_rolling_radius_m = 0;  // r0 of that contact: spin rate V / r0
};

using BodyKind = std::variant<RigidBodyKind, WheelsetKind>;

inline bool attached_in_spinning_frame(const BodyKind& kind) {
  return std::visit([](const auto& k) { return std::decay_t<decltype(k)>::kAttachedInSpinningFrame; },
                    kind);
}
inline const char* kind_name(const BodyKind& kind) {
  return std::visit([](const auto& k) { return std::decay_t<decltype(k)>::kName; }, kind);
}

template <class S> struct BodyTpl {
  std::string name;
  BodyKind kind = RigidBodyKind{};
  S mass_kg = S(0);
  Vec3<S> inertia_kg_m2 = Vec3<S>::Zero();  // principal Jx, Jy, Jz in B
  double track_offset_m = 0.0;  // arc length of its track frame minus the reference
  std::array<int, 6> state_index{};          // index into q, or -1 when frozen
  Eigen::Matrix<double, 6, 1> nominal_q;     // nominal position, no offsets
  Eigen::Matrix<double, 6, 1> initial_offset;  // scene's initial offsets
  Eigen::Matrix<double, 6, 1> initial_rate;    // scene's initial rates (without spin)

  const WheelsetKind* wheelset() const { return std::get_if<WheelsetKind>(&kind); }
  // Steady spin rate about the axle at speed V (pitch rate), 0 for other kinds.
  double steady_spin_rate(double speed_m_per_s) const {
    const WheelsetKind* w = wheelset();
    return w ? speed_m_per_s / w->nominal_rolling_radius_m : 0.0;
  }
  // Rate of coordinate i at rest relative to the track at speed V.
  double steady_rate(int i, double speed_m_per_s) const {
    return i == 4 ? steady_spin_rate(speed_m_per_s) : 0.0;
  }
  // Prescribed value and rate of a frozen coordinate at time t, with the
  // speed V(t) = V0 + dV/dt t (dV/dt = 0: constant speed; the steady rate is
  // linear in V, so its integral is steady_rate(V0) t + steady_rate(dV/dt) t^2/2):
  //   q_i(t)  = nominal + offset + (initial rate + steady rate(V0)) t
  //             + steady_rate(dV/dt) t^2 / 2
  //   q_i'(t) = initial rate + steady rate(V(t)).
  double prescribed_rate(int i, double speed_now_m_per_s) const {
    return initial_rate(i) + steady_rate(i, speed_now_m_per_s);
  }
  double prescribed_value(int i, double t_s, double speed_m_per_s,
                          double speed_rate_m_per_s2 = 0.0) const {
    const double value = nominal_q(i) + initial_offset(i) + prescribed_rate(i, speed_m_per_s) * t_s;
    return speed_rate_m_per_s2 == 0.0 ? value
                                      : value + 0.5 * steady_rate(i, speed_rate_m_per_s2) * t_s * t_s;
  }

  // The body's differentiable parameters: f(key, index or -1, value).
  template <class F> void for_each_parameter(F&& f) {
    f("mass_kg", -1, mass_kg);
    for (int i = 0; i < 3; ++i) f("inertia_kg_m2", i, inertia_kg_m2(i));
  }

  template <class S2> BodyTpl<S2> cast() const {
    BodyTpl<S2> b;
    b.name = name;
    b.kind = kind;
    b.mass_kg = lift<S2>(mass_kg);
    b.inertia_kg_m2 = lift<S2>(inertia_kg_m2);
    b.track_offset_m = track_offset_m;
    b.state_index = state_index;
    b.nominal_q = nominal_q;
    b.initial_offset = initial_offset;
    b.initial_rate = initial_rate;
    return b;
  }
};

}  // namespace railstab
