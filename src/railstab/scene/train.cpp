#include <railstab/scene/train.hpp>

#include <algorithm>
#include <stdexcept>

namespace railstab {

namespace {

bool has_body(const SceneSpec& scene, const std::string& name) {
  return std::any_of(scene.bodies.begin(), scene.bodies.end(),
                     [&](const BodySpec& b) { return b.name == name; });
}

std::string coupler_name(int car_ahead, const std::string& name) {
  return "car" + std::to_string(car_ahead) + "_car" + std::to_string(car_ahead + 1) + "_" + name;
}

}  // namespace

std::string car_body_name(int car, const std::string& name) {
  return "car" + std::to_string(car) + "_" + name;
}

SceneSpec make_train(const SceneSpec& vehicle, const TrainSpec& train) {
  if (train.cars < 1)
    throw std::invalid_argument("make_train: cars must be at least 1, got " +
                                std::to_string(train.cars));
  if (!(train.car_spacing_m > 0.0))
    throw std::invalid_argument("make_train: car_spacing_m must be > 0, got " +
                                std::to_string(train.car_spacing_m));
  for (const ElementSpec& coupler : train.couplers) {
    const ElementEnds& e = ends_of(coupler);
    for (const std::string* body : {&e.body1_name, &e.body2_name})
      if (!has_body(vehicle, *body))
        throw std::invalid_argument("make_train: coupler '" + e.name + "' names body '" + *body +
                                    "', which the vehicle does not have");
  }
  SceneSpec scene = vehicle;
  scene.bodies.clear();
  scene.elements.clear();
  for (int car = 1; car <= train.cars; ++car) {
    const double shift_m = double(car - 1) * train.car_spacing_m;
    for (BodySpec body : vehicle.bodies) {
      body.name = car_body_name(car, body.name);
      body.track_offset_m -= shift_m;
      if (car > 1) {
        body.initial_offset = {0, 0, 0, 0, 0, 0};
        body.initial_rate = {0, 0, 0, 0, 0, 0};
      }
      scene.bodies.push_back(std::move(body));
    }
    for (ElementSpec element : vehicle.elements) {
      ElementEnds& e = ends_of(element);
      e.name = car_body_name(car, e.name);
      if (e.body1_name != kTrackBodyName) e.body1_name = car_body_name(car, e.body1_name);
      e.body2_name = car_body_name(car, e.body2_name);
      scene.elements.push_back(std::move(element));
    }
  }
  for (int car = 1; car < train.cars; ++car)
    for (ElementSpec coupler : train.couplers) {
      ElementEnds& e = ends_of(coupler);
      e.name = coupler_name(car, e.name);
      e.body1_name = car_body_name(car, e.body1_name);
      e.body2_name = car_body_name(car + 1, e.body2_name);
      scene.elements.push_back(std::move(coupler));
    }
  return scene;
}

}  // namespace railstab
