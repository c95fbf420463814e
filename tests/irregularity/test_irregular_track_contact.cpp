// Track irregularities in the wheel-rail contact (docs/irregular_track.md,
// "In the contact"), against references that do not use the code under
// test: a constant displacement of both rails is a translation of the whole
// vehicle; a constant gauge widening is a wider track_gauge_m, whose contact
// table is built from the profiles anew; a sinusoidal alignment drives the
// linearised vehicle at its frequency response, from the AD state matrix.
#include <gtest/gtest.h>

#include "support/test_files.hpp"

#include <railstab/integrate/integrator.hpp>
#include <railstab/linear/linearization.hpp>
#include <railstab/model/equations_of_motion.hpp>
#include <railstab/model/wheel_forces.hpp>
#include <railstab/setup/prepare_scene.hpp>

#include <Eigen/Dense>

#include <cmath>
#include <complex>
#include <functional>
#include <numbers>

namespace railstab {
namespace {

// A measured record made in memory: rows every ds over [s0, s1], each
// channel a function of s (null: not in the record), no fades.
IrregularitySpec record(double s0, double s1, double ds,
                        std::array<std::function<double(double)>, kIrregularityChannels> channels) {
  MeasuredIrregularities m;
  m.path = "<test record>";
  for (double s = s0; s <= s1 + 1e-9; s += ds) m.arc_length_m.push_back(s);
  for (int c = 0; c < kIrregularityChannels; ++c) {
    m.in_file[size_t(c)] = bool(channels[size_t(c)]);
    for (double s : m.arc_length_m) m.channels_m[size_t(c)].push_back(channels[size_t(c)] ? channels[size_t(c)](s) : 0.0);
  }
  IrregularitySpec spec;
  spec.measured = std::move(m);
  spec.start_m = s0;
  spec.length_m = s1 - s0;
  spec.fade_in_m = spec.fade_out_m = 0.0;
  return spec;
}

std::function<double(double)> constant(double v) {
  return [v](double) { return v; };
}

IntegrationOptions tight_run(double t_end_s) {
  IntegrationOptions o;
  o.t_end_s = t_end_s;
  o.output_interval_s = 0.01;
  o.relative_tolerance = 1e-9;
  o.absolute_tolerance = 1e-12;
  return o;
}

// c0 + c1 cos(omega t) + c2 sin(omega t) fitted to state `full` (minus
// `offset`) over t >= t0; returns c2 + i c1, the complex amplitude X of
// Im(X e^{i omega t}).
std::complex<double> fitted_amplitude(const Trajectory& traj, int full, double offset, double omega, double t0) {
  std::vector<Eigen::RowVector3d> rows;
  std::vector<double> values;
  for (size_t k = 0; k < traj.times_s.size(); ++k) {
    const double t = traj.times_s[k];
    if (t < t0) continue;
    rows.push_back(Eigen::RowVector3d(1.0, std::cos(omega * t), std::sin(omega * t)));
    values.push_back(traj.states[k](full) - offset);
  }
  Eigen::MatrixXd basis(Eigen::Index(rows.size()), 3);
  Eigen::VectorXd y(Eigen::Index(rows.size()));
  for (size_t k = 0; k < rows.size(); ++k) {
    basis.row(Eigen::Index(k)) = rows[k];
    y(Eigen::Index(k)) = values[k];
  }
  const Eigen::Vector3d c = basis.colPivHouseholderQr().solve(y);
  return {c(2), c(1)};
}

int state_named(const Model& model, const std::string& name) {
  for (int i = 0; i < model.state_size(); ++i)
    if (model.state_name(i) == name) return i;
  ADD_FAILURE() << "no state " << name;
  return 0;
}

// Constant alignment A and level Z move both rails by (A, Z): on a vehicle
// with no element to the track the motion is the perfect track's, moved by
// (A, Z) in every body's y and z.
void expect_translation_invariance(const std::string& case_name, double t_end_s, double tolerance_m) {
  const double A = 3e-3, Z = 2e-3;
  const SceneSpec perfect_spec = load_scene_with_overrides(test::case_path(case_name), {});
  SceneSpec irregular_spec = perfect_spec;
  irregular_spec.track.irregularities = record(-1000.0, 5000.0, 10.0, {constant(A), constant(Z), nullptr, nullptr});
  const PreparedScene perfect = prepare_scene(perfect_spec);
  const PreparedScene irregular = prepare_scene(irregular_spec, true);
  const Model& model = irregular.model;
  ASSERT_NE(model.track.irregularities(), nullptr);
  const Eigen::VectorXd x0 = perturbed_initial_state(perfect);
  Eigen::VectorXd shift = Eigen::VectorXd::Zero(x0.size());
  for (int i = 0; i < model.n_coordinates; ++i) {
    const int coordinate = model.coordinate_of_state[size_t(i)].second;
    if (coordinate == int(CoordinateIndex::y)) shift(i) = A;
    if (coordinate == int(CoordinateIndex::z)) shift(i) = Z;
  }
  // The static equilibrium found on the displaced rails is the moved one.
  EXPECT_LT((irregular.equilibrium.state - perfect.equilibrium.state - shift).lpNorm<Eigen::Infinity>(), 1e-9);
  const double V = perfect.speed_m_per_s;
  const Trajectory a = integrate(perfect.model, V, x0, tight_run(t_end_s));
  const Trajectory b = integrate(model, V, x0 + shift, tight_run(t_end_s));
  ASSERT_EQ(a.times_s.size(), b.times_s.size());
  double worst = 0.0, largest_motion = 0.0;
  for (size_t k = 0; k < a.times_s.size(); ++k) {
    worst = std::max(worst, (b.states[k] - shift - a.states[k]).head(model.n_coordinates).lpNorm<Eigen::Infinity>());
    largest_motion = std::max(largest_motion, (a.states[k] - perfect.equilibrium.state).head(model.n_coordinates).lpNorm<Eigen::Infinity>());
  }
  EXPECT_GT(largest_motion, 1e-4);  // the run moves: the comparison means something
  EXPECT_LT(worst, tolerance_m) << case_name;
}

TEST(IrregularTrackContact, ConstantAlignmentAndLevelAreATranslationKnifeEdge) {
  // Both runs take the same steps up to rounding: agreement far inside the
  // integration tolerance.
  expect_translation_invariance("thesis_vehicle_tangent", 3.0, 1e-9);
}

TEST(IrregularTrackContact, ConstantAlignmentAndLevelAreATranslationProfiles) {
  expect_translation_invariance("thesis_bogie_s1002_tangent", 1.0, 1e-9);
}

// Irregularities of zero amplitude (amplitude_scale = 0) leave every run as
// it was on perfect track, bit for bit: the irregular path adds exact zeros.
TEST(IrregularTrackContact, ZeroIrregularityReproducesThePerfectTrackRunBitForBit) {
  for (const std::string case_name : {"thesis_vehicle_tangent", "thesis_bogie_s1002_tangent"}) {
    const SceneSpec perfect_spec = load_scene_with_overrides(test::case_path(case_name), {});
    SceneSpec zero_spec = perfect_spec;
    IrregularitySpec irr;
    irr.length_m = 400.0;
    irr.components = 100;
    irr.amplitude_scale = 0.0;
    zero_spec.track.irregularities = irr;
    const PreparedScene perfect = prepare_scene(perfect_spec);
    const PreparedScene zero = prepare_scene(zero_spec, true);
    IntegrationOptions o = integration_options_for(perfect.spec.simulation);
    o.t_end_s = 0.5;
    const Eigen::VectorXd x0 = perturbed_initial_state(perfect);
    const Trajectory a = integrate(perfect.model, perfect.speed_m_per_s, x0, o);
    const Trajectory b = integrate(zero.model, zero.speed_m_per_s, x0, o);
    ASSERT_EQ(a.times_s.size(), b.times_s.size()) << case_name;
    EXPECT_EQ(a.stats.steps, b.stats.steps) << case_name;
    bool identical = true;
    for (size_t k = 0; k < a.states.size(); ++k) identical = identical && a.states[k] == b.states[k];
    EXPECT_TRUE(identical) << case_name;
  }
}

// A constant gauge widening g moves the left rail out by g/2 and the right
// one out by g/2: the scene with track_gauge_m + g, whose contact table is
// built anew from the profiles. g/2 is a whole number of the table's
// lateral steps, so the two tables hold the same poses at their nodes; what
// remains is the contact search's own rounding on a rail placed anew
// (~3e-8 m in the steady state, a few 1e-6 of the wheel load, measured).
TEST(IrregularTrackContact, ConstantGaugeWideningIsAWiderTrackGauge) {
  const std::string case_name = "thesis_bogie_s1002_tangent";
  const double g = 2e-3;
  SceneOverrides wider;
  wider.values.push_back({"contacts.s1002_uic60.track_gauge_m", 1.435 + g});
  const PreparedScene wide = prepare_scene(test::case_path(case_name), wider);
  SceneSpec spec = load_scene_with_overrides(test::case_path(case_name), {});
  spec.track.irregularities = record(-1000.0, 5000.0, 10.0, {nullptr, nullptr, nullptr, constant(g)});
  const PreparedScene irregular = prepare_scene(spec, true);
  const double V = wide.speed_m_per_s;
  EXPECT_LT((irregular.equilibrium.state - wide.equilibrium.state).lpNorm<Eigen::Infinity>(), 1e-7);
  double Q0 = 0.0;  // the mean static wheel load
  for (const WheelForces& w : wheel_forces(wide.model, V, 0.0, wide.equilibrium.state)) Q0 += w.Q_N / 4.0;
  ASSERT_GT(Q0, 10e3);
  // Wheel forces at states off the equilibrium: lateral shifts into flange contact.
  double largest_Y = 0.0;
  for (double y : {-7e-3, -2e-3, 0.5e-3, 4e-3, 8e-3}) {
    Eigen::VectorXd x = wide.equilibrium.state;
    for (int i = 0; i < wide.model.n_coordinates; ++i)
      if (wide.model.coordinate_of_state[size_t(i)].second == int(CoordinateIndex::y)) x(i) += y;
    const std::vector<WheelForces> a = wheel_forces(wide.model, V, 0.0, x);
    const std::vector<WheelForces> b = wheel_forces(irregular.model, V, 0.0, x);
    ASSERT_EQ(a.size(), b.size());
    for (size_t w = 0; w < a.size(); ++w) {
      EXPECT_NEAR(b[w].Q_N, a[w].Q_N, 1e-5 * Q0) << "lateral shift " << y;
      EXPECT_NEAR(b[w].Y_N, a[w].Y_N, 1e-5 * Q0) << "lateral shift " << y;
      largest_Y = std::max(largest_Y, std::abs(a[w].Y_N));
    }
  }
  EXPECT_GT(largest_Y, 0.2 * Q0);  // flange forces among them
}

// Every wheelset meets a defect when it gets there: the rails under a
// wheelset at time t + (x_1 - x_2) / V are those under the leading one at t.
TEST(IrregularTrackContact, EachWheelsetMeetsTheSameRailsLaterByItsDistance) {
  SceneSpec spec = load_scene_with_overrides(test::case_path("thesis_vehicle_tangent"), {});
  IrregularitySpec irr;
  irr.spectrum = IrregularitySpectrum::erri_b176_high;
  irr.length_m = 600.0;
  irr.components = 200;
  spec.track.irregularities = irr;
  const PreparedScene s = prepare_scene(spec, true);
  const Model& model = s.model;
  const double V = s.speed_m_per_s;
  const int lead = model.find_body("wheelset1");
  Workspace<double> ws(model);
  int compared = 0;
  for (int b = 0; b < int(model.bodies.size()); ++b) {
    if (!model.bodies[size_t(b)].wheelset()) continue;
    const double delay = (model.bodies[size_t(lead)].track_offset_m - model.bodies[size_t(b)].track_offset_m) / V;
    for (double t : {1.0, 2.5, 7.25}) {
      ws.update_frames(model, t, V);
      const std::array<RailDisplacement, 2> leading = ws.frames[size_t(lead)].rails;
      ws.update_frames(model, t + delay, V);
      for (int side = 0; side < 2; ++side) {
        EXPECT_NEAR(ws.frames[size_t(b)].rails[size_t(side)].lateral_m, leading[size_t(side)].lateral_m, 1e-15);
        EXPECT_NEAR(ws.frames[size_t(b)].rails[size_t(side)].vertical_m, leading[size_t(side)].vertical_m, 1e-15);
      }
      EXPECT_GT(std::abs(leading[0].lateral_m), 1e-6);  // on the irregular stretch
      ++compared;
    }
  }
  EXPECT_EQ(compared, 4 * 3);
}

// A sinusoidal alignment a(s) = a0 sin(2 pi s / L) at speed V drives every
// wheelset w at omega = 2 pi V / L with the phase 2 pi s_w(0) / L. The
// linearised vehicle x' = A x + sum_w B_w a_w(t) answers in steady state
// with Im(X e^{i omega t}), X = (i omega - A)^-1 sum_w B_w a0 e^{i phi_w};
// B_w, the response of the equations of motion to wheelset w's rails moving
// sideways, is a central difference of the right-hand side. The time-domain
// run's settled motion is fitted by c0 + c1 cos(omega t) + c2 sin(omega t):
// c1 = Im X, c2 = Re X, to the model's nonlinearity at 0.1 mm.
TEST(IrregularTrackContact, SinusoidalAlignmentGivesTheLinearFrequencyResponse) {
  const double a0 = 1e-4, L = 25.0;
  SceneSpec spec = load_scene_with_overrides(test::case_path("thesis_vehicle_tangent"), {});
  const double s_lead0 = spec.reference_arc_length_m;
  spec.track.irregularities = record(-500.0, 1000.0, 0.05, {[&](double s) { return a0 * std::sin(2 * std::numbers::pi * s / L); },
                                                             nullptr, nullptr, nullptr});
  const PreparedScene perfect = prepare_scene(load_scene_with_overrides(test::case_path("thesis_vehicle_tangent"), {}));
  const PreparedScene irregular = prepare_scene(spec, true);
  const Model& model = perfect.model;
  const double V = perfect.speed_m_per_s;
  const Eigen::VectorXd& x_eq = perfect.equilibrium.state;
  const LinearModel lin = linearize(model, V, x_eq);
  const int n = lin.states();
  const double omega = 2 * std::numbers::pi * V / L;
  Eigen::VectorXcd input = Eigen::VectorXcd::Zero(n);
  const double h = 1e-7;
  for (int b = 0; b < int(model.bodies.size()); ++b) {
    if (!model.bodies[size_t(b)].wheelset()) continue;
    Eigen::VectorXd f[2];
    for (int k = 0; k < 2; ++k) {
      Workspace<double> ws(model);
      ws.update_frames(model, 0.0, V);
      for (RailDisplacement& rail : ws.frames[size_t(b)].rails) rail.lateral_m = k == 0 ? h : -h;
      Eigen::VectorXd xdot(x_eq.size());
      evaluate_rhs<double>(model, ws, 0.0, V, x_eq, xdot);
      f[k] = xdot;
    }
    const double phase = 2 * std::numbers::pi * (s_lead0 + model.bodies[size_t(b)].track_offset_m) / L;
    for (int i = 0; i < n; ++i)
      input(i) += (f[0](lin.kept_states[size_t(i)]) - f[1](lin.kept_states[size_t(i)])) / (2 * h) * a0 *
                  std::polar(1.0, phase);
  }
  const Eigen::MatrixXcd M = std::complex<double>(0.0, omega) * Eigen::MatrixXcd::Identity(n, n) - lin.A.cast<std::complex<double>>();
  const Eigen::VectorXcd X = M.partialPivLu().solve(input);

  IntegrationOptions o = tight_run(30.0);
  o.relative_tolerance = 1e-8;
  const Trajectory traj = integrate(irregular.model, V, irregular.equilibrium.state, o);
  ASSERT_TRUE(traj.stopped_early.empty()) << traj.stopped_early;
  // The last 8 periods, once the start's transient has died away.
  const double period = 2 * std::numbers::pi / omega, t1 = traj.times_s.back(), t0 = t1 - 8 * period;
  for (const std::string name : {"wheelset1.y_m", "wheelset4.yaw_rad", "carbody.y_m"}) {
    const int full = state_named(model, name);
    int reduced = -1;
    for (int i = 0; i < n; ++i)
      if (lin.kept_states[size_t(i)] == full) reduced = i;
    ASSERT_GE(reduced, 0);
    const std::complex<double> fitted = fitted_amplitude(traj, full, x_eq(full), omega, t0);
    const std::complex<double> predicted = X(reduced);
    EXPECT_GT(std::abs(predicted), 1e-3 * a0) << name;  // a response worth comparing
    EXPECT_LT(std::abs(fitted - predicted), 0.01 * std::abs(predicted))
        << name << ": fitted " << fitted << ", linear " << predicted;
  }
}

// The textbook wheelset (linear conicity lambda, constant creep
// coefficients, prescribed loads, lateral and yaw springs k_y, k_psi to the
// design track) on a sinusoidal alignment a = a0 sin(k s), s = V t: its
// equations are linear,
//   m y''   = -2 f22 (y'/V - psi) - k_y y
//   J psi'' = -2 f11 e0 (e0 psi'/V + lambda (y - a)/r0) - k_psi psi,
// so at omega = k V the response is the 2 x 2 solve below, exactly. At 5 m/s
// the creep forces dominate: the wheelset follows the rail nearly as the
// kinematic (Klingel) law y = a k_K^2 / (k_K^2 - k^2) would, and at
// k = k_K / 2 it moves about 4/3 of the alignment.
TEST(IrregularTrackContact, TextbookWheelsetFollowsASinusoidalAlignmentAsItsClosedForm) {
  const double a0 = 1e-3, V = 5.0;
  const double lambda = 0.1, e0 = 0.75, r0 = 0.45, f11 = 1e7, f22 = 1e7, m = 1500.0, J = 799.35;
  const double k_y = 2 * 0.5e6, k_psi = 2 * 1e6 * 1.0 * 1.0;  // springs at +-1 m
  const double k_kinematic = std::sqrt(lambda / (e0 * r0));
  const double k = 0.5 * k_kinematic, L = 2 * std::numbers::pi / k, omega = k * V;
  SceneOverrides at_speed;
  at_speed.speed_m_per_s = V;
  SceneSpec spec = load_scene_with_overrides(test::case_path("textbook_wheelset"), at_speed);
  spec.track.irregularities = record(-100.0, 1000.0, 0.05, {[&](double s) { return a0 * std::sin(k * s); },
                                                            nullptr, nullptr, nullptr});
  const PreparedScene s = prepare_scene(spec, true);
  // Phasors of y and psi for a = a0 e^{i (omega t + phi)}, phi = k s(0).
  using C = std::complex<double>;
  const C i(0.0, 1.0);
  Eigen::Matrix2cd M;
  M << -m * omega * omega + 2 * f22 * i * omega / V + k_y, C(-2 * f22),
      C(2 * f11 * e0 * lambda / r0), -J * omega * omega + 2 * f11 * e0 * e0 * i * omega / V + k_psi;
  const C a = a0 * std::polar(1.0, k * spec.reference_arc_length_m);
  const Eigen::Vector2cd X = M.partialPivLu().solve(Eigen::Vector2cd(C(0.0), 2 * f11 * e0 * lambda / r0 * a));
  EXPECT_NEAR(std::abs(X(0)) / a0, 4.0 / 3.0, 0.1);  // near the kinematic law

  IntegrationOptions o = tight_run(250.0 / V);
  const Trajectory traj = integrate(s.model, V, s.equilibrium.state, o);
  ASSERT_TRUE(traj.stopped_early.empty()) << traj.stopped_early;
  const double t0 = traj.times_s.back() - 4 * L / V;  // the last 4 wavelengths: the start's transient has died
  const C y = fitted_amplitude(traj, state_named(s.model, "wheelset1.y_m"), 0.0, omega, t0);
  const C psi = fitted_amplitude(traj, state_named(s.model, "wheelset1.yaw_rad"), 0.0, omega, t0);
  EXPECT_LT(std::abs(y - X(0)), 1e-4 * std::abs(X(0))) << y << " against " << X(0);
  EXPECT_LT(std::abs(psi - X(1)), 1e-4 * std::abs(X(1))) << psi << " against " << X(1);
}

}  // namespace
}  // namespace railstab
