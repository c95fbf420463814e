// EN 14363's running-stability assessment (assessment/running_stability.hpp):
// the bogie frames and their masses, f0 of a known signal, and the whole
// chain (band-pass at f0, 100 m windows, limits) on a synthetic run whose
// rms is known.
#include <gtest/gtest.h>

#include "support/test_files.hpp"

#include <railstab/assessment/running_stability.hpp>
#include <railstab/setup/prepare_scene.hpp>

#include <cmath>
#include <numbers>

namespace railstab {
namespace {

const Model& thesis_vehicle() {
  static const PreparedScene s = prepare_scene(test::case_path("thesis_vehicle_tangent"), {});
  return s.model;
}

TEST(RunningStability, BogieFramesAreTheBodiesTheWheelsetsHangFrom) {
  const Model& m = thesis_vehicle();
  const std::vector<BogieFrame> frames = bogie_frames(m);
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(m.bodies[size_t(frames[0].body)].name, "bogie1");
  EXPECT_EQ(m.bodies[size_t(frames[1].body)].name, "bogie2");
  const double wheelset = m.bodies[size_t(m.find_body("wheelset1"))].mass_kg;
  EXPECT_DOUBLE_EQ(frames[0].mass_kg, 3020.0 + 2.0 * wheelset);
}

TEST(RunningStability, DominantFrequencyOfANoisySinusoid) {
  std::vector<double> x;
  const double dt = 0.01;
  for (int i = 0; i < 2000; ++i)
    x.push_back(3.0 * std::sin(2.0 * std::numbers::pi * 4.3 * i * dt) + 0.5 * std::sin(17.0 * i * dt + 1.0) + 7.0);
  // The periodogram's bin over the second half padded 8-fold: 1/(8 * 10 s).
  EXPECT_NEAR(dominant_frequency_Hz(x, dt), 4.3, 1.0 / 80.0);
}

// A run of the thesis vehicle's shape: 4 wheelsets, the bogie frames' and
// car body's CMs, Sum Y = A sin(2 pi f t) on every wheelset, the frames'
// lateral acceleration B sin(2 pi f t), over 30 s at 50 m/s (1.5 km).
RideHistory synthetic_run(double A_N, double B_m_per_s2) {
  const Model& m = thesis_vehicle();
  RideHistory h;
  for (size_t b = 0; b < m.bodies.size(); ++b)
    if (m.bodies[b].wheelset()) h.static_loads.push_back({int(b), 70e3, 70e3});
  h.points = acceleration_points(m);
  const double dt = 0.005, f = 5.0;
  for (int i = 0; i <= 6000; ++i) {
    const double t = i * dt, wave = std::sin(2.0 * std::numbers::pi * f * t);
    h.times_s.push_back(t);
    h.distance_m.push_back(50.0 * t);
    std::vector<WheelsetForces> forces(h.static_loads.size());
    for (size_t w = 0; w < forces.size(); ++w) {
      forces[w].body = h.static_loads[w].body;
      forces[w].sum_y_N = A_N * wave;
      forces[w].left.y_over_q = 0.1;
      forces[w].right.y_over_q = 0.05;
    }
    h.wheelsets.push_back(forces);
    h.accelerations.push_back(std::vector<Eigen::Vector3d>(h.points.size(), Eigen::Vector3d(0.0, B_m_per_s2 * wave, 0.0)));
  }
  return h;
}

TEST(RunningStability, SinusoidAtF0KeepsItsRmsAndIsJudgedAgainstTheLimits) {
  // Limits: Sum Y rms (10 kN + 140 kN / 3) / 2 = 28.33 kN; bogie frame
  // (12 - m_b / 5) / 2 with m_b = 3.02 t + 2 wheelsets.
  const double sum_y_limit = (10e3 + 140e3 / 3.0) / 2.0;
  for (const double fraction : {0.7, 1.3}) {
    const double rms = fraction * sum_y_limit;
    const RideHistory h = synthetic_run(rms * std::sqrt(2.0), 1.0);
    const RunningStabilityAssessment a = assess_running_stability(thesis_vehicle(), h, AssessmentSpec{}, "");
    EXPECT_NEAR(a.instability_frequency_Hz, 5.0, 0.02);
    int sum_y_quantities = 0, frame_quantities = 0;
    for (const AssessedQuantity& q : a.quantities) {
      if (q.quantity == "sum_y_rms") {
        ++sum_y_quantities;
        EXPECT_NEAR(q.limit, sum_y_limit, 1e-6);
        // A sinusoid at the band's centre passes with gain 1 (the filter's
        // start transient is over within the first window's first metres).
        EXPECT_NEAR(q.value, rms, 0.01 * rms) << q.subject;
        EXPECT_EQ(q.passed, fraction < 1.0) << q.subject;
        EXPECT_EQ(q.windows.size(), size_t((1500.0 - 100.0) / 10.0) + 1);
      }
      if (q.quantity == "bogie_lateral_acceleration_rms") {
        ++frame_quantities;
        EXPECT_NEAR(q.value, 1.0 / std::sqrt(2.0), 0.01);
        EXPECT_TRUE(q.passed);  // 0.71 m/s2 against ~5.4 m/s2
      }
      if (q.quantity == "y_over_q_2m") {
        EXPECT_NEAR(q.value, 0.1, 1e-12);
      }
    }
    EXPECT_EQ(sum_y_quantities, 4);
    EXPECT_EQ(frame_quantities, 2);
    EXPECT_EQ(a.passed, fraction < 1.0);
  }
  // A run that stopped early fails whatever its rms.
  EXPECT_FALSE(assess_running_stability(thesis_vehicle(), synthetic_run(1.0, 0.1), AssessmentSpec{},
                                        "wheelset1 reached the flange clearance")
                   .passed);
}

TEST(RunningStability, AWheelThatLiftsOffFailsWithoutAValue) {
  RideHistory h = synthetic_run(1.0, 0.1);
  h.wheelsets[4000][1].right.y_over_q.reset();
  const RunningStabilityAssessment a = assess_running_stability(thesis_vehicle(), h, AssessmentSpec{}, "");
  EXPECT_FALSE(a.passed);
  ASSERT_EQ(a.failures_without_value.size(), 1u);
  EXPECT_NE(a.failures_without_value[0].find("wheelset2"), std::string::npos) << a.failures_without_value[0];
}

TEST(RunningStability, ARunShorterThanOneWindowIsRefusedOrFailsWhenItStoppedEarly) {
  RideHistory h = synthetic_run(1.0, 0.1);
  h.times_s.resize(300);
  h.distance_m.resize(300);
  h.wheelsets.resize(300);
  h.accelerations.resize(300);
  try {
    assess_running_stability(thesis_vehicle(), h, AssessmentSpec{}, "");
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("assessment.stability_window_m"), std::string::npos) << e.what();
  }
  // The same run stopped early (at the flange clearance): a fail, saying why.
  const RunningStabilityAssessment a =
      assess_running_stability(thesis_vehicle(), h, AssessmentSpec{}, "wheelset1 reached the flange clearance");
  EXPECT_FALSE(a.passed);
  EXPECT_TRUE(a.quantities.empty());
  ASSERT_EQ(a.failures_without_value.size(), 1u);
  EXPECT_NE(a.failures_without_value[0].find("before one 100 m window"), std::string::npos)
      << a.failures_without_value[0];
}

}  // namespace
}  // namespace railstab
