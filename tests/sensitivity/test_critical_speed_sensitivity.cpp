// d(critical speed)/dp from the eigenvalue derivative and the implicit
// function theorem against central differences of the critical speed
// itself (each side a full critical-speed search bisected to 1e-9 m/s).
#include <gtest/gtest.h>

#include <railstab/sensitivity/critical_speed_sensitivity.hpp>
#include <railstab/sensitivity/parameter_derivative.hpp>
#include <railstab/setup/prepare_scene.hpp>
#include <railstab/stability/speed_analysis.hpp>

#include <cmath>

using namespace railstab;

namespace {

CriticalSpeedResult search(const SceneSpec& spec) {
  const PreparedScene s = prepare_scene(spec);
  CriticalSpeedOptions opt;
  opt.from_m_per_s = 5.0;
  opt.to_m_per_s = 150.0;
  opt.grid_step_m_per_s = 2.5;
  opt.tolerance_m_per_s = 1e-9;
  return find_critical_speed(s.model, s.equilibrium.state, s.speed_m_per_s, opt);
}

}  // namespace

TEST(CriticalSpeedSensitivity, AgreesWithCentralDifferencesOfTheCriticalSpeed) {
  const SceneSpec scene = load_scene_with_overrides(std::string(RAILSTAB_CASES_DIR) + "/textbook_bogie.toml", {});
  const CriticalSpeedResult base = search(scene);
  ASSERT_TRUE(base.critical_speed_found);
  const double Vc = base.critical_speed_m_per_s;
  const double f = base.at_critical.modes[size_t(base.at_critical.least_stable)].frequency_hz;
  const std::vector<std::string> keys = {"elements.primary_ws1.stiffness_N_per_m[0]",
                                         "elements.primary_ws1.stiffness_N_per_m[1]",
                                         "bodies.bogie1.mass_kg",
                                         "bodies.wheelset1.inertia_kg_m2[2]",
                                         "contacts.textbook_linear.conicity"};
  const CriticalSpeedSensitivities s = critical_speed_sensitivities(scene, Vc, f, keys);
  ASSERT_EQ(s.parameters.size(), keys.size());
  EXPECT_LT(std::abs(s.eigenvalue.real()), 1e-6);  // on the stability boundary
  EXPECT_GT(s.real_part_speed_derivative, 0.0);    // it loses stability with speed
  for (const ParameterSensitivity& p : s.parameters) {
    const double delta = 1e-3 * std::abs(p.value);
    const CriticalSpeedResult up = search(with_parameter(scene, p.key, p.value + delta));
    const CriticalSpeedResult down = search(with_parameter(scene, p.key, p.value - delta));
    ASSERT_TRUE(up.critical_speed_found && down.critical_speed_found) << p.key;
    const double fd = (up.critical_speed_m_per_s - down.critical_speed_m_per_s) / (2.0 * delta);
    const double fd_elasticity = fd * p.value / Vc;
    // Central-difference truncation ~ (delta/p)^2 ~ 1e-6; bisection 1e-9 m/s
    // over 2 delta; the speed step of d Re lambda / dV ~ 1e-6 relative.
    // Measured: 4e-8 to 9e-7 relative.
    EXPECT_NEAR(p.elasticity, fd_elasticity, 1e-5 * std::abs(fd_elasticity))
        << p.key << ": dVc/dp " << p.critical_speed_derivative << " vs central difference " << fd;
  }
  for (size_t i = 1; i < s.parameters.size(); ++i)
    EXPECT_GE(std::abs(s.parameters[i - 1].elasticity), std::abs(s.parameters[i].elasticity));
}

// The thesis vehicle: the car body mass moves the preloads (ERRATA 13), a
// primary stiffness, and the cone angle (a contact parameter that moves the
// equilibrium). The creep reduction factor, ranked first, sits at its upper
// limit 1 and has no central difference.
TEST(CriticalSpeedSensitivity, ThesisVehicleAgreesWithCentralDifferences) {
  const SceneSpec scene =
      load_scene_with_overrides(std::string(RAILSTAB_CASES_DIR) + "/thesis_vehicle_tangent.toml", {});
  const CriticalSpeedResult base = search(scene);
  ASSERT_TRUE(base.critical_speed_found);
  const double Vc = base.critical_speed_m_per_s;
  EXPECT_NEAR(Vc, 111.46, 0.01);
  const double f = base.at_critical.modes[size_t(base.at_critical.least_stable)].frequency_hz;
  const CriticalSpeedSensitivities s = critical_speed_sensitivities(
      scene, Vc, f,
      {"bodies.carbody.mass_kg", "elements.primary_ws4.stiffness_N_per_m[0]",
       "contacts.thesis_knife_edge.cone_angle_rad"});
  for (const ParameterSensitivity& p : s.parameters) {
    const double delta = 1e-3 * std::abs(p.value);
    const CriticalSpeedResult up = search(with_parameter(scene, p.key, p.value + delta));
    const CriticalSpeedResult down = search(with_parameter(scene, p.key, p.value - delta));
    ASSERT_TRUE(up.critical_speed_found && down.critical_speed_found) << p.key;
    const double fd = (up.critical_speed_m_per_s - down.critical_speed_m_per_s) / (2.0 * delta);
    // Measured: 2e-7, 1.4e-4 (the stiff primary spring), 1e-6 relative.
    EXPECT_NEAR(p.critical_speed_derivative, fd, 5e-4 * std::abs(fd)) << p.key;
    EXPECT_GT(std::abs(p.elasticity), 0.01) << p.key;  // 0.43, -0.11, -0.03: far from round-off
  }
}
