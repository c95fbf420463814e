// Trains of coupled vehicles (scene/train.hpp, [train] in a scene file):
//  - a one-car train is the vehicle: the same critical speed (the thesis
//    vehicle's 111.46 m/s) to round-off;
//  - two cars without couplers are two independent vehicles: the train's
//    spectrum is the vehicle's with every eigenvalue twice;
//  - with buffers (cases/thesis_train_4.toml) on tangent track the buffers
//    carry nothing at the steady state, so every car sits where the lone
//    vehicle does (the equal-and-opposite buffer forces vanish only there);
//  - bad [train] input is refused naming the key.
// The Jacobian pattern of the train against dense AD, bit for bit, is in
// tests/linear/test_jacobian_pattern.cpp (every scene in cases/).
#include <railstab/eigen/eigen_analysis.hpp>
#include <railstab/io/regular_file.hpp>
#include <railstab/scene_reading/load_scene.hpp>
#include <railstab/linear/linearization.hpp>
#include <railstab/scene/train.hpp>
#include <railstab/setup/prepare_scene.hpp>
#include <railstab/stability/speed_analysis.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include "support/test_files.hpp"

using namespace railstab;

namespace {

using railstab::test::case_path;

std::string vehicle_text() { return read_regular_file(case_path("thesis_vehicle_tangent")); }

SceneSpec vehicle_with_train(const std::string& train_section) {
  return load_scene_text(vehicle_text() + "\n" + train_section, "train_test.toml");
}

CriticalSpeedResult critical_speed(const PreparedScene& s) {
  CriticalSpeedOptions opt;
  opt.from_m_per_s = 60.0;
  opt.to_m_per_s = 120.0;
  opt.grid_step_m_per_s = 5.0;
  return find_critical_speed(s.model, s.equilibrium.state, s.speed_m_per_s, opt);
}

std::string load_error(const std::string& train_section) {
  try {
    vehicle_with_train(train_section);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST(Train, OneCarTrainIsTheVehicle) {
  const PreparedScene vehicle = prepare_scene(case_path("thesis_vehicle_tangent"), {});
  const PreparedScene train = prepare_scene(vehicle_with_train("[train]\ncars = 1\ncar_spacing_m = 26.0\n"));
  ASSERT_EQ(train.model.state_size(), vehicle.model.state_size());
  EXPECT_EQ(train.model.bodies.front().name, "car1_wheelset1");
  const CriticalSpeedResult a = critical_speed(vehicle), b = critical_speed(train);
  ASSERT_TRUE(a.critical_speed_found && b.critical_speed_found);
  EXPECT_NEAR(a.critical_speed_m_per_s, 111.46, 0.01);
  // Same equations in the same order: equal to round-off.
  EXPECT_NEAR(b.critical_speed_m_per_s, a.critical_speed_m_per_s, 1e-9);
}

TEST(Train, UncoupledCarsRepeatTheVehicleSpectrum) {
  const PreparedScene vehicle = prepare_scene(case_path("thesis_vehicle_tangent"), {});
  const PreparedScene train = prepare_scene(vehicle_with_train("[train]\ncars = 2\ncar_spacing_m = 26.0\n"));
  const double V = 80.0;
  SpeedStability sv(vehicle.model, vehicle.equilibrium.state, vehicle.speed_m_per_s);
  SpeedStability st(train.model, train.equilibrium.state, train.speed_m_per_s);
  StabilityOptions dense;
  dense.solver = EigenSolverKind::dense;
  const std::vector<EigenPair> ev = eigen_dense(sv.at(V).linear.A);
  const std::vector<EigenPair> et = eigen_dense(st.at(V).linear.A);
  ASSERT_EQ(et.size(), 2 * ev.size());
  // Every vehicle eigenvalue twice among the train's (greedy pairing in
  // order; the two copies of a double root differ at round-off of A's
  // ~1e9 entries times a modest condition number).
  std::vector<bool> used(et.size(), false);
  for (const EigenPair& p : ev)
    for (int copy = 0; copy < 2; ++copy) {
      int best = -1;
      double best_d = 1e300;
      for (size_t j = 0; j < et.size(); ++j)
        if (!used[j] && std::abs(et[j].value - p.value) < best_d) {
          best_d = std::abs(et[j].value - p.value);
          best = int(j);
        }
      ASSERT_GE(best, 0);
      used[size_t(best)] = true;
      EXPECT_LE(best_d, 1e-6 * std::max(1.0, std::abs(p.value))) << p.value;
    }
}

TEST(Train, BuffersCarryNothingAtTheSteadyStateOnTangent) {
  const PreparedScene vehicle = prepare_scene(case_path("thesis_vehicle_tangent"), SceneOverrides::at_speed(60.0));
  const PreparedScene train = prepare_scene(case_path("thesis_train_4"), SceneOverrides::at_speed(60.0));
  ASSERT_EQ(train.model.bodies.size(), 4 * vehicle.model.bodies.size());
  ASSERT_EQ(train.model.n_coordinates, 4 * vehicle.model.n_coordinates);
  const int n = vehicle.model.n_coordinates, nt = train.model.n_coordinates;
  // Car k's coordinates are the vehicle's (bodies in the same order).
  for (int car = 0; car < 4; ++car)
    for (int k = 0; k < n; ++k) {
      EXPECT_NEAR(train.equilibrium.state(car * n + k), vehicle.equilibrium.state(k), 1e-9)
          << train.model.state_name(car * n + k);
      EXPECT_NEAR(train.equilibrium.state(nt + car * n + k), vehicle.equilibrium.state(n + k),
                  1e-9 * std::max(1.0, std::abs(vehicle.equilibrium.state(n + k))))
          << train.model.state_name(nt + car * n + k);
    }
}

TEST(Train, BadTrainInputIsRefusedNamingTheKey) {
  EXPECT_NE(load_error("[train]\ncars = 0\ncar_spacing_m = 26.0\n").find("train.cars"),
            std::string::npos);
  EXPECT_NE(load_error("[train]\ncars = 2.5\ncar_spacing_m = 26.0\n").find("whole number"),
            std::string::npos);
  EXPECT_NE(load_error("[train]\ncars = 2\ncar_spacing_m = -1.0\n").find("train.car_spacing_m"),
            std::string::npos);
  EXPECT_NE(load_error("[train]\ncars = 2\n").find("train.car_spacing_m"), std::string::npos);
  const std::string unknown_body = load_error(
      "[train]\ncars = 2\ncar_spacing_m = 26.0\n[[train.couplers]]\nname = \"c\"\n"
      "type = \"spring_damper_3d\"\nbody1 = \"carbody\"\nbody2 = \"car_body\"\n"
      "point1_m = [-13.0, 0.0, 0.0]\npoint2_m = [13.0, 0.0, 0.0]\n"
      "stiffness_N_per_m = [1.0, 1.0, 1.0]\ndamping_N_s_per_m = [0.0, 0.0, 0.0]\n");
  EXPECT_NE(unknown_body.find("train.couplers[0].body2"), std::string::npos) << unknown_body;
  EXPECT_NE(unknown_body.find("'car_body'"), std::string::npos) << unknown_body;
  // 20 cars of 26 m do not fit behind the reference at 100 m.
  const std::string off_track = load_error("[train]\ncars = 20\ncar_spacing_m = 26.0\n");
  EXPECT_NE(off_track.find("track_offset_m"), std::string::npos) << off_track;
  EXPECT_NE(load_error("[train]\ncars = 2\ncar_spacing_m = 26.0\nwagons = 3\n").find("train.wagons"),
            std::string::npos);
}

TEST(Train, MakeTrainNamesAndPlacesTheCars) {
  const SceneSpec vehicle = load_scene_text(vehicle_text(), "v.toml");
  TrainSpec t;
  t.cars = 3;
  t.car_spacing_m = 26.0;
  SpringDamper3d<double> buffer;
  buffer.ends.name = "buffer";
  buffer.ends.body1_name = "carbody";
  buffer.ends.body2_name = "carbody";
  t.couplers.push_back(buffer);
  const SceneSpec train = make_train(vehicle, t);
  ASSERT_EQ(train.bodies.size(), 3 * vehicle.bodies.size());
  ASSERT_EQ(train.elements.size(), 3 * vehicle.elements.size() + 2);
  const BodySpec& last = train.bodies[2 * vehicle.bodies.size()];
  EXPECT_EQ(last.name, "car3_" + vehicle.bodies[0].name);
  EXPECT_DOUBLE_EQ(last.track_offset_m, vehicle.bodies[0].track_offset_m - 52.0);
  EXPECT_EQ(last.initial_offset[1], 0.0);  // disturbance on car 1 only
  EXPECT_EQ(train.bodies[0].initial_offset[1], vehicle.bodies[0].initial_offset[1]);
  const ElementEnds& c = ends_of(train.elements.back());
  EXPECT_EQ(c.name, "car2_car3_buffer");
  EXPECT_EQ(c.body1_name, "car2_carbody");
  EXPECT_EQ(c.body2_name, "car3_carbody");
  t.cars = 0;
  EXPECT_THROW(make_train(vehicle, t), std::invalid_argument);
}
