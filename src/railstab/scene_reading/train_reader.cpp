#include <railstab/scene_reading/train_reader.hpp>

#include <railstab/scene/train.hpp>
#include <railstab/scene_reading/elements_reader.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

namespace railstab::scene_reading {

namespace {

constexpr int kMaxTrainCars = 64;

struct TrainExpansion {
  SceneSpec scene;
  std::vector<std::string> element_paths;
};

TrainExpansion expand_train(const TableReader& train, SceneSpec vehicle,
                            std::vector<std::string> vehicle_element_paths) {
  TrainSpec spec;
  const double cars = train.number("cars", "");
  if (!(cars >= 1 && cars <= kMaxTrainCars && cars == std::floor(cars)))
    train.fail("cars", "a whole number of cars from 1 to " + std::to_string(kMaxTrainCars),
               format_number(cars));
  spec.cars = int(cars);
  spec.car_spacing_m = train.number("car_spacing_m", "m");
  if (!(spec.car_spacing_m > 0.0 && spec.car_spacing_m <= 1000.0))
    train.fail("car_spacing_m",
               "the distance along the track between the same point of two consecutive cars, "
               "in (0, 1000] m",
               format_number(spec.car_spacing_m));
  ElementList couplers = read_element_tables(train, "couplers");
  std::vector<std::string> names;
  for (const BodySpec& body : vehicle.bodies) names.push_back(body.name);
  for (size_t i = 0; i < couplers.specs.size(); ++i) {
    const ElementEnds& e = ends_of(couplers.specs[i]);
    for (const auto& [key, body] : {std::pair<const char*, const std::string*>{"body1", &e.body1_name},
                                    {"body2", &e.body2_name}})
      if (std::find(names.begin(), names.end(), *body) == names.end())
        throw scene_error(train.source(), child_path(couplers.file_paths[i], key),
                          "unknown body " + quoted(*body) + " (a coupler joins bodies of the " +
                              "vehicle: " + comma_separated(names) + ")");
  }
  spec.couplers = std::move(couplers.specs);
  TrainExpansion out{make_train(vehicle, spec), {}};
  for (int car = 1; car <= spec.cars; ++car)
    out.element_paths.insert(out.element_paths.end(), vehicle_element_paths.begin(),
                             vehicle_element_paths.end());
  for (int car = 1; car < spec.cars; ++car)
    out.element_paths.insert(out.element_paths.end(), couplers.file_paths.begin(),
                             couplers.file_paths.end());
  return out;
}

}  // namespace

void read_train(const TableReader& top, SceneSpec& scene, std::vector<std::string>& element_paths) {
  const std::optional<TableReader> train =
      top.optional_table("train", {"cars", "car_spacing_m", "couplers"});
  if (!train) return;
  TrainExpansion expanded = expand_train(*train, std::move(scene), std::move(element_paths));
  scene = std::move(expanded.scene);
  element_paths = std::move(expanded.element_paths);
}

}  // namespace railstab::scene_reading
