#pragma once
// A train: N copies of one vehicle one behind the other on the track, the
// cars joined by couplers (any force element kind; buffers and draw gear are
// usually spring_damper_3d pairs at the car body ends).
//
// Car k (1 = leading) is the vehicle with every body's track offset moved
// back by (k - 1) * car_spacing_m: the same point of two consecutive cars is
// car_spacing_m apart along the track (T frames; a curve bends the train the
// way it bends one car's bogies). Bodies and elements of car k are named
// "car<k>_<name>"; a coupler joins body1 of car k (the car ahead) and body2 of
// car k + 1 (the car behind) and is named "car<k>_car<k+1>_<name>", its
// points in the frames of those bodies as for any element. Contacts are
// shared (they describe the wheel-rail pair, not a body). The vehicle's
// initial offsets and rates (the disturbance of a time-domain run) are kept
// on car 1 only: the train is disturbed at its head, the other cars start
// from the steady state.
//
// A one-car train is the vehicle with renamed bodies: same equations, same
// eigenvalues (tests/scene/test_train.cpp).
#include <railstab/scene/scene_spec.hpp>

#include <string>
#include <vector>

namespace railstab {

struct TrainSpec {
  int cars = 1;
  double car_spacing_m = 0.0;  // along the track, car k to car k + 1 (> 0)
  // body1/body2: names of bodies of the vehicle (body1 in the car ahead,
  // body2 in the car behind); never "track".
  std::vector<ElementSpec> couplers;
};

// The body or element name of `name` in car `car` (1-based).
std::string car_body_name(int car, const std::string& name);

// The train's scene from the vehicle's. Throws std::invalid_argument for
// cars < 1, car_spacing_m <= 0 or a coupler naming a body the vehicle does
// not have (or "track"); the scene loader reports those against the file's
// keys before calling this.
SceneSpec make_train(const SceneSpec& vehicle, const TrainSpec& train);

}  // namespace railstab
