// A hunting orbit on real profiles (S1002 on UIC60 1:40, contact tables C1
// between their nodes, flange contact): the thesis bogie's flange-hunting
// cycle at 45 m/s (linear critical speed 39.80 m/s), found as the
// `bifurcation --cycle-speed` start does (a time-domain run settles, its last
// period is the guess, damped Newton at fixed speed), checked against
// references that do not use the shooting code:
// - the settled time-domain run itself: after 14 periods whose transient
//   decays with the orbit's largest multiplier (|mu| 0.054 per period), its
//   last period's excursion and period equal the orbit's;
// - a plain run (integrate(), CVODE BDF, rtol 1e-10) from the orbit's start
//   returns to it after one period;
// - the orbit's stability (largest multiplier inside the unit circle) agrees
//   with that run settling on it, and the largest multiplier with a run
//   perturbed along its eigenvector.
#include <gtest/gtest.h>

#include <railstab/equilibrium/speed_continuation.hpp>
#include <railstab/integrate/integrator.hpp>
#include <railstab/nonlinear/bifurcation_analysis.hpp>
#include <railstab/nonlinear/model_orbits.hpp>
#include <railstab/nonlinear/periodic_orbit.hpp>
#include <railstab/nonlinear/speed_ramp.hpp>
#include <railstab/setup/prepare_scene.hpp>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <string>
#include <vector>

using namespace railstab;

namespace {

// The bifurcation run of these tests: the linear search over [from, to] on a
// 2.5 m/s grid, no Hopf branch (its micrometre orbits on a tabulated
// contact), the time-domain branch up to 8 mm and max_orbits orbits.
BifurcationOptions time_domain_branch_options(double from_m_per_s, double to_m_per_s, int max_orbits) {
  BifurcationOptions o;
  o.linear.from_m_per_s = from_m_per_s;
  o.linear.to_m_per_s = to_m_per_s;
  o.linear.grid_step_m_per_s = 2.5;
  o.from_hopf = false;
  o.max_amplitude_m = 0.008;
  o.continuation.max_orbits = max_orbits;
  return o;
}

// `railstab bifurcation CASE --from F --to T --no-hopf-branch --max-orbits N`
// with the profile-contact default start (no cycle speed given).
BifurcationResult default_start_run(const std::string& case_file, double from_m_per_s,
                                    double to_m_per_s, int max_orbits) {
  const PreparedScene scene = prepare_scene(std::string(RAILSTAB_CASES_DIR) + "/" + case_file, {});
  return analyse_bifurcation(scene.model, scene.equilibrium.state, scene.speed_m_per_s,
                             time_domain_branch_options(from_m_per_s, to_m_per_s, max_orbits));
}

// Issue 22: the nonlinear critical speed by continuation against the ramp
// method at two rates, both computed here (no number of either put in).
// The branch from the cycle a run from 5 mm settles on at cycle_speed is
// followed down to its first fold; a ramp started on that cycle follows it
// down to the fold and loses its hunting below it, later by a speed delay
// d(a) that shrinks with the rate a: d ~ a^p, p = 2/3 for the slow passage
// through a saddle-node (the orbit lingers near its ghost for a time ~
// a^(-1/3)) and 1 for the decay after it, so 1/2 <= p <= 1 bounds it with
// room. Two rates a1 > a2 with end speeds V1 < V2 then put the zero-rate
// limit (the fold) at V2 + (V2 - V1) r / (1 - r), r = (a2/a1)^p, i.e. in
// [V2 + 0.67 (V2 - V1), V2 + 1.72 (V2 - V1)] for a2/a1 = 0.4: the "spread
// of the ramp method at two rates" the fold must lie in, below V_c.
void expect_fold_in_the_ramps_bracket(const std::string& case_file, const std::string& tag,
                                      double from_m_per_s, double to_m_per_s, int max_orbits,
                                      double cycle_speed_m_per_s, double ramp_end_m_per_s) {
  SceneOverrides overrides;
  overrides.values = {SceneValueSetting("track.segments[0].length_m", 5000.0)};
  const PreparedScene scene =
      prepare_scene(std::string(RAILSTAB_CASES_DIR) + "/" + case_file, overrides);
  BifurcationOptions o = time_domain_branch_options(from_m_per_s, to_m_per_s, max_orbits);
  o.cycle_speed_m_per_s = cycle_speed_m_per_s;
  o.continuation.stop_at_first_fold = true;
  const std::string prefix = "[ " + tag + std::string(std::max<size_t>(1, 9 - tag.size()), ' ') + "] ";
  int failure_lines = 0;
  o.progress = [&failure_lines, &prefix](const std::string& line) {
    std::printf("%s%s\n", prefix.c_str(), line.c_str());
    failure_lines += line.find("corrector failed") != std::string::npos;
  };
  const BifurcationResult r =
      analyse_bifurcation(scene.model, scene.equilibrium.state, scene.speed_m_per_s, o);
  ASSERT_TRUE(r.linear.critical_speed_found);
  ASSERT_EQ(r.branches.size(), 1u);
  ASSERT_TRUE(r.branches[0].error.empty()) << r.branches[0].error;
  const OrbitBranch& branch = r.branches[0].branch;
  EXPECT_EQ(branch.stop_reason, "stopped past the first fold (stop at fold)");
  EXPECT_EQ(failure_lines, branch.failed_correctors);  // each failure is said on stderr
  ASSERT_TRUE(r.nonlinear.found) << r.nonlinear.explanation;
  ASSERT_EQ(r.nonlinear.bound, StableBound::fold) << r.nonlinear.explanation;
  const double fold = r.nonlinear.speed_m_per_s;
  const PeriodicOrbit& first = branch.orbits.front();
  ASSERT_TRUE(first.stable);
  std::printf("%sV_c %.3f m/s; first orbit %.4f mm at %.2f m/s; fold %.4f m/s after %zu orbits, "
              "%.1f s CPU\n",
              prefix.c_str(), r.linear.critical_speed_m_per_s,
              1e3 * first.amplitude(r.coords.amplitude_state), first.speed_m_per_s, fold,
              branch.orbits.size(), branch.cpu_seconds);
  EXPECT_LT(fold, first.speed_m_per_s);
  EXPECT_LT(fold, r.linear.critical_speed_m_per_s);

  // The ramps from the first orbit (on the stable cycle).
  std::vector<double> ends;
  for (double a : {0.5, 0.2}) {
    SpeedRampOptions ramp;
    ramp.start_speed_m_per_s = first.speed_m_per_s;
    ramp.ramp_rate_m_per_s2 = a;
    ramp.end_speed_m_per_s = ramp_end_m_per_s;
    ramp.integration = integration_options_for(scene.spec.simulation);
    const SpeedRampResult run =
        run_speed_ramp(scene.model, embed_state(scene.model, r.reduced_states, first.start), ramp);
    ASSERT_TRUE(run.vanished) << run.outcome;
    ends.push_back(run.hunting_end_speed_m_per_s);
    std::printf("%sramp %.1f m/s^2 from %.1f m/s: hunting ends at %.4f m/s (%.1f s CPU)\n",
                prefix.c_str(), a, first.speed_m_per_s, ends.back(),
                run.trajectory.stats.cpu_seconds);
  }
  EXPECT_LT(ends[0], ends[1]);  // the slower ramp nearer the fold
  EXPECT_LT(ends[1], fold);     // a ramp cannot lose a stable cycle above its fold
  const double spread = ends[1] - ends[0];
  EXPECT_GT(fold, ends[1] + 0.67 * spread);
  EXPECT_LT(fold, ends[1] + 1.72 * spread);
}

}  // namespace

TEST(ProfileContactOrbit, S1002BogieFlangeHuntingCycleIsATimeDomainSolution) {
  const PreparedScene scene = prepare_scene(std::string(RAILSTAB_CASES_DIR) +
                                                "/thesis_bogie_s1002_tangent.toml",
                                            {});
  const Model& model = scene.model;
  const double V = 45.0;
  std::vector<int> reduced;
  const FlowSystem system = model_flow_system(model, 0.0, &reduced);
  const OrbitCoordinates coords = wheelset_orbit_coordinates(model, reduced);
  const int ia = coords.amplitude_state;
  const EquilibriumResult eq =
      continue_equilibrium_in_speed(model, scene.speed_m_per_s, scene.equilibrium.state, V, {});
  IntegrationOptions settle;
  settle.output_interval_s = 1e-4;
  settle.relative_tolerance = 1e-8;
  settle.absolute_tolerance = 1e-11;
  const OrbitGuess guess =
      settled_cycle_guess(model, V, eq.state, reduced, coords, 0.005, 6.0, settle);
  const PeriodicOrbit o = solve_periodic_orbit(system, coords, OrbitConstraint::fixed_speed(V),
                                               guess.start, guess.period_s, V);
  const double a = o.start(ia) - eq.state(reduced[size_t(ia)]);
  std::printf("[ S1002    ] orbit at %.1f m/s: excursion %.4f mm (run %.4f), period %.6f s (run "
              "%.6f), |mu| %.4f, %d iterations (%d damped), %ld steps, %.2f s CPU\n",
              V, 1e3 * o.start(ia), 1e3 * guess.start(ia), o.period_s, guess.period_s,
              std::abs(o.critical_multiplier), o.newton_iterations, o.damped_steps,
              o.integration_steps, o.cpu_seconds);
  // Flange hunting: the excursion beyond the flange contact (~6 mm), stable.
  EXPECT_GT(a, 5e-3);
  EXPECT_TRUE(o.stable);
  // The settled run's last period (samples 0.1 ms apart, linear
  // interpolation at the section: O(1e-8) in time and excursion).
  EXPECT_NEAR(o.start(ia), guess.start(ia), 1e-5 * a);
  EXPECT_NEAR(o.period_s, guess.period_s, 1e-5 * o.period_s);
  // A plain run from the orbit returns after one period.
  IntegrationOptions io;
  io.t_end_s = o.period_s;
  io.output_interval_s = o.period_s;
  io.relative_tolerance = 1e-10;
  io.absolute_tolerance = 1e-13;
  const Trajectory back_run = integrate(model, V, embed_state(model, reduced, o.start), io);
  ASSERT_TRUE(back_run.stopped_early.empty()) << back_run.stopped_early;
  const Eigen::VectorXd back = reduce_state(reduced, back_run.states.back());
  const double scale = o.amplitude.cwiseAbs().maxCoeff();
  std::printf("[ S1002    ] return after one period: %.3e of the largest amplitude\n",
              (back - o.start).cwiseAbs().maxCoeff() / scale);
  // 1e-6 of the amplitude, as issue 22 asks and the knife-edge vehicle's
  // test checks (measured 5e-8).
  EXPECT_LT((back - o.start).cwiseAbs().maxCoeff(), 1e-6 * scale);

  // The same orbit with the variational equations in a second pass (what
  // the bifurcation analysis uses on profile contact): the same start and
  // period to the flow's accuracy, the same largest multiplier to the
  // sensitivities' tolerance (rtol 1e-5, a period's error of a few 1e-5),
  // the trivial multiplier at 1.
  ShootingOptions second_pass;
  second_pass.flow.variational = FlowOptions::Variational::second_pass;
  const PeriodicOrbit o2 = solve_periodic_orbit(system, coords, OrbitConstraint::fixed_speed(V),
                                                guess.start, guess.period_s, V, second_pass);
  std::printf("[ S1002    ] second pass: excursion %.6f mm, period %.8f s, |mu| %.6f (alongside "
              "%.6f), trivial |mu - 1| %.1e, %d iterations, %.2f s CPU\n",
              1e3 * o2.start(ia), o2.period_s, std::abs(o2.critical_multiplier),
              std::abs(o.critical_multiplier), o2.trivial_multiplier_error, o2.newton_iterations,
              o2.cpu_seconds);
  EXPECT_LT((o2.start - o.start).cwiseAbs().maxCoeff(), 1e-6 * scale);
  EXPECT_NEAR(o2.period_s, o.period_s, 1e-7 * o.period_s);
  EXPECT_NEAR(std::abs(o2.critical_multiplier), std::abs(o.critical_multiplier), 1e-4);
  EXPECT_LT(o2.trivial_multiplier_error, 1e-4);
  EXPECT_TRUE(o2.stable);

  // The largest multiplier against a perturbed run (time domain against the
  // Floquet analysis, issue 22): along the critical multiplier's
  // eigenvector v (phase turned so that its largest entry is real, the start
  // perturbed by its real part), a plain run over one period departs from
  // the run from x0 by eps Re(mu v) to first order in eps; the two runs'
  // difference cancels the orbit's periodicity residual. eps = 1e-5 of the
  // largest amplitude: smaller, the runs' own errors (rtol 1e-11) show in
  // the difference (misfit 1.3e-2 at 1e-6, 0.44 at 1e-8); the second-order
  // part is of order eps. Measured misfit 1.4e-3 to 2.4e-3 (the start
  // guessed one cycle apart).
  Eigen::EigenSolver<Eigen::MatrixXd> es(o.monodromy);
  Eigen::Index j = 0;
  for (Eigen::Index k = 1; k < es.eigenvalues().size(); ++k)
    if (std::abs(es.eigenvalues()(k) - o.critical_multiplier) <
        std::abs(es.eigenvalues()(j) - o.critical_multiplier))
      j = k;
  const std::complex<double> mu = es.eigenvalues()(j);
  Eigen::VectorXcd v = es.eigenvectors().col(j);
  Eigen::Index largest = 0;
  v.cwiseAbs().maxCoeff(&largest);
  v *= std::conj(v(largest)) / std::abs(v(largest)) / std::abs(v(largest));
  const double eps = 1e-5 * scale;
  FlowOptions plain;
  plain.sensitivities = false;
  plain.relative_tolerance = 1e-11;
  plain.absolute_tolerance = 1e-14;
  const FlowResult base = integrate_flow(system, o.start, V, o.period_s, plain);
  const FlowResult moved = integrate_flow(system, o.start + eps * v.real(), V, o.period_s, plain);
  const Eigen::VectorXd measured = moved.end_state - base.end_state;
  const Eigen::VectorXd predicted = eps * (mu * v).real();
  const double misfit = (measured - predicted).norm() / predicted.norm();
  std::printf("[ S1002    ] perturbed run: mu %.6f%+.6fi; after one period |dx| / eps %.6e, "
              "predicted %.6e, misfit %.2e\n",
              mu.real(), mu.imag(), measured.norm() / eps, predicted.norm() / eps, misfit);
  EXPECT_LT(misfit, 1e-2);
}

// `bifurcation` without a cycle speed on profile contact starts the
// time-domain branch at 1.03 V_c (BifurcationOptions::default_cycle_start):
// on the thesis bogie (V_c 39.80 m/s) at 40.99 m/s, where a plain run from a
// 5 mm displacement settles on the flange-hunting cycle of docs/nonlinear.md
// (`railstab simulate cases/thesis_bogie_s1002_tangent.toml --speed 41
// --offset wheelset1.y_m=0.005 --t-end 12`: 5.18 mm, period 0.478 s). The
// branch's first orbit is that cycle: amplitude within 0.2 mm and period
// within 2 % of the plain run's at 41 m/s (0.01 m/s away), stable. Two
// orbits only; 20-60 s CPU.
TEST(ProfileContactOrbit, S1002BogieDefaultCycleStartFindsTheFlangeHuntingCycle) {
  const BifurcationResult r = default_start_run("thesis_bogie_s1002_tangent.toml", 30.0, 45.0, 2);
  ASSERT_TRUE(r.linear.critical_speed_found);
  EXPECT_TRUE(r.cycle_speed_default);
  EXPECT_NEAR(r.cycle_speed_m_per_s, kDefaultCycleSpeedRatio * r.linear.critical_speed_m_per_s, 1e-9);
  EXPECT_NEAR(r.cycle_speed_m_per_s, 40.99, 0.01);
  ASSERT_EQ(r.branches.size(), 1u);
  EXPECT_EQ(r.branches[0].origin, "time_domain");
  ASSERT_TRUE(r.branches[0].error.empty()) << r.branches[0].error;
  ASSERT_FALSE(r.branches[0].branch.orbits.empty());
  const PeriodicOrbit& first = r.branches[0].branch.orbits.front();
  EXPECT_NEAR(first.speed_m_per_s, r.cycle_speed_m_per_s, 1e-9);
  EXPECT_NEAR(first.amplitude(r.coords.amplitude_state), 5.18e-3, 0.2e-3);
  EXPECT_NEAR(first.period_s, 0.478, 0.02 * 0.478);
  EXPECT_TRUE(first.stable);
}

// The default start on the S1002 vehicle (V_c 118.53 m/s): at 1.03 V_c =
// 122.09 m/s the hunting is not periodic (docs/nonlinear.md), nor at 0.95
// and 0.95^2 of it; the settled runs' spreads, measured 19 %, 5 % and 1.9 %
// against the 1 % limit, lower the start each time, and at 0.95^3 x 122.09
// = 104.67 m/s (spread 0.13 %) the run settles on a flange-hunting cycle of
// 6.3 mm whose orbit is found: the branch starts where a periodic orbit
// exists, in seconds, where the first orbit at 122 m/s ran for 10 minutes
// without converging. About 45 s CPU (four 6 s runs, two orbits).
TEST(ProfileContactOrbit, S1002VehicleDefaultStartLowersItsSpeedToAPeriodicCycle) {
  const BifurcationResult r = default_start_run("thesis_vehicle_s1002_tangent.toml", 60.0, 150.0, 2);
  ASSERT_TRUE(r.linear.critical_speed_found);
  EXPECT_TRUE(r.cycle_speed_default);
  const double first_try = kDefaultCycleSpeedRatio * r.linear.critical_speed_m_per_s;
  ASSERT_EQ(r.cycle_speeds_not_periodic_m_per_s.size(), 3u);
  for (size_t k = 0; k < 3; ++k)
    EXPECT_NEAR(r.cycle_speeds_not_periodic_m_per_s[k], first_try * std::pow(kDefaultStartLowering, k),
                1e-9);
  EXPECT_NEAR(r.cycle_speed_m_per_s, first_try * std::pow(kDefaultStartLowering, 3), 1e-9);
  ASSERT_EQ(r.branches.size(), 1u);
  ASSERT_TRUE(r.branches[0].error.empty()) << r.branches[0].error;
  ASSERT_EQ(r.branches[0].branch.orbits.size(), 2u);
  const PeriodicOrbit& first = r.branches[0].branch.orbits.front();
  EXPECT_NEAR(first.speed_m_per_s, r.cycle_speed_m_per_s, 1e-9);
  EXPECT_NEAR(first.amplitude(r.coords.amplitude_state), 6.31e-3, 0.05e-3);
  EXPECT_TRUE(first.stable);
}

// The time-domain branch followed upwards in speed (`--cycle-direction up`):
// from the S1002 bogie's flange-hunting cycle at 41 m/s the second orbit
// lies 0.5 m/s above it and the third above that (the branch away from its
// fold at 34.99 m/s); the report says which way it went.
TEST(ProfileContactOrbit, S1002BogieCycleBranchCanBeFollowedUpwards) {
  const PreparedScene scene = prepare_scene(std::string(RAILSTAB_CASES_DIR) +
                                                "/thesis_bogie_s1002_tangent.toml",
                                            {});
  BifurcationOptions o = time_domain_branch_options(30.0, 45.0, 3);
  o.cycle_speed_m_per_s = 41.0;
  o.cycle_speed_step_m_per_s = cycle_speed_step_for("up", "--cycle-direction");
  const BifurcationResult r =
      analyse_bifurcation(scene.model, scene.equilibrium.state, scene.speed_m_per_s, o);
  EXPECT_TRUE(r.cycle_branch_upwards);
  ASSERT_EQ(r.branches.size(), 1u);
  ASSERT_TRUE(r.branches[0].error.empty()) << r.branches[0].error;
  const std::vector<PeriodicOrbit>& orbits = r.branches[0].branch.orbits;
  ASSERT_EQ(orbits.size(), 3u);
  EXPECT_NEAR(orbits[0].speed_m_per_s, 41.0, 1e-9);
  EXPECT_NEAR(orbits[1].speed_m_per_s, 41.5, 1e-9);
  EXPECT_GT(orbits[2].speed_m_per_s, orbits[1].speed_m_per_s);
  for (const PeriodicOrbit& orbit : orbits) EXPECT_TRUE(orbit.stable);
  o.cycle_speed_step_m_per_s = 0.0;  // no direction
  EXPECT_THROW(analyse_bifurcation(scene.model, scene.equilibrium.state, scene.speed_m_per_s, o),
               std::invalid_argument);
}

// Issue 22: the nonlinear critical speed of the thesis bogie on S1002/UIC60
// (32 states, linear critical speed 39.80 m/s) against the ramp method at
// two rates (expect_fold_in_the_ramps_bracket): the branch from the cycle a
// run from 5 mm settles on at 38 m/s (4.96 mm, |mu| 0.023) is stable down
// to its fold near 35.0 m/s (docs/nonlinear.md: 34.99 from the 41 m/s
// cycle, a flat fold). About 110 s CPU: 11 orbits and three failed
// correctors at the fold, and the ramps.
TEST(ProfileContactOrbit, S1002BogieFoldLiesWhereItsRampsTendAtZeroRate) {
  expect_fold_in_the_ramps_bracket("thesis_bogie_s1002_tangent.toml", "bogie", 20.0, 50.0, 30,
                                   38.0, 25.0);
}

// The same on the thesis vehicle (82 states, linear critical speed
// 118.53 m/s): the branch from the cycle a run from 5 mm settles on at
// 77 m/s (0.81 mm) is stable down to a fold at 75.89 m/s (`railstab
// bifurcation cases/thesis_vehicle_s1002_tangent.toml --cycle-speed 77
// --no-hopf-branch`, docs/nonlinear.md). The fold comes after 6-10 orbits,
// each 3-15 s CPU, and correctors that fail near it cost as much again.
TEST(ProfileContactOrbit, S1002VehicleFoldLiesWhereItsRampsTendAtZeroRate) {
  expect_fold_in_the_ramps_bracket("thesis_vehicle_s1002_tangent.toml", "vehicle", 60.0, 125.0, 16,
                                   77.0, 70.0);
}
