// Compile-fail test of the force-element contract (elements/
// force_element_concept.hpp): a line spring that lacks `potential` must not
// compile as a force element. Built twice by CTest (tests/CMakeLists.txt):
// as is, it must compile (the control: the file is otherwise a valid
// element); with RAILSTAB_OMIT_POTENTIAL it must fail with the concept's
// message.
#include <railstab/elements/force_element_concept.hpp>
#include <railstab/elements/line_motion.hpp>

#include <string>

namespace railstab {

template <class S> struct PlainLineSpring {
  static constexpr const char* kType = "plain_line_spring";
  static constexpr int kInternalStates = 0;
  static constexpr bool kInGravitySag = true;
  ElementEnds ends;
  S stiffness_N_per_m = S(0);
  double free_length_m = 0.0;

  void set_nominal(const Attachment<double>& a1, const Attachment<double>& a2) {
    free_length_m = value_of(line_motion(a1, ends.point1_m, a2, ends.point2_m).length_m);
  }
  template <class T> Vec3<T> elastic_load(const Attachment<T>&, const Attachment<T>&) const {
    return Vec3<T>::Zero();
  }
  void set_preload(const Vec3<S>&) {}
  template <class F> void for_each_preloaded_axis(F&&) const {}
  template <class F> void for_each_parameter(F&& f) { f("stiffness_N_per_m", -1, stiffness_N_per_m); }
  template <class T>
  void apply(const Attachment<T>& a1, const Attachment<T>& a2, const T*, T*) const {
    const LineMotion<T> m = line_motion(a1, ends.point1_m, a2, ends.point2_m);
    apply_line_tension(a1, a2, m, lift<T>(stiffness_N_per_m) * (m.length_m - T(free_length_m)));
  }
#ifndef RAILSTAB_OMIT_POTENTIAL
  double potential(const Attachment<double>&, const Attachment<double>&, const double*) const {
    return 0.0;
  }
#endif
  std::string internal_state_name(int) const { return {}; }
  template <class S2> PlainLineSpring<S2> cast() const { return {}; }
};

static_assert(assert_force_element<PlainLineSpring<double>, double>());

}  // namespace railstab
