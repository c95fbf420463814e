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
