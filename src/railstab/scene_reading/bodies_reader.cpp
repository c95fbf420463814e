#include <railstab/scene_reading/bodies_reader.hpp>

#include <railstab/bodies/body.hpp>
#include <railstab/core/coordinates.hpp>

#include <optional>

namespace railstab::scene_reading {

namespace {

// The body kinds' own names (bodies/body.hpp kName).
const Choices<bool> kBodyIsWheelset = {{WheelsetKind::kName, true}, {RigidBodyKind::kName, false}};

// free = ["y", "yaw"] -> which of the six coordinates move.
std::array<bool, 6> read_free_coordinates(const TableReader& body) {
  Choices<int> coordinates;
  for (int c = 0; c < kCoordinatesPerBody; ++c) coordinates.push_back({kCoordinateKeys[c], c});
  const toml::array& names =
      body.array("free", "an array of coordinate names such as [\"y\", \"yaw\"]");
  std::array<bool, 6> free = {false, false, false, false, false, false};
  for (size_t i = 0; i < names.size(); ++i) {
    const std::string path = indexed_path(body.path_of("free"), i);
    const int c = choice_from(*names.get(i), body.source(), path, coordinates);
    if (free[c])
      fail_expectation(body.source(), path, "each coordinate at most once",
                       quoted(kCoordinateKeys[c]) + " a second time");
    free[c] = true;
  }
  return free;
}

// initial_offset = { y_m = 0.001 } and initial_rate = { yaw_rad_per_s = 0.1 }:
// one optional number per coordinate (kOffsetKeys, kRateKeys).
std::array<double, 6> read_coordinate_values(const TableReader& body, std::string_view table_key,
                                             const std::array<CoordinateKey, 6>& keys) {
  std::vector<std::string_view> known_keys;
  for (const CoordinateKey& key : keys) known_keys.push_back(key.key);
  const std::optional<TableReader> table = body.optional_table(table_key, known_keys);
  std::array<double, 6> values = {0, 0, 0, 0, 0, 0};
  if (!table) return values;
  for (int c = 0; c < kCoordinatesPerBody; ++c)
    values[c] = table->number_or(keys[c].key, keys[c].unit, 0.0);
  return values;
}

// [[bodies.measure_points]]: name and position_m (from the CM, body axes);
// only on rigid bodies: a wheelset's body frame spins.
std::vector<MeasurePointSpec> read_measure_points(const TableReader& body, bool is_wheelset) {
  std::vector<MeasurePointSpec> points;
  if (!body.has("measure_points")) return points;
  if (is_wheelset)
    body.fail("measure_points",
              "no measure points on a wheelset (its frame spins; put them on the bogie frame)",
              "a measure_points array");
  for (const TableReader& point : body.tables_in_array("measure_points", {"name", "position_m"})) {
    MeasurePointSpec spec;
    spec.name = point.text("name");
    spec.position_m = point.vector3("position_m", "m");
    for (const MeasurePointSpec& earlier : points)
      if (earlier.name == spec.name)
        point.fail("name", "a measure point name unique within the body", quoted(spec.name) + " twice");
    points.push_back(spec);
  }
  return points;
}

BodySpec read_body(const TableReader& body) {
  BodySpec spec;
  spec.name = body.text("name");
  spec.is_wheelset = body.choice("type", kBodyIsWheelset);
  spec.mass_kg = body.number("mass_kg", "kg");
  spec.inertia_kg_m2 = body.vector3("inertia_kg_m2", "kg m2");
  spec.track_offset_m = body.number_or("track_offset_m", "m", 0.0);
  spec.position_m = body.vector3("position_m", "m");
  if (body.has("free")) spec.free = read_free_coordinates(body);
  if (spec.is_wheelset && !body.has("contact"))
    body.fail_missing("contact",
                      "the name of a [contacts.<name>] table (every wheelset needs one)");
  if (spec.is_wheelset)
    spec.contact = body.text("contact");
  else
    body.reject_if_present("contact",
                           "no contact on a rigid_body (only wheelsets touch the rails)");
  spec.initial_offset = read_coordinate_values(body, "initial_offset", kOffsetKeys);
  spec.initial_rate = read_coordinate_values(body, "initial_rate", kRateKeys);
  spec.measure_points = read_measure_points(body, spec.is_wheelset);
  return spec;
}

}  // namespace

std::vector<BodySpec> read_bodies(const TableReader& top) {
  std::vector<BodySpec> bodies;
  for (const TableReader& body : top.tables_in_array(
           "bodies", {"name", "type", "mass_kg", "inertia_kg_m2", "track_offset_m", "position_m",
                      "free", "contact", "initial_offset", "initial_rate", "measure_points"}))
    bodies.push_back(read_body(body));
  return bodies;
}

}  // namespace railstab::scene_reading
