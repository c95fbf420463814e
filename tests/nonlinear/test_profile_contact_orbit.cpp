// A hunting orbit on real profiles (S1002 on UIC60 1:40, contact tables C1
// between their nodes, flange contact): the thesis bogie's flange-hunting
// cycle at 45 m/s (linear critical speed 39.80 m/s), found as the
// `bifurcation --cycle-speed` start does (a time-domain run settles, its last
// period is the guess, damped Newton at fixed speed), checked against
// references that do not use the shooting code:
// - the settled time-domain run itself: after 14 periods whose transient
//   decays with the orbit's largest multiplier (~0.23 per period), its last
//   period's excursion and period equal the orbit's;
// - a plain run (integrate(), CVODE BDF, rtol 1e-10) from the orbit's start
//   returns to it after one period;
// - the orbit's stability (largest multiplier inside the unit circle) agrees
//   with that run settling on it.
#include <gtest/gtest.h>

#include <railstab/equilibrium/speed_continuation.hpp>
#include <railstab/integrate/integrator.hpp>
#include <railstab/nonlinear/model_orbits.hpp>
#include <railstab/nonlinear/periodic_orbit.hpp>
#include <railstab/setup/prepare_scene.hpp>

#include <cstdio>
#include <string>
#include <vector>

using namespace railstab;

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
}
