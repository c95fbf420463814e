// --set KEY=VALUE: the value lands where the key path says (checked through
// the sensitivity module's parameter keys, which name the same values), a
// scene read with --set equals the scene whose file was edited (same
// critical speed to the last bit), and each bad setting is refused with a
// message naming the flag, the key and what is wrong.
#include <gtest/gtest.h>

#include <railstab/io/regular_file.hpp>
#include <railstab/scene_reading/load_scene.hpp>
#include <railstab/scene_reading/scene_set_values.hpp>
#include <railstab/sensitivity/parameter_derivative.hpp>
#include <railstab/setup/prepare_scene.hpp>
#include <railstab/stability/speed_analysis.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

using namespace railstab;

namespace {

const std::string kTextbook = std::string(RAILSTAB_CASES_DIR) + "/textbook_wheelset.toml";

std::string error_of(const std::vector<SceneValueSetting>& settings) {
  try {
    load_scene_file(kTextbook, settings);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

double critical_speed_of(const SceneSpec& spec) {
  const PreparedScene s = prepare_scene(spec);
  CriticalSpeedOptions opt;
  opt.from_m_per_s = 5.0;
  opt.to_m_per_s = 120.0;
  opt.grid_step_m_per_s = 5.0;
  const CriticalSpeedResult r = find_critical_speed(s.model, s.equilibrium.state, s.speed_m_per_s, opt);
  EXPECT_TRUE(r.critical_speed_found);
  return r.critical_speed_m_per_s;
}

}  // namespace

TEST(SceneSetValues, ParsesKeyEqualsFiniteNumber) {
  const SceneValueSetting s = parse_scene_value_setting("elements.yaw_damper.damping_N_s_per_m[0]=2.5e5");
  EXPECT_EQ(s.key, "elements.yaw_damper.damping_N_s_per_m[0]");
  EXPECT_EQ(s.value, 2.5e5);
  EXPECT_EQ(parse_scene_value_setting("a=+3").value, 3.0);
  EXPECT_EQ(parse_scene_value_setting("a=-0.125").value, -0.125);
  EXPECT_EQ(setting_text(parse_scene_value_setting("a.b=0.1")), "a.b=0.1");
  for (const char* bad : {"abc", "=3", "a=", "a=abc", "a=nan", "a=inf", "a=1e999", "a=1.5x"})
    EXPECT_THROW(parse_scene_value_setting(bad), std::invalid_argument) << bad;
}

TEST(SceneSetValues, EachKeyFormReachesItsValue) {
  const SceneSpec spec = load_scene_file(
      kTextbook, {{"bodies.wheelset1.mass_kg", 1600.0},
                  {"bodies[0].inertia_kg_m2[1]", 94.5},
                  {"elements.track_holder.stiffness_N_per_m[1]", 7.0e5},
                  {"contacts.textbook_linear.conicity", 0.15},
                  {"track.segments[0].length_m", 4000.0},
                  {"scene.speed_m_per_s", 31.0}});
  EXPECT_EQ(parameter_value(spec, "bodies.wheelset1.mass_kg"), 1600.0);
  EXPECT_EQ(parameter_value(spec, "bodies.wheelset1.inertia_kg_m2[1]"), 94.5);
  // One scene entry, mirrored into two elements: the key moves both.
  ASSERT_EQ(spec.elements.size(), 2u);
  EXPECT_EQ(parameter_value(spec, "elements.track_holder_left.stiffness_N_per_m[1]"), 7.0e5);
  EXPECT_EQ(parameter_value(spec, "elements.track_holder_right.stiffness_N_per_m[1]"), 7.0e5);
  EXPECT_EQ(parameter_value(spec, "contacts.textbook_linear.conicity"), 0.15);
  EXPECT_EQ(spec.track.segments[0].length_m, 4000.0);
  EXPECT_EQ(spec.speed_m_per_s, 31.0);
  // A later setting of the same key wins.
  EXPECT_EQ(load_scene_file(kTextbook, {{"bodies.wheelset1.mass_kg", 1.0e3},
                                        {"bodies.wheelset1.mass_kg", 2.0e3}})
                .bodies[0]
                .mass_kg,
            2.0e3);
}

TEST(SceneSetValues, EqualsEditingTheFile) {
  const std::string text = read_regular_file(kTextbook);
  std::string edited = text;
  const std::string from = "conicity = 0.1 ", to = "conicity = 0.15";
  ASSERT_NE(edited.find(from), std::string::npos);
  edited.replace(edited.find(from), from.size(), to);
  const std::string mass_from = "mass_kg = 1500.0", mass_to = "mass_kg = 1234.5";
  edited.replace(edited.find(mass_from), mass_from.size(), mass_to);
  const SceneSpec by_file = load_scene_text(edited, kTextbook);
  const SceneSpec by_set = load_scene_file(
      kTextbook, {{"contacts.textbook_linear.conicity", 0.15}, {"bodies.wheelset1.mass_kg", 1234.5}});
  const double v_file = critical_speed_of(by_file), v_set = critical_speed_of(by_set);
  EXPECT_EQ(v_file, v_set);
  // ... and the setting changed it (the critical speed falls with conicity).
  EXPECT_LT(v_set, critical_speed_of(load_scene_file(kTextbook)) - 1.0);
}

TEST(SceneSetValues, AFractionalValueForAnIntegerInTheFileBecomesAFloat) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("railstab_set_int_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::string text = read_regular_file(kTextbook);
  text.replace(text.find("mass_kg = 1500.0"), 16, "mass_kg = 1500");
  const std::string path = (dir / "int.toml").string();
  std::ofstream(path) << text;
  EXPECT_EQ(load_scene_file(path, {{"bodies.wheelset1.mass_kg", 1500.25}}).bodies[0].mass_kg, 1500.25);
  EXPECT_EQ(load_scene_file(path, {{"bodies.wheelset1.mass_kg", 1600.0}}).bodies[0].mass_kg, 1600.0);
  std::filesystem::remove_all(dir);
}

TEST(SceneSetValues, BadSettingsNameTheFlagTheKeyAndTheProblem) {
  struct Case {
    SceneValueSetting setting;
    std::vector<std::string> said;
  };
  const std::vector<Case> cases = {
      {{"bodies.carbody.mass_kg", 1.0}, {"--set bodies.carbody.mass_kg=1", "no 'carbody'", "wheelset1"}},
      {{"bodies.wheelset1.inertia_kg_m2[3]", 1.0}, {"--set bodies.wheelset1.inertia_kg_m2[3]=1", "out of range", "3 elements"}},
      {{"bodies[4].mass_kg", 1.0}, {"--set bodies[4].mass_kg=1", "out of range"}},
      {{"contacts.textbook_linear.normal", 1.0}, {"contacts.textbook_linear.normal", "a string", "not a number"}},
      {{"bodies.wheelset1.inertia_kg_m2", 1.0}, {"give an index", "inertia_kg_m2[0]"}},
      {{"bodies.wheelset1.mass_kg[0]", 1.0}, {"not an array"}},
      {{"bodies..mass_kg", 1.0}, {"--set bodies..mass_kg=1", "empty step"}},
      {{"nothing", 1.0}, {"--set nothing=1"}},
      // The loader's own checks, with the settings in force said.
      {{"bodies.wheelset1.mass_kg", -3.0}, {"mass_kg", "expected a mass", "-3", "(with --set bodies.wheelset1.mass_kg=-3)"}},
      {{"bodies.wheelset1.mas_kg", 1.0}, {"mas_kg", "(with --set bodies.wheelset1.mas_kg=1)"}},
  };
  for (const Case& c : cases) {
    const std::string message = error_of({c.setting});
    ASSERT_FALSE(message.empty()) << c.setting.key;
    EXPECT_EQ(message.rfind(kTextbook, 0), 0u) << message;
    for (const std::string& s : c.said) EXPECT_NE(message.find(s), std::string::npos) << s << " in: " << message;
  }
}

SceneValueSetting toml_setting(const std::string& text) { return parse_scene_value_setting(text); }

// A TOML value (inline table, array, string) replaces the key as an edit of
// its line would, and a missing optional table or section is created on the
// way to a key (issue 24: `--set` could not give an initial_offset).
TEST(SceneSetValues, TablesArraysAndMissingSectionsAreWrittenAsTheFileWould) {
  const SceneValueSetting table = toml_setting("bodies.wheelset1.initial_offset={yaw_rad = 0.002}");
  EXPECT_EQ(table.toml_value, "{yaw_rad = 0.002}");
  EXPECT_EQ(setting_text(table), "bodies.wheelset1.initial_offset={yaw_rad = 0.002}");
  // Replaces the file's { y_m = 0.001 } whole: y back to its default 0.
  const SceneSpec replaced = load_scene_file(kTextbook, {table});
  EXPECT_EQ(replaced.bodies[0].initial_offset[1], 0.0);
  EXPECT_EQ(replaced.bodies[0].initial_offset[5], 0.002);
  // The scene has no initial_rate: the table is added, as a whole or by a key.
  const SceneSpec rate = load_scene_file(
      kTextbook, {toml_setting("bodies.wheelset1.initial_rate={y_m_per_s = 0.25}")});
  EXPECT_EQ(rate.bodies[0].initial_rate[1], 0.25);
  const SceneSpec rate_key =
      load_scene_file(kTextbook, {{"bodies.wheelset1.initial_rate.yaw_rad_per_s", 0.125}});
  EXPECT_EQ(rate_key.bodies[0].initial_rate[5], 0.125);
  // A missing optional section ([assessment]) by one of its keys.
  EXPECT_EQ(load_scene_file(kTextbook, {{"assessment.y_over_q_limit", 0.9}}).assessment.y_over_q_limit, 0.9);
  // An array replaces an array.
  EXPECT_EQ(load_scene_file(kTextbook, {toml_setting("bodies.wheelset1.inertia_kg_m2=[700.0, 94.5, 700.0]")})
                .bodies[0]
                .inertia_kg_m2(1),
            94.5);
  // Booleans and strings: the same as the file saying so.
  EXPECT_EQ(load_scene_file(kTextbook, {toml_setting("scene.name=\"renamed\"")}).name, "renamed");
}

TEST(SceneSetValues, ATableGivenByFlagEqualsTheEditedFile) {
  const std::string text = read_regular_file(kTextbook);
  std::string edited = text;
  const std::string from = "initial_offset = { y_m = 0.001 }";
  ASSERT_NE(edited.find(from), std::string::npos);
  edited.replace(edited.find(from), from.size(),
                 "initial_offset = { y_m = 0.002, yaw_rad = 0.001 }\ninitial_rate = { y_m_per_s = 0.01 }");
  const SceneSpec by_file = load_scene_text(edited, kTextbook);
  const SceneSpec by_set = load_scene_file(
      kTextbook, {toml_setting("bodies.wheelset1.initial_offset={ y_m = 0.002, yaw_rad = 0.001 }"),
                  {"bodies.wheelset1.initial_rate.y_m_per_s", 0.01}});
  EXPECT_EQ(by_file.bodies[0].initial_offset, by_set.bodies[0].initial_offset);
  EXPECT_EQ(by_file.bodies[0].initial_rate, by_set.bodies[0].initial_rate);
}

TEST(SceneSetValues, BadTomlValuesNameTheFlagTheKeyAndWhatWasExpected) {
  // Refused when parsed (before any scene is read), saying what was expected.
  for (const char* bad : {"a={y_m = }", "a=[1, 2", "a=\"open", "a={y_m = 1} x"}) {
    try {
      parse_scene_value_setting(bad);
      ADD_FAILURE() << bad << " was accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("as the value of a"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("TOML value"), std::string::npos) << e.what();
    }
  }
  struct Case {
    std::string text;
    std::vector<std::string> said;
  };
  const std::vector<Case> cases = {
      // A value of the wrong kind: the reader's message, the setting named.
      {"bodies.wheelset1.mass_kg={a = 1}", {"mass_kg", "(with --set bodies.wheelset1.mass_kg={a = 1})"}},
      {"bodies.wheelset1.initial_offset={y_mm = 1.0}", {"y_mm", "(with --set bodies.wheelset1.initial_offset={y_mm = 1.0})"}},
      // A number where the file has a table: the kind to give.
      {"bodies.wheelset1.initial_offset=0.001", {"--set bodies.wheelset1.initial_offset=0.001", "a table", "not a number", "={...}"}},
      // An entry of [[bodies]] is not replaced whole.
      {"bodies.wheelset1={mass_kg = 1.0}", {"--set bodies.wheelset1={mass_kg = 1.0}", "entry of an array of tables", "one by one"}},
      {"bodies[0]=[1]", {"--set bodies[0]=[1]", "entry of an array of tables"}},
      // No entry is created; an index into an array that is not there.
      {"bodies.carbody.initial_offset={y_m = 0.001}", {"no 'carbody'", "wheelset1"}},
      {"bodies.wheelset1.initial_rate[1]=0.1", {"--set bodies.wheelset1.initial_rate[1]=0.1", "has no 'initial_rate[1]'"}},
  };
  for (const Case& c : cases) {
    std::string message;
    try {
      load_scene_file(kTextbook, {toml_setting(c.text)});
    } catch (const SceneError& e) {
      message = e.what();
    }
    ASSERT_FALSE(message.empty()) << c.text;
    EXPECT_EQ(message.rfind(kTextbook, 0), 0u) << message;
    for (const std::string& s : c.said) EXPECT_NE(message.find(s), std::string::npos) << s << " in: " << message;
  }
}

// A table characteristic's scale factor (spring_force_scale,
// damper_force_scale): read and set like any key, refused without a table
// and outside (0, 100].
TEST(SceneSetValues, TableScaleFactorsAreKeysOfTheirElements) {
  const std::string coach = std::string(RAILSTAB_CASES_DIR) + "/coach_tangent.toml";
  const std::string key = "elements.yaw_damper_bogie1.damper_force_scale";
  EXPECT_EQ(parameter_value(load_scene_file(coach), key), 1.0);
  const SceneSpec set = load_scene_file(coach, {{key, 2.5}});
  // One scene entry, mirrored: both halves scaled.
  EXPECT_EQ(parameter_value(set, "elements.yaw_damper_bogie1_left.damper_force_scale"), 2.5);
  EXPECT_EQ(parameter_value(set, "elements.yaw_damper_bogie1_right.damper_force_scale"), 2.5);
  EXPECT_EQ(parameter_value(set, "elements.yaw_damper_bogie2.damper_force_scale"), 1.0);
  auto error = [&](const std::string& file, const SceneValueSetting& s) {
    try {
      load_scene_file(file, {s});
    } catch (const SceneError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string zero = error(coach, {key, 0.0});
  EXPECT_NE(zero.find("damper_force_scale: expected a scale factor in (0, 100]"), std::string::npos) << zero;
  // A linear damper is varied by its coefficient: a scale beside it is
  // refused, naming the key and the table it would need.
  std::string text = read_regular_file(coach);
  const std::string table = "damper_force_velocity_table = [[-0.3, -14800.0], [-0.02, -9000.0], [0.0, 0.0],\n"
                            "                               [0.02, 9000.0], [0.3, 14800.0]]";
  ASSERT_NE(text.find(table), std::string::npos);
  text.replace(text.find(table), table.size(), "damping_N_s_per_m = 4.5e5");
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("railstab_set_scale_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string linear_file = (dir / "linear.toml").string();
  std::ofstream(linear_file) << text;
  const std::string linear = error(linear_file, {key, 2.0});
  EXPECT_NE(linear.find("damper_force_scale: expected a scale factor beside damper_force_velocity_table"),
            std::string::npos)
      << linear;
  EXPECT_NE(linear.find("varied by damping_N_s_per_m"), std::string::npos) << linear;
  std::filesystem::remove_all(dir);
}
