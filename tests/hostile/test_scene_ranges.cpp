// Issue 10, scene half: every kind of physical number is refused outside its
// plausible range (scene/physical_ranges.hpp) with the key and the range in
// the message; values at the limits are accepted; names are restricted to a
// documented set; the stored-output count is bounded by the reader, naming
// the key; e0 and D must agree; --arc-length is blamed on the flag.
#include <gtest/gtest.h>

#include <railstab/scene_reading/load_scene.hpp>
#include <railstab/scene/physical_ranges.hpp>
#include <railstab/setup/prepare_scene.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace railstab;

namespace {

const std::string kCase = std::string(RAILSTAB_CASES_DIR) + "/thesis_bogie_tangent.toml";
const std::string kSource = "ranges.toml";

std::string case_text() {
  std::ifstream in(kCase);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The case with the first `original` replaced (it must occur).
std::string with(const std::string& original, const std::string& replacement) {
  std::string text = case_text();
  const size_t at = text.find(original);
  if (at == std::string::npos) throw std::logic_error("not in the case: " + original);
  return text.replace(at, original.size(), replacement);
}

std::string error_of(const std::string& text) {
  try {
    load_scene_text(text, kSource);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

struct RangeCase {
  std::string original, replacement, expected;  // expected: a fragment of the message
};

}  // namespace

// One value outside its range per kind of number; the message names the
// file, the key path, the range and the value.
TEST(SceneRanges, EachKindOutsideItsRangeIsRefusedWithKeyAndRange) {
  const std::vector<RangeCase> cases = {
      {"mass_kg = 1500.0", "mass_kg = 1e-300",
       "ranges.toml: bodies[0].mass_kg: expected a mass in [0.1, 1e+06] kg, got 1e-300"},
      {"mass_kg = 3020.0", "mass_kg = 1e7", "bodies[2].mass_kg: expected a mass in [0.1"},
      {"inertia_kg_m2 = [799.35, 93.75, 799.35]", "inertia_kg_m2 = [799.35, 1e9, 799.35]",
       "bodies[0].inertia_kg_m2[1]: expected a principal moment of inertia in [1e-04, 1e+08] "
       "kg m2, got 1e+09"},
      {"stiffness_N_per_m = [3.9e7, 7.85e6, 9.75e5]", "stiffness_N_per_m = [1e20, 7.85e6, 9.75e5]",
       "elements[0].stiffness_N_per_m[0]: expected a stiffness in [0, 1e+11] N/m, got 1e+20"},
      {"damping_N_s_per_m = [0.0, 0.0, 1.08e4]", "damping_N_s_per_m = [0.0, 0.0, 1e12]",
       "elements[0].damping_N_s_per_m[2]: expected a damping in [0, 1e+08] N s/m"},
      {"normal_damping_N_s_per_m = 0.0", "normal_damping_N_s_per_m = 1e12",
       "contacts.thesis_knife_edge.normal_damping_N_s_per_m: expected a damping in [0, 1e+08]"},
      {"point2_m = [1.5, 1.0, -0.6075]", "point2_m = [1e308, 1.0, -0.6075]",
       "elements[0].point2_m[0]: expected a coordinate in [-100, 100] m, got 1e+308"},
      {"wheel_young_modulus_Pa = 2.1e11", "wheel_young_modulus_Pa = 1",
       "contacts.thesis_knife_edge.wheel_young_modulus_Pa: expected a Young's modulus in "
       "[1e+08, 1e+14] Pa, got 1"},
      {"nominal_rolling_radius_m = 0.45", "nominal_rolling_radius_m = 45",
       "nominal_rolling_radius_m: expected a rolling radius in [0.05, 3] m, got 45"},
      {"rail_head_transverse_radius_m = 0.30", "rail_head_transverse_radius_m = 1e-9",
       "rail_head_transverse_radius_m: expected a rail head radius in [0.001, 1000] m"},
      {"speed_m_per_s = 20.0", "speed_m_per_s = 1e6",
       "scene.speed_m_per_s: expected a speed in [0, 300] m/s, got 1e+06"},
      {"length_m = 1000.0", "length_m = 1e9",
       "track.segments[0].length_m: expected a segment length in [0.001, 1e+06] m"},
      {"end_radius_m = 1000.0", "end_radius_m = 0.5",
       "track.segments[1].end_radius_m: expected a curve radius in [5, 1e+08] m"},
      {"track_offset_m = -3.0", "track_offset_m = -1e5",
       "bodies[1].track_offset_m: expected a track offset in [-10000, 10000] m"},
      {"position_m = [0.0, 0.0, 1.0575]", "position_m = [0.0, 0.0, 1e5]",
       "bodies[2].position_m[2]: expected a coordinate in [-100, 100] m"},
      {"initial_offset = { y_m = 0.001 }", "initial_offset = { y_m = 2.0 }",
       "bodies[0].initial_offset.y_m: expected an initial offset in [-1, 1] m, got 2"},
      {"initial_offset = { y_m = 0.001 }", "initial_rate = { yaw_rad_per_s = 1e4 }",
       "bodies[0].initial_rate.yaw_rad_per_s: expected an initial rate in [-1000, 1000] rad/s"},
      {"relative_tolerance = 1.0e-3", "relative_tolerance = 1e-20",
       "simulation.relative_tolerance: expected a relative tolerance in [1e-14, 1], got 1e-20"},
      {"absolute_tolerance = 1.0e-6", "absolute_tolerance = 5",
       "simulation.absolute_tolerance: expected an absolute tolerance in [1e-20, 1]"},
      {"output_interval_s = 0.01", "output_interval_s = 1e-12",
       "simulation.output_interval_s: expected an output interval in [1e-07, 1000] s, got 1e-12"},
      {"t_end_s = 20.0", "t_end_s = 1e20",
       "simulation.t_end_s: expected an end time in (0, 1e+05] s, got 1e+20"},
      {"gravity_m_per_s2 = 9.81", "gravity_m_per_s2 = 981",
       "scene.gravity_m_per_s2: expected a gravity in [0, 100] m/s2"},
      {"rail_contact_distance_m = 1.5", "rail_contact_distance_m = 150",
       "track.rail_contact_distance_m: expected a rail contact distance in [0.2, 4] m"},
      {"reference_arc_length_m = 100.0", "reference_arc_length_m = 1e12",
       "scene.reference_arc_length_m: expected an arc length in [0, 1e+07] m"},
  };
  for (const RangeCase& c : cases) {
    const std::string message = error_of(with(c.original, c.replacement));
    EXPECT_NE(message.find(c.expected), std::string::npos)
        << c.replacement << "\n  message: " << message << "\n  expected: " << c.expected;
  }
}

// The limits themselves are inside (a range test that cannot fail would
// accept everything; this one shows the bounds are where the header says).
TEST(SceneRanges, ValuesAtTheLimitsAreAccepted) {
  namespace r = physical_ranges;
  auto ok = [](const std::string& text) {
    try {
      load_scene_text(text, kSource);
      return std::string();
    } catch (const SceneError& e) {
      return std::string(e.what());
    }
  };
  EXPECT_EQ(ok(with("mass_kg = 3020.0", "mass_kg = 1e6")), "");
  EXPECT_EQ(ok(with("mass_kg = 3020.0", "mass_kg = 0.1")), "");
  EXPECT_EQ(ok(with("stiffness_N_per_m = [3.9e7, 7.85e6, 9.75e5]",
                    "stiffness_N_per_m = [1e11, 0.0, 9.75e5]")),
            "");
  EXPECT_EQ(ok(with("wheel_young_modulus_Pa = 2.1e11", "wheel_young_modulus_Pa = 1e8")), "");
  EXPECT_EQ(ok(with("speed_m_per_s = 20.0", "speed_m_per_s = 300")), "");
  EXPECT_TRUE(r::mass_kg.contains(0.1) && !r::mass_kg.contains(0.0999));
  EXPECT_TRUE(r::flange_clearance_m.contains(1e-9) && !r::flange_clearance_m.contains(0.0));
}

TEST(SceneRanges, StoredOutputsAreBoundedByTheReaderNamingTheKey) {
  // 20 s every 1e-5 s: 2e6 outputs, twice the limit; each value alone is in range.
  const std::string message = error_of(with("output_interval_s = 0.01", "output_interval_s = 1e-5"));
  EXPECT_NE(message.find("ranges.toml: simulation.output_interval_s: expected at most 1e+06 "
                         "stored outputs"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("t_end_s = 20 s / output_interval_s = 1e-05 s = 2e+06 outputs"),
            std::string::npos)
      << message;
  EXPECT_EQ(error_of(with("output_interval_s = 0.01", "output_interval_s = 2e-5")), "");
}

// Issue 10: "a body placed at y = -1 m" failed deep in the Hertz contact.
TEST(SceneRanges, WheelsetsMustSitOnTheRails) {
  std::string message =
      error_of(with("position_m = [0.0, 0.0, 0.45]", "position_m = [0.0, -1.0, 0.45]"));
  EXPECT_NE(message.find("bodies[0].position_m[1]: expected a wheelset's nominal lateral "
                         "position within the flange clearance of the track centre, [-0.0075, "
                         "0.0075] m"),
            std::string::npos)
      << message;
  message = error_of(with("position_m = [0.0, 0.0, 0.45]", "position_m = [0.0, 0.0, 0.9]"));
  EXPECT_NE(message.find("bodies[0].position_m[2]: expected a wheelset's axle height at its "
                         "rolling radius above the rail plane, 0.45 m within 10 %"),
            std::string::npos)
      << message;
  EXPECT_EQ(error_of(with("position_m = [0.0, 0.0, 0.45]", "position_m = [0.0, 0.007, 0.46]")), "");
}

TEST(SceneRanges, HalfContactDistanceMustMatchTheRailContactDistance) {
  const std::string message =
      error_of(with("half_contact_distance_m = 0.75", "half_contact_distance_m = 0.5"));
  EXPECT_NE(message.find("contacts.thesis_knife_edge.half_contact_distance_m: expected half of "
                         "track.rail_contact_distance_m = 1.5 m within 5 %"),
            std::string::npos)
      << message;
  EXPECT_EQ(error_of(with("half_contact_distance_m = 0.75", "half_contact_distance_m = 0.76")), "");
}

// Names: any printable UTF-8 up to 100 bytes (commas, quotes, umlauts are
// escaped by the writers); control characters and longer names are refused
// (a control character printed in a message is a terminal command).
TEST(SceneRanges, NamesAreRestrictedToPrintableTextOfBoundedLength) {
  EXPECT_EQ(error_of(with("name = \"thesis_bogie_tangent\"", "name = \"Drehgestell \\u00e4, \\\"1\\\" |x\"")), "");
  std::string message = error_of(with("name = \"bogie1\"", "name = \"bogie\\u001b[2J\""));
  EXPECT_NE(message.find("bodies[2].name: expected a name of 1 to 100 bytes without control "
                         "characters, got a control character (0x1B) at byte 5"),
            std::string::npos)
      << message;
  message = error_of(with("name = \"bogie1\"", "name = \"b\\u0085\""));  // C1 NEL
  EXPECT_NE(message.find("got a control character (0x85)"), std::string::npos) << message;
  message = error_of(with("name = \"thesis_bogie_tangent\"",
                          "name = \"" + std::string(101, 'n') + "\""));
  EXPECT_NE(message.find("scene.name: expected a name of 1 to 100 bytes without control "
                         "characters, got a name of 101 bytes"),
            std::string::npos)
      << message;
  message = error_of(with("name = \"primary_ws1\"", "name = \"p\\tq\""));
  EXPECT_NE(message.find("elements[0].name: expected a name of 1 to 100 bytes"), std::string::npos)
      << message;
}

TEST(SceneRanges, EveryCaseFileIsInsideTheRanges) {
  for (const auto& entry : std::filesystem::directory_iterator(RAILSTAB_CASES_DIR)) {
    if (entry.path().extension() != ".toml") continue;
    std::ifstream in(entry.path());
    std::stringstream s;
    s << in.rdbuf();
    if (s.str().find("\n[scene]") == std::string::npos) continue;  // a contact-geometry file
    EXPECT_NO_THROW(load_scene_file(entry.path().string())) << entry.path();
  }
}

// --arc-length that puts a body off the track is blamed on the flag, not on
// bodies[0].track_offset_m (which the user did not change).
TEST(SceneRanges, ArcLengthOverrideIsBlamedOnTheFlag) {
  SceneOverrides overrides;
  overrides.reference_arc_length_m = 5000.0;  // track 4200 m, offsets -3 .. 0 m
  try {
    prepare_scene(kCase, overrides);
    ADD_FAILURE() << "expected a SceneError";
  } catch (const SceneError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(kCase + ": --arc-length: expected an arc length in [3, 4200] m (the "
                                   "track is 4200 m long"),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("got 5000"), std::string::npos) << message;
    EXPECT_EQ(message.find("track_offset_m:"), std::string::npos) << message;
  }
}
