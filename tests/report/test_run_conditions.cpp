// Reports state their conditions (report/run_conditions.hpp, io/sha256.hpp):
// - SHA-256 against the FIPS 180-4 examples and against coreutils' sha256sum
//   of a scene file;
// - the cant deficiency against V^2 D / (g R) - cant;
// - a critical-speed run in the arc: its files carry the arc length (a
//   tangent run's are not overwritten), and the JSON and the Markdown state
//   the same track, cant deficiency, scene hash, version and critical speed.
#include "cli/run_cli.hpp"
#include <railstab/scene_reading/load_scene.hpp>
#include <railstab/io/sha256.hpp>
#include <railstab/curving/steady_curving.hpp>
#include <railstab/report/run_conditions.hpp>
#include <railstab/setup/build_model.hpp>
#include <railstab/setup/prepare_scene.hpp>

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include <unistd.h>
#include "support/test_files.hpp"

using namespace railstab;
namespace fs = std::filesystem;

TEST(Sha256, FipsExamples) {
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  // One million 'a' (several blocks, the length field beyond one byte).
  EXPECT_EQ(sha256_hex(std::string(1000000, 'a')),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(Sha256, EqualsCoreutilsOnASceneFile) {
  const std::string scene = std::string(RAILSTAB_CASES_DIR) + "/thesis_bogie_curve.toml";
  FILE* p = ::popen(("sha256sum '" + scene + "'").c_str(), "r");
  ASSERT_NE(p, nullptr);
  char buf[65] = {};
  ASSERT_EQ(std::fread(buf, 1, 64, p), 64u);
  ::pclose(p);
  EXPECT_EQ(sha256_of_file(scene), std::string(buf, 64));
}

TEST(RunConditions, CantDeficiencyAndTrackInTheArc) {
  SceneOverrides o;
  o.reference_arc_length_m = 2000.0;
  const Model model = build_model(load_scene_with_overrides(
      std::string(RAILSTAB_CASES_DIR) + "/thesis_bogie_curve.toml", o));
  const RunConditions c = run_conditions(model);
  EXPECT_FALSE(c.tangent);
  EXPECT_NEAR(c.curvature_per_m, 1e-3, 1e-12);  // R = 1000 m, left
  EXPECT_NEAR(c.cant_m, 0.05, 1e-12);
  // 20^2 * 1.5 / (9.81 * 1000) - 0.05 = 0.0111621 m
  EXPECT_NEAR(c.cant_deficiency_m(20.0), 400.0 * 1.5 / (9.81 * 1000.0) - 0.05, 1e-12);
  EXPECT_NEAR(c.cant_deficiency_m(20.0), 0.0111621, 1e-7);
  EXPECT_EQ(run_file_tag(c), "_arc2000m");
  // The stem is the scene file's (not the scene's name), with the arc length.
  EXPECT_EQ(steady_state_file_stem("somewhere/copy.of.bogie.toml", model), "copy.of.bogie_arc2000m");
  const Model tangent = build_model(
      load_scene_file(std::string(RAILSTAB_CASES_DIR) + "/thesis_bogie_tangent.toml"));
  EXPECT_TRUE(run_conditions(tangent).tangent);
  EXPECT_EQ(steady_state_file_stem("cases/thesis_bogie_tangent.toml", tangent), "thesis_bogie_tangent");
  EXPECT_EQ(steady_state_file_stem("x/../evil name;.toml", tangent), "evil_name_");
  EXPECT_EQ(run_conditions(tangent).cant_deficiency_m(30.0), 0.0);
  // A canted straight: all excess, the report and the curving formula alike.
  const Model canted = build_model(load_scene_file(
      std::string(RAILSTAB_CASES_DIR) + "/thesis_bogie_tangent.toml",
      {{"track.start_cant_m", -0.04}, {"track.segments[0].end_cant_m", -0.04}}));
  const RunConditions cc = run_conditions(canted);
  EXPECT_FALSE(cc.tangent);
  EXPECT_NEAR(cc.cant_deficiency_m(30.0), -0.04, 1e-15);
  EXPECT_NEAR(cant_deficiency_m(CurvingCondition{0.0, -0.04, 30.0}, 1.5, 9.81), -0.04, 1e-15);
}

namespace {
using railstab::test::read_text;
}  // namespace

TEST(RunConditions, CurveReportJsonAndMarkdownAgree) {
  const fs::path dir = fs::temp_directory_path() / ("railstab_conditions_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string scene = std::string(RAILSTAB_CASES_DIR) + "/thesis_bogie_curve.toml";
  const auto run = test::run_railstab({"critical-speed", scene, "--arc-length", "2000", "--from",
                                       "30", "--to", "45", "--step", "5", "--no-plots", "--out",
                                       "o"},
                                      dir);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_FALSE(fs::exists(dir / "o/thesis_bogie_curve_critical_speed.json"));
  const std::string json = read_text(dir / "o/thesis_bogie_curve_arc2000m_critical_speed.json");
  const std::string md = read_text(dir / "o/thesis_bogie_curve_arc2000m_critical_speed.md");
  ASSERT_FALSE(json.empty());
  ASSERT_FALSE(md.empty());
  const std::string sha = sha256_of_file(scene);
  EXPECT_NE(json.find("\"scene_sha256\": \"" + sha + "\""), std::string::npos);
  EXPECT_NE(md.find("SHA-256 `" + sha + "`"), std::string::npos);
  EXPECT_NE(json.find("\"radius_m\": 1000"), std::string::npos) << json.substr(0, 1200);
  EXPECT_NE(md.find("arc R = 1000 m (left), cant 50 mm, reference point at arc length 2000 m"),
            std::string::npos);
  EXPECT_NE(json.find(std::string("\"railstab_version\": \"") + "0."), std::string::npos);
  // Cant deficiency at 30 m/s: 900 * 1.5 / 9810 - 0.05 = 0.0876147 m.
  EXPECT_TRUE(std::regex_search(
      json, std::regex("\"speed_m_per_s\": 30,\\s*\"cant_deficiency_m\": 0\\.087614678")))
      << json.substr(0, 2000);
  EXPECT_NE(md.find("| 30 | 87.61 |"), std::string::npos);
  // The same critical speed in both (JSON full precision, Markdown 4 digits).
  std::smatch m;
  ASSERT_TRUE(std::regex_search(json, m, std::regex("\"critical_speed_m_per_s\": ([0-9.]+)")));
  const double vc = std::stod(m[1]);
  std::ostringstream shown;
  shown.precision(4);
  shown << "critical speed | **" << vc << " m/s**";
  EXPECT_NE(md.find(shown.str()), std::string::npos) << shown.str() << "\n" << md.substr(0, 1500);
  fs::remove_all(dir);
}
