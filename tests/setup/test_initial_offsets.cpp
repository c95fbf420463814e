// --offset BODY.COORDINATE=VALUE (setup/initial_offsets.hpp): a run started
// with it is the run of the scene file with the same initial_offset written
// in it, bit for bit; a bogie frame's name moves its wheelsets too; bad
// settings are refused naming --offset.
#include <railstab/integrate/integrator.hpp>
#include <railstab/scene_reading/scene_error.hpp>
#include <railstab/setup/initial_offsets.hpp>
#include <railstab/setup/prepare_scene.hpp>

#include "support/test_files.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <regex>

using namespace railstab;
using railstab::test::case_path;
using railstab::test::fresh_dir;
using railstab::test::read_text;

namespace {

// The thesis bogie's scene text with wheelset1's initial_offset line replaced.
std::string bogie_scene_with(const std::string& wheelset1_offset, const std::string& extra_lines = "") {
  std::string text = read_text(case_path("thesis_bogie_tangent"));
  const std::string line = "initial_offset = { y_m = 0.001 }";
  const size_t at = text.find(line);
  EXPECT_NE(at, std::string::npos);
  text.replace(at, line.size(), wheelset1_offset);
  return text + extra_lines;
}

Trajectory short_run(const PreparedScene& scene) {
  IntegrationOptions opt = integration_options_for(scene.spec.simulation);
  opt.t_end_s = 0.5;
  return integrate(scene.model, scene.speed_m_per_s, perturbed_initial_state(scene), opt);
}

double largest_difference(const Trajectory& a, const Trajectory& b) {
  EXPECT_EQ(a.states.size(), b.states.size());
  double d = 0.0;
  for (size_t i = 0; i < std::min(a.states.size(), b.states.size()); ++i)
    d = std::max(d, (a.states[i] - b.states[i]).cwiseAbs().maxCoeff());
  return d;
}

}  // namespace

TEST(InitialOffsets, AnOffsetFlagRunIsTheRunWithTheOffsetInTheScene) {
  const auto dir = fresh_dir("offsets", "same_run");
  const std::string edited = (dir / "bogie.toml").string();
  std::ofstream(edited) << bogie_scene_with("initial_offset = { y_m = 0.004, yaw_rad = 0.001 }");
  const PreparedScene in_file = prepare_scene(edited, SceneOverrides{});

  SceneOverrides flags;
  flags.offsets = {parse_offset_setting("wheelset1.y_m=0.004"),
                   parse_offset_setting("wheelset1.yaw_rad=0.001")};
  const PreparedScene on_command_line = prepare_scene(case_path("thesis_bogie_tangent"), flags);
  EXPECT_EQ(on_command_line.spec.bodies[0].initial_offset, in_file.spec.bodies[0].initial_offset);
  // Bit-identical: the same numbers reach the same code (tolerance 0).
  EXPECT_EQ(largest_difference(short_run(on_command_line), short_run(in_file)), 0.0);
}

TEST(InitialOffsets, ABogieFrameNameMovesTheFrameAndItsWheelsets) {
  SceneOverrides flags;
  flags.offsets = {parse_offset_setting("bogie1.y_m=0.002")};
  const SceneSpec spec = load_scene_with_overrides(case_path("thesis_bogie_tangent"), flags);
  for (const BodySpec& b : spec.bodies) EXPECT_EQ(b.initial_offset[1], 0.002) << b.name;

  // The same as writing the three offsets into the file.
  const auto dir = fresh_dir("offsets", "bogie");
  const std::string edited = (dir / "bogie.toml").string();
  std::string text = bogie_scene_with("initial_offset = { y_m = 0.002 }");
  for (const std::string body : {"wheelset2", "bogie1"}) {
    const std::string name_line = "name = \"" + body + "\"";
    const size_t at = text.find(name_line);
    ASSERT_NE(at, std::string::npos);
    text.insert(at + name_line.size(), "\ninitial_offset = { y_m = 0.002 }");
  }
  std::ofstream(edited) << text;
  EXPECT_EQ(largest_difference(short_run(prepare_scene(case_path("thesis_bogie_tangent"), flags)),
                               short_run(prepare_scene(edited, SceneOverrides{}))),
            0.0);
}

TEST(InitialOffsets, BadSettingsNameTheFlagAndWhatWasExpected) {
  auto parse_error = [](const std::string& text) {
    try {
      parse_offset_setting(text);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(parse_error("wheelset1.y_m"),
            "--offset 'wheelset1.y_m': expected BODY.COORDINATE=VALUE, e.g. wheelset1.y_m=0.005 (no '=')");
  EXPECT_NE(parse_error("wheelset1.y=0.001").find("a coordinate key of initial_offset (x_m, y_m, z_m, "
                                                  "roll_rad, pitch_rad, yaw_rad), got 'y'"),
            std::string::npos);
  EXPECT_NE(parse_error("wheelset1.y_m=5mm").find("a finite number after '=' (m or rad), got '5mm'"),
            std::string::npos);
  EXPECT_NE(parse_error("wheelset1.y_m=nan").find("a finite number"), std::string::npos);
  EXPECT_NE(parse_error("y_m=0.1").find("no body name"), std::string::npos);

  SceneOverrides unknown;
  unknown.offsets = {parse_offset_setting("wheelset9.y_m=0.001")};
  try {
    load_scene_with_overrides(case_path("thesis_bogie_tangent"), unknown);
    FAIL() << "an unknown body was accepted";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("thesis_bogie_tangent.toml: --offset 'wheelset9.y_m=0.001': "
                                         "no body named 'wheelset9' (the scene's bodies: wheelset1, "
                                         "wheelset2, bogie1)"),
              std::string::npos)
        << e.what();
  }
  SceneOverrides too_far;
  too_far.offsets = {parse_offset_setting("wheelset1.y_m=2")};
  try {
    load_scene_with_overrides(case_path("thesis_bogie_tangent"), too_far);
    FAIL() << "a 2 m offset was accepted";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("--offset 'wheelset1.y_m=2': expected an initial offset in "
                                         "[-1, 1] m, got 2"),
              std::string::npos)
        << e.what();
  }
}
