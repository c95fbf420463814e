// The quasi-linear critical speed by amplitude
// (stability/quasi_linear_critical_speed.hpp): on a linear-conicity contact
// the contact functions are their own harmonic linearisation, so the
// quasi-linear critical speed is the plain one (1e-9 relative) at every
// amplitude; on the thesis bogie with S1002/UIC60 the curve V_c(A) is finite
// from 0.5 mm to flange contact and continuous (no jump between amplitudes
// 0.02 mm apart), and the equivalent conicity it reports is the contact's.
#include <gtest/gtest.h>

#include "support/test_files.hpp"

#include <railstab/setup/prepare_scene.hpp>
#include <railstab/stability/quasi_linear_critical_speed.hpp>

#include <cmath>

using namespace railstab;

namespace {

CriticalSpeedOptions search(double from, double to, double step) {
  CriticalSpeedOptions o;
  o.from_m_per_s = from;
  o.to_m_per_s = to;
  o.grid_step_m_per_s = step;
  o.mode_shapes_at_critical = false;
  return o;
}

}  // namespace

TEST(QuasiLinearCriticalSpeed, LinearConicityContactGivesThePlainCriticalSpeed) {
  const PreparedScene s = prepare_scene(test::case_path("textbook_wheelset"), {});
  const CriticalSpeedOptions o = search(5, 120, 5);
  const CriticalSpeedResult plain = find_critical_speed(s.model, s.equilibrium.state, s.speed_m_per_s, o);
  ASSERT_TRUE(plain.critical_speed_found);
  for (double A : {1e-4, 3e-3}) {
    const QuasiLinearCriticalSpeed q =
        find_quasi_linear_critical_speed(s.model, s.equilibrium.state, s.speed_m_per_s, A, o);
    EXPECT_FALSE(q.has_profile_contact);
    EXPECT_TRUE(q.wheelsets.empty());
    ASSERT_TRUE(q.result.critical_speed_found);
    EXPECT_NEAR(q.result.critical_speed_m_per_s, plain.critical_speed_m_per_s,
                1e-9 * plain.critical_speed_m_per_s);
  }
  EXPECT_THROW(QuasiLinearModelBuilder(s.model, s.equilibrium.state).at(-1e-3), std::invalid_argument);
}

TEST(QuasiLinearCriticalSpeed, S1002BogieCurveIsFiniteAndContinuous) {
  const PreparedScene s = prepare_scene(test::case_path("thesis_bogie_s1002_tangent"), {});
  const QuasiLinearModelBuilder builder(s.model, s.equilibrium.state);
  ASSERT_TRUE(builder.has_profile_contact());
  const double flange = builder.flange_contact_amplitude_m();
  ASSERT_GT(flange, 4e-3);
  const CriticalSpeedOptions o = search(5, 150, 5);
  std::vector<double> amplitudes;
  for (double A : {0.5e-3, 1e-3, 2e-3, 3e-3, 4e-3}) {
    amplitudes.push_back(A);
    amplitudes.push_back(A + 2e-5);
  }
  amplitudes.push_back(flange);
  const QuasiLinearCurve c =
      quasi_linear_critical_speed_curve(builder, s.equilibrium.state, s.speed_m_per_s, amplitudes, o);
  ASSERT_EQ(c.points.size(), amplitudes.size());
  for (const QuasiLinearCurvePoint& p : c.points) {
    EXPECT_TRUE(p.critical_speed_found) << "A = " << p.amplitude_m << ": " << p.note;
    EXPECT_TRUE(std::isfinite(p.critical_speed_m_per_s));
    EXPECT_GT(p.equivalent_conicity, 0.0);
  }
  // Amplitudes 0.02 mm apart: the gains move by O(0.02 mm / A), the speed
  // by far less than the 0.5 m/s bound (a jump would be metres per second).
  for (size_t i = 0; i + 1 < amplitudes.size() - 1; i += 2)
    EXPECT_NEAR(c.points[i].critical_speed_m_per_s, c.points[i + 1].critical_speed_m_per_s, 0.5)
        << "A = " << amplitudes[i];
  // The reported conicity is the contact's N_dr(A)/2 about the centred state.
  const QuasiLinearModel q = builder.at(3e-3);
  ASSERT_EQ(q.wheelsets.size(), 2u);
  EXPECT_NEAR(q.wheelsets[0].centre_m, 0.0, 1e-9);
  EXPECT_NEAR(c.points[6].equivalent_conicity, q.wheelsets[0].equivalent_conicity, 1e-14);
  EXPECT_THROW(builder.at(builder.max_amplitude_m() + 1e-4), std::invalid_argument);
}
