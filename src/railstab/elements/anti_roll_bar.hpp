#pragma once
// anti_roll_bar: a torsion bar carried by body 1 (bogie frame) whose two arms
// are linked to body 2 (car body) at lateral positions +a and -a. Bounce
// turns both arms alike and does not twist the bar; roll of body 2 relative
// to body 1 does. With dz_L, dz_R the vertical deflections of the two links
// in body 1's axes (from the nominal configuration, as spring_damper_3d
// measures d - d0) the bar's twist and potential are
//   theta = (dz_L - dz_R) / (2 a),   V = 1/2 k_roll theta^2 + M_pre theta
// and each link carries the vertical force -/+ (k_roll theta + M_pre)/(2 a)
// (frame 1), applied as a spring_damper_3d applies its force: for a pure
// relative roll phi, theta = sin(phi) and the restoring moment is k_roll phi
// to first order: k_roll is the roll stiffness the bar adds.
// point1_m / point2_m give the link's x and z on each body; their y is
// replaced by +a (left link) and -a (right link).
#include <railstab/elements/axis_deflection.hpp>
#include <railstab/elements/element_ends.hpp>

#include <array>
#include <string>

namespace railstab {

template <class S> struct AntiRollBar {
  static constexpr const char* kType = "anti_roll_bar";
  static constexpr int kInternalStates = 0;
  static constexpr bool kInGravitySag = true;
  ElementEnds ends;
  S roll_stiffness_N_m_per_rad = S(0);
  double link_half_spacing_m = 1.0;  // a
  S preload_N_m = S(0);              // solved by the builder
  Eigen::Vector3d free_vector_left_m = Eigen::Vector3d::Zero();   // set by the builder
  Eigen::Vector3d free_vector_right_m = Eigen::Vector3d::Zero();

  Eigen::Vector3d link_point(const Eigen::Vector3d& p, double side) const {
    return Eigen::Vector3d(p.x(), side * link_half_spacing_m, p.z());
  }
  template <class T>
  std::array<AxisDeflection<T>, 2> links(const Attachment<T>& a1, const Attachment<T>& a2) const {
    return {axis_deflection(a1, link_point(ends.point1_m, 1), a2, link_point(ends.point2_m, 1)),
            axis_deflection(a1, link_point(ends.point1_m, -1), a2, link_point(ends.point2_m, -1))};
  }
  template <class T> T twist(const std::array<AxisDeflection<T>, 2>& d) const {
    return (d[0].d.z() - T(free_vector_left_m.z()) - d[1].d.z() + T(free_vector_right_m.z())) /
           T(2.0 * link_half_spacing_m);
  }

  void set_nominal(const Attachment<double>& a1, const Attachment<double>& a2) {
    const auto d = links(a1, a2);
    free_vector_left_m = d[0].d;
    free_vector_right_m = d[1].d;
  }
  template <class T>
  Vec3<T> elastic_load(const Attachment<T>& a1, const Attachment<T>& a2) const {
    return Vec3<T>(lift<T>(roll_stiffness_N_m_per_rad) * twist(links(a1, a2)), T(0), T(0));
  }
  void set_preload(const Vec3<S>& load) { preload_N_m = load.x(); }
  // The preload on each preloaded axis and the axis's stiffness, for the
  // model check's static deflections: f(axis, unit, preload, stiffness).
  template <class F> void for_each_preloaded_axis(F&& f) const {
    f("twist", "rad", value_of(preload_N_m), value_of(roll_stiffness_N_m_per_rad));
  }
  template <class F> void for_each_parameter(F&& f) {
    f("roll_stiffness_N_m_per_rad", -1, roll_stiffness_N_m_per_rad);
  }

  template <class T>
  void apply(const Attachment<T>& a1, const Attachment<T>& a2, const T*, T*) const {
    const auto d = links(a1, a2);
    const T moment = lift<T>(roll_stiffness_N_m_per_rad) * twist(d) + lift<T>(preload_N_m);
    const T link_force = moment / T(2.0 * link_half_spacing_m);
    apply_axis_force(a1, a2, d[0], Vec3<T>(T(0), T(0), link_force));
    apply_axis_force(a1, a2, d[1], Vec3<T>(T(0), T(0), -link_force));
  }

  double potential(const Attachment<double>& a1, const Attachment<double>& a2,
                   const double*) const {
    const double th = twist(links(a1, a2));
    return 0.5 * value_of(roll_stiffness_N_m_per_rad) * th * th + value_of(preload_N_m) * th;
  }

  std::string internal_state_name(int) const { return {}; }

  template <class S2> AntiRollBar<S2> cast() const {
    AntiRollBar<S2> e;
    e.ends = ends;
    e.roll_stiffness_N_m_per_rad = lift<S2>(roll_stiffness_N_m_per_rad);
    e.link_half_spacing_m = link_half_spacing_m;
    e.preload_N_m = lift<S2>(preload_N_m);
    e.free_vector_left_m = free_vector_left_m;
    e.free_vector_right_m = free_vector_right_m;
    return e;
  }
};

}  // namespace railstab
