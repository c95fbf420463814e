// The static wheel loads Q0 (Delta Q/Q0, Prud'homme's limit) are those of the
// vehicle's steady state on straight track: they do not depend on a run's
// initial disturbance, and on level track they carry the whole weight. The
// S1002 bogie above its linear critical speed (39.80 m/s) with its leading
// wheelset displaced 5 mm: the equilibrium solved from that disturbance
// failed ("no equilibrium found ... largest acceleration residual 10.3 in
// wheelset1.pitch_rad/s"), so `simulate` refused every such run.
#include <gtest/gtest.h>

#include "support/test_files.hpp"

#include <railstab/ride/wheelset_forces.hpp>
#include <railstab/setup/prepare_scene.hpp>

namespace railstab {
namespace {

TEST(StaticWheelLoads, DoNotDependOnTheInitialDisturbanceAndCarryTheWeight) {
  SceneSpec spec = load_scene_with_overrides(test::case_path("thesis_bogie_s1002_tangent"), {});
  const PreparedScene nominal = prepare_scene(spec);
  for (BodySpec& b : spec.bodies)
    if (b.name == "wheelset1") b.initial_offset[1] = 0.005;
  const PreparedScene disturbed = prepare_scene(spec);
  const double V = 41.0;  // above the linear critical speed
  const std::vector<StaticWheelLoad> a = static_wheel_loads(nominal.model, V);
  const std::vector<StaticWheelLoad> b = static_wheel_loads(disturbed.model, V);
  ASSERT_EQ(a.size(), 2u);
  ASSERT_EQ(b.size(), a.size());
  double weight = 0.0, carried = 0.0;
  for (const BodySpec& body : spec.bodies) weight += body.mass_kg * spec.gravity_m_per_s2;
  for (size_t w = 0; w < a.size(); ++w) {
    // The same steady state to Newton's tolerance (1e-9 of the load).
    EXPECT_NEAR(b[w].left_N, a[w].left_N, 1e-9 * a[w].left_N);
    EXPECT_NEAR(b[w].right_N, a[w].right_N, 1e-9 * a[w].right_N);
    // Symmetric vehicle on level track: both wheels alike.
    EXPECT_NEAR(a[w].left_N, a[w].right_N, 1e-6 * a[w].left_N);
    carried += a[w].axle_load_N();
  }
  // The wheels carry the whole bogie (no body of it is held vertically).
  EXPECT_NEAR(carried, weight, 1e-6 * weight);
}

}  // namespace
}  // namespace railstab
