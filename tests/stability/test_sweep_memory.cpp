// A critical-speed search keeps what its results and reports read (modes,
// eigenvectors, the linear model's state names) but not the state matrix of
// each point: memory per grid point bounded (issue 11).
#include <railstab/setup/prepare_scene.hpp>
#include <railstab/stability/speed_analysis.hpp>

#include <gtest/gtest.h>

using namespace railstab;

TEST(SweepMemory, GridPointsKeepModesButNotTheStateMatrix) {
  const PreparedScene s =
      prepare_scene(std::string(RAILSTAB_CASES_DIR) + "/thesis_vehicle_tangent.toml", {});
  CriticalSpeedOptions o;
  o.from_m_per_s = 100.0;
  o.to_m_per_s = 120.0;
  o.grid_step_m_per_s = 10.0;
  o.tolerance_m_per_s = 1.0;
  const CriticalSpeedResult r = find_critical_speed(s.model, s.equilibrium.state, s.speed_m_per_s, o);
  ASSERT_TRUE(r.critical_speed_found);
  ASSERT_EQ(r.grid.size(), 3u);
  for (const StabilityPoint& p : r.grid) {
    EXPECT_EQ(p.linear.A.size(), 0);
    EXPECT_EQ(p.linear.A_sparse.nonZeros(), 0);
    EXPECT_EQ(p.linear.states(), 78);
    ASSERT_EQ(p.modes.size(), 78u);  // dense: every mode, with its eigenvector
    EXPECT_EQ(p.modes.front().vector.size(), 78);
  }
  EXPECT_EQ(r.at_critical.linear.A.size(), 0);
  EXPECT_EQ(r.at_critical.modes.size(), 78u);
  // A single point evaluated on its own keeps its matrix (callers may want it).
  SpeedStability single(s.model, s.equilibrium.state, s.speed_m_per_s);
  EXPECT_EQ(single.at(100.0).linear.A.rows(), 78);
}
