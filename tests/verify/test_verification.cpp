// Time domain against eigenvalues on the same model, and the damped-sinusoid
// fit against known signals.
#include <railstab/setup/prepare_scene.hpp>
#include <railstab/verify/verification.hpp>

#include <gtest/gtest.h>

#include <cmath>

using namespace railstab;

// The fit recovers a known damped sinusoid with offset exactly (no noise),
// from a guess 20 % off.
TEST(DampedSinusoidFit, RecoversKnownSignal) {
  std::vector<double> t, y;
  for (int i = 0; i < 400; ++i) {
    t.push_back(1.0 + 0.01 * i);
    const double tau = t.back() - 1.0;
    y.push_back(std::exp(-0.7 * tau) * (2e-3 * std::cos(9.0 * tau) - 1e-3 * std::sin(9.0 * tau)) +
                1e-5);
  }
  const DampedSinusoid f = fit_damped_sinusoid(t, y, -0.56, 10.8);
  EXPECT_NEAR(f.sigma_per_s, -0.7, 1e-9);
  EXPECT_NEAR(f.omega_rad_s, 9.0, 1e-9);
  EXPECT_NEAR(f.c, 1e-5, 1e-12);
  EXPECT_LT(f.rms_residual, 1e-12);
}

// Thesis bogie below (20 m/s) and above (38 m/s) its critical speed: the
// nonlinear response to a 0.1 mm perturbation along the least stable mode
// decays / grows at the eigenvalue's rate. Targets of the issue: frequency
// within 1 %, real part within 5 %; measured agreement is ~1e-5, limited by
// the integration tolerance and the amplitude-squared nonlinearity.
TEST(Verification, ThesisBogieMatchesEigenvalue) {
  for (double v : {20.0, 38.0}) {
    const PreparedScene s = prepare_scene(std::string(RAILSTAB_CASES_DIR) +
                                              "/thesis_bogie_tangent.toml", SceneOverrides::at_speed(v));
    const VerificationResult r = verify_least_stable_mode(s.model, s.speed_m_per_s, s.equilibrium.state);
    EXPECT_LT(r.frequency_difference_relative, 0.01) << v;
    EXPECT_LT(r.real_difference_relative, 0.05) << v;
    EXPECT_EQ(r.fitted_real_per_s > 0.0, v > 36.9) << v;  // grows above V_crit = 36.90 m/s
    EXPECT_LT(r.integration_error_relative, 1e-4) << v;
  }
}

// Thesis vehicle below (110 m/s) and above (115 m/s) its critical speed
// 111.46 m/s: the least stable lateral mode is the bogie hunting mode near
// 4.2 Hz. Same targets as the bogie.
TEST(Verification, ThesisVehicleMatchesEigenvalue) {
  for (double v : {110.0, 115.0}) {
    const PreparedScene s = prepare_scene(std::string(RAILSTAB_CASES_DIR) +
                                              "/thesis_vehicle_tangent.toml", SceneOverrides::at_speed(v));
    const VerificationResult r = verify_least_stable_mode(s.model, s.speed_m_per_s, s.equilibrium.state);
    EXPECT_LT(r.frequency_difference_relative, 0.01) << v;
    EXPECT_LT(r.real_difference_relative, 0.05) << v;
    EXPECT_EQ(r.fitted_real_per_s > 0.0, v > 111.46) << v;
    EXPECT_NEAR(r.eigen_frequency_hz, 4.2, 0.2) << v;
    EXPECT_LT(r.integration_error_relative, 1e-4) << v;
  }
}

// At 100 m/s the least stable lateral mode is the car-body sway (0.42 Hz):
// 2 settling periods and 2 to fit need 9.6 s, but the tangent of the thesis
// track ends after 9 s. The run would enter the clothoid and leave the
// steady state the eigenvalue belongs to, so verify refuses with the reason;
// settling for one period it fits the sway (measured 6e-10).
TEST(Verification, RefusesToRunOffTheUniformTrack) {
  const PreparedScene s = prepare_scene(std::string(RAILSTAB_CASES_DIR) +
                                            "/thesis_vehicle_tangent.toml", SceneOverrides::at_speed(100.0));
  try {
    verify_least_stable_mode(s.model, s.speed_m_per_s, s.equilibrium.state);
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("leaves the uniform stretch of track"), std::string::npos)
        << e.what();
  }
  VerificationOptions o;
  o.settle_periods = 1.0;
  const VerificationResult r = verify_least_stable_mode(s.model, s.speed_m_per_s, s.equilibrium.state, o);
  EXPECT_TRUE(r.track_limited);
  EXPECT_NEAR(r.eigen_frequency_hz, 0.417, 0.001);
  EXPECT_LT(r.frequency_difference_relative, 0.01);
  EXPECT_LT(r.real_difference_relative, 0.05);
}

// From the thesis cases' own start (1 mm offset of wheelset1) instead of the
// mode: the other modes die out in the two settling periods and the fit
// still meets the targets (measured 7e-6 and 0.55 % on the real part: the
// 1 mm start is ten times the mode perturbation, so the amplitude-dependent
// nonlinearity shows at 38 m/s).
TEST(Verification, FromTheSceneOffsetsMeetsTheTargets) {
  for (double v : {20.0, 38.0}) {
    const PreparedScene s = prepare_scene(std::string(RAILSTAB_CASES_DIR) +
                                              "/thesis_bogie_tangent.toml", SceneOverrides::at_speed(v));
    VerificationOptions o;
    o.initial_state = perturbed_initial_state(s);
    const VerificationResult r = verify_least_stable_mode(s.model, s.speed_m_per_s, s.equilibrium.state, o);
    EXPECT_EQ(r.start, "given initial state");
    EXPECT_LT(r.frequency_difference_relative, 0.01) << v;
    EXPECT_LT(r.real_difference_relative, 0.05) << v;
    EXPECT_EQ(r.fitted_real_per_s > 0.0, v > 36.9) << v;
  }
}

// The thesis bogie on S1002/UIC60 (cases/thesis_bogie_s1002_tangent.toml,
// critical speed 39.80 m/s) at 20 and 25 m/s, started along the hunting mode
// with 0.01 mm: the time domain decays as the eigenvalue says (measured
// 0.32 % / 0.56 % in the real part, 0.10 % / 0.18 % in the frequency, when
// the two tread slots both counted their shared overlap). The linear range
// of this profile pair is small: the contact jumps at a lateral shift of
// 0.25 mm, so a 0.1 mm start is already nonlinear; closer to the critical
// speed see the next test.
TEST(Verification, ProfileBogieMatchesEigenvalueInItsLinearRange) {
  for (double v : {20.0, 25.0}) {
    const PreparedScene s = prepare_scene(std::string(RAILSTAB_CASES_DIR) +
                                              "/thesis_bogie_s1002_tangent.toml", SceneOverrides::at_speed(v));
    VerificationOptions o;
    o.amplitude_m = 1e-5;
    const VerificationResult r =
        verify_least_stable_mode(s.model, s.speed_m_per_s, s.equilibrium.state, o);
    EXPECT_LT(r.frequency_difference_relative, 0.005) << v;
    EXPECT_LT(r.real_difference_relative, 0.02) << v;
    EXPECT_LT(r.fitted_real_per_s, 0.0) << v;
  }
}

// Near the critical speed (36 m/s, Vc 39.80 m/s) the difference is a
// nonlinearity that vanishes with the amplitude, not a linearisation error:
// measured 0.19 % (real part) at 10 um and 0.019 % at 1 um, first order in
// the amplitude as the saturating creep law's correction is in the creepage
// (SHE: F = F_L (1 - u/3 ...)). The relative error grows towards the
// critical speed because the real part it is divided by goes to zero (-0.22
// 1/s here against -0.51 at 20 m/s). (7.9 % at 10 um while the two tread
// slots both counted their shared overlap, docs/model.md 6.1: a wheel moving
// off the centre met a force that doubled within 0.1 mm.)
// Asserted: within 0.5 % at 1 um, and at least 5x smaller than at 10 um.
TEST(Verification, ProfileBogieNearCriticalSpeedConvergesAsTheAmplitudeShrinks) {
  const PreparedScene s = prepare_scene(
      std::string(RAILSTAB_CASES_DIR) + "/thesis_bogie_s1002_tangent.toml", SceneOverrides::at_speed(36.0));
  double error[2] = {0.0, 0.0};
  const double amplitudes[2] = {1e-5, 1e-6};
  for (int i = 0; i < 2; ++i) {
    VerificationOptions o;
    o.amplitude_m = amplitudes[i];
    error[i] = verify_least_stable_mode(s.model, 36.0, s.equilibrium.state, o).real_difference_relative;
  }
  EXPECT_LT(error[1], 0.005);
  EXPECT_GT(error[0], 5.0 * error[1]) << error[0] << " " << error[1];
}
