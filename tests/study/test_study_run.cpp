// Running a study: each point equals a critical-speed search of the scene
// with its values set, a failing combination is a row with its error (the
// others are computed), results do not depend on the number of threads,
// records of shards merge into the whole study, and a record naming an
// unknown eigen-solver is refused.
#include <gtest/gtest.h>

#include <railstab/setup/prepare_scene.hpp>
#include <railstab/stability/speed_analysis.hpp>
#include <railstab/study/study_record.hpp>
#include <railstab/study/study_run.hpp>

#include <cmath>
#include <fstream>
#include <sstream>

using namespace railstab;

namespace {

StudyDefinition textbook_study(std::vector<VariedKey> varied) {
  StudyDefinition d;
  d.scene_path = std::string(RAILSTAB_CASES_DIR) + "/textbook_wheelset.toml";
  d.scene_name = "textbook_wheelset";
  d.scene_hash = "0";
  d.varied = std::move(varied);
  d.analysis.from_m_per_s = 5.0;
  d.analysis.to_m_per_s = 120.0;
  d.analysis.grid_step_m_per_s = 5.0;
  return d;
}

// The critical-speed search a study point must equal: the scene with
// `values` set, on the study's grid.
CriticalSpeedResult search_with(const StudyDefinition& d, std::vector<SceneValueSetting> values) {
  SceneOverrides o;
  o.values = std::move(values);
  const PreparedScene s = prepare_scene(d.scene_path, o);
  CriticalSpeedOptions opt;
  opt.from_m_per_s = d.analysis.from_m_per_s;
  opt.to_m_per_s = d.analysis.to_m_per_s;
  opt.grid_step_m_per_s = d.analysis.grid_step_m_per_s;
  return find_critical_speed(s.model, s.equilibrium.state, s.speed_m_per_s, opt);
}

}  // namespace

TEST(StudyRun, EachPointIsTheSearchOfTheSceneWithItsValues) {
  const StudyDefinition d = textbook_study({parse_varied_key("contacts.textbook_linear.conicity=0.1:0.3:0.1")});
  const std::vector<StudyPoint> points = run_study(d, {});
  ASSERT_EQ(points.size(), 3u);
  for (const StudyPoint& p : points) {
    const CriticalSpeedResult r = search_with(d, {{"contacts.textbook_linear.conicity", p.values[0]}});
    ASSERT_TRUE(r.critical_speed_found);
    EXPECT_EQ(p.status, "critical_speed_found");
    EXPECT_EQ(p.critical_speed_m_per_s, r.critical_speed_m_per_s);
    EXPECT_GT(p.frequency_hz, 0.0);
    EXPECT_FALSE(p.mode.empty());
  }
  // Klingel: hunting speed ~ 1/sqrt(conicity) for this wheelset on springs
  // (the kinematic frequency grows with sqrt(lambda)); at least it falls.
  EXPECT_GT(points[0].critical_speed_m_per_s, points[1].critical_speed_m_per_s);
  EXPECT_GT(points[1].critical_speed_m_per_s, points[2].critical_speed_m_per_s);
}

// Linked keys (--vary 'K1,K2=...') take one value together: each point is the
// search of the scene with both set, and not that of varying one key alone.
TEST(StudyRun, LinkedKeysTakeOneValueTogether) {
  const std::string k0 = "elements.track_holder.stiffness_N_per_m[0]";
  const std::string k1 = "elements.track_holder.stiffness_N_per_m[1]";
  const StudyDefinition linked = textbook_study({parse_varied_key(k0 + "," + k1 + "=4e5:8e5:4e5")});
  const StudyDefinition alone = textbook_study({parse_varied_key(k1 + "=4e5:8e5:4e5")});
  const std::vector<StudyPoint> points = run_study(linked, {});
  const std::vector<StudyPoint> single = run_study(alone, {});
  ASSERT_EQ(points.size(), 2u);
  ASSERT_EQ(single.size(), 2u);
  for (const StudyPoint& p : points) {
    const CriticalSpeedResult r = search_with(linked, {{k0, p.values[0]}, {k1, p.values[0]}});
    ASSERT_TRUE(r.critical_speed_found);
    EXPECT_EQ(p.status, "critical_speed_found");
    EXPECT_EQ(p.critical_speed_m_per_s, r.critical_speed_m_per_s);
  }
  // At 4e5 N/m the longitudinal stiffness differs from the scene's 1e6 only
  // in the linked study: the yaw stiffness, and so the critical speed, differ.
  ASSERT_EQ(points[0].status, "critical_speed_found");
  ASSERT_EQ(single[0].status, "critical_speed_found");
  EXPECT_GT(std::abs(points[0].critical_speed_m_per_s - single[0].critical_speed_m_per_s), 0.1);
}

TEST(StudyRun, AFailingCombinationIsARowNotTheEndAndThreadsDoNotChangeResults) {
  // A mass of -1000 or 0 kg is refused by the scene check; 1000 and 2000 kg run.
  const StudyDefinition d = textbook_study({parse_varied_key("bodies.wheelset1.mass_kg=-1000:2000:1000"),
                                            parse_varied_key("contacts.textbook_linear.conicity=0.1:0.2:0.1")});
  StudyRunOptions one, two;
  two.jobs = 2;
  std::vector<std::string> progress;
  two.progress = [&](const std::string& line) { progress.push_back(line); };
  const std::vector<StudyPoint> a = run_study(d, one), b = run_study(d, two);
  ASSERT_EQ(a.size(), 8u);
  ASSERT_EQ(b.size(), 8u);
  EXPECT_EQ(progress.size(), 8u);
  for (std::size_t i = 0; i < 8; ++i) {
    EXPECT_EQ(a[i].index, i);
    EXPECT_EQ(a[i].status, b[i].status);
    EXPECT_EQ(a[i].critical_speed_m_per_s, b[i].critical_speed_m_per_s);
    EXPECT_EQ(a[i].frequency_hz, b[i].frequency_hz);
    EXPECT_EQ(a[i].message, b[i].message);
  }
  for (std::size_t i : {0u, 1u, 2u, 3u}) {
    EXPECT_EQ(a[i].status, "error");
    EXPECT_NE(a[i].message.find("mass_kg"), std::string::npos) << a[i].message;
    EXPECT_NE(a[i].message.find("--vary bodies.wheelset1.mass_kg=-1000:2000:1000"), std::string::npos)
        << a[i].message;
  }
  for (std::size_t i : {4u, 5u, 6u, 7u}) EXPECT_EQ(a[i].status, "critical_speed_found") << a[i].message;
}

TEST(StudyRun, ShardRecordsMergeIntoTheWholeStudy) {
  const StudyDefinition d = textbook_study({parse_varied_key("contacts.textbook_linear.conicity=0.1:0.5:0.1")});
  const std::vector<StudyPoint> whole = run_study(d, {});
  std::vector<StudyRecord> records;
  for (std::size_t i = 1; i <= 2; ++i) {
    StudyRunOptions o;
    o.shard = {i, 2};
    std::stringstream text;
    write_study_record(text, d, o.shard, run_study(d, o));
    const std::string path = ::testing::TempDir() + "railstab_record_" + std::to_string(i) + ".toml";
    { std::ofstream(path) << text.str(); }
    records.push_back(read_study_record(path));
  }
  const std::vector<StudyPoint> merged = merge_study_records({records[1], records[0]});
  ASSERT_EQ(merged.size(), whole.size());
  for (std::size_t i = 0; i < whole.size(); ++i) {
    EXPECT_EQ(merged[i].index, i);
    EXPECT_EQ(merged[i].values, whole[i].values);
    EXPECT_EQ(merged[i].critical_speed_m_per_s, whole[i].critical_speed_m_per_s);  // exact
    EXPECT_EQ(merged[i].frequency_hz, whole[i].frequency_hz);
    EXPECT_EQ(merged[i].mode, whole[i].mode);
  }
  auto merge_error = [](const std::vector<StudyRecord>& r) {
    try {
      merge_study_records(r);
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(merge_error({records[0]}).find("shard(s) 2/2 missing"), std::string::npos);
  EXPECT_NE(merge_error({records[0], records[0]}).find("given twice"), std::string::npos);
  StudyRecord other = records[1];
  other.definition.analysis.to_m_per_s = 100.0;
  EXPECT_NE(merge_error({records[0], other}).find("different study"), std::string::npos);
  other = records[1];
  other.definition.scene_hash = "1";
  EXPECT_NE(merge_error({records[0], other}).find("different study"), std::string::npos);
  other = records[1];
  other.points.pop_back();
  EXPECT_NE(merge_error({records[0], other}).find("missing"), std::string::npos);
}

// A record written before the output keys were renamed (format 1: `scene`
// the path, `scene_name`, points' `frequency_Hz` and `mode`) is refused,
// naming the file, the old key and its new name; one of the current format
// round-trips its names.
TEST(StudyRun, RecordWithTheOldKeyNamesIsRefusedNamingTheKeyAndItsNewName) {
  const StudyDefinition d = textbook_study({parse_varied_key("contacts.textbook_linear.conicity=0.1:0.2:0.1")});
  std::stringstream text;
  write_study_record(text, d, {1, 1}, run_study(d, {}));
  const std::string now = text.str();
  for (const char* key : {"scene = ", "scene_file = ", "hunting_frequency_Hz = ", "hunting_mode = "})
    EXPECT_NE(now.find(key), std::string::npos) << key << "\n" << now;
  EXPECT_NE(now.find("format = 'railstab study record 2'"), std::string::npos) << now;
  const std::string current = ::testing::TempDir() + "railstab_record_current.toml";
  { std::ofstream(current) << now; }
  const StudyRecord r = read_study_record(current);
  EXPECT_EQ(r.definition.scene_name, d.scene_name);
  EXPECT_EQ(r.definition.scene_path, d.scene_path);

  auto refusal = [](const std::string& path, const std::string& record) {
    { std::ofstream(path) << record; }
    try {
      read_study_record(path);
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  auto replaced = [](std::string s, const std::string& from, const std::string& to) {
    for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
      s.replace(at, from.size(), to);
    return s;
  };
  // The whole old record: its study table is refused first.
  std::string old = replaced(now, "railstab study record 2", "railstab study record 1");
  old = replaced(old, "\nscene = ", "\nscene_name = ");
  old = replaced(old, "\nscene_file = ", "\nscene = ");
  old = replaced(old, "hunting_frequency_Hz = ", "frequency_Hz = ");
  old = replaced(old, "hunting_mode = ", "mode = ");
  const std::string old_path = ::testing::TempDir() + "railstab_record_old.toml";
  const std::string message = refusal(old_path, old);
  EXPECT_EQ(message.rfind(old_path + ": study.scene_name: renamed to study.scene;", 0), 0u) << message;
  EXPECT_NE(message.find("study.scene_file"), std::string::npos) << message;
  // An old name among the points alone is refused by its own name.
  for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
           {"hunting_frequency_Hz", "frequency_Hz"}, {"hunting_mode", "mode"}}) {
    const std::string path = ::testing::TempDir() + "railstab_record_" + to + ".toml";
    const std::string said = refusal(path, replaced(now, from + " = ", to + " = "));
    EXPECT_EQ(said.rfind(path + ": points." + to + ": renamed to points." + from + ";", 0), 0u) << said;
  }
}

// A record's eigen_solver is one of the solver names; the message is the
// solver parser's, with the file and the key in front.
TEST(StudyRun, RecordWithAnUnknownEigenSolverIsRefused) {
  StudyDefinition d = textbook_study({parse_varied_key("contacts.textbook_linear.conicity=0.1:0.5:0.1")});
  d.analysis.solver = "qr";
  std::stringstream text;
  write_study_record(text, d, StudyShard{}, {});
  const std::string path = ::testing::TempDir() + "railstab_record_unknown_solver.toml";
  { std::ofstream(path) << text.str(); }
  try {
    read_study_record(path);
    ADD_FAILURE() << "expected the record to be refused";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path + ": study.eigen_solver: eigen-solver 'qr': expected "
                                                "one of auto, dense, sparse, arpack"),
              std::string::npos)
        << e.what();
  }
}

// A table damper varied by its scale factor (issue 24: the coach's yaw
// dampers are force-velocity tables and had no key a study could vary): the
// front and rear dampers linked, each point the search of the scene with
// the scale set, the scale 1 point the scene as shipped, and the scale
// moving the critical speed (the dampers set the coach's hunting speed:
// docs/parameter_studies.md, "The coach study").
TEST(StudyRun, TableDamperScaleFactorIsAStudyKey) {
  StudyDefinition d;
  d.scene_path = std::string(RAILSTAB_CASES_DIR) + "/coach_tangent.toml";
  d.scene_name = "coach_tangent";
  d.scene_hash = "0";
  d.varied = {parse_varied_key(
      "elements.yaw_damper_bogie1.damper_force_scale,elements.yaw_damper_bogie2.damper_force_scale=0.5:1:0.5")};
  d.analysis.from_m_per_s = 100.0;
  d.analysis.to_m_per_s = 300.0;
  d.analysis.grid_step_m_per_s = 10.0;
  const std::vector<StudyPoint> points = run_study(d, {});
  ASSERT_EQ(points.size(), 2u);
  for (const StudyPoint& p : points) {
    ASSERT_EQ(p.status, "critical_speed_found") << p.message;
    const CriticalSpeedResult r = search_with(d, {{"elements.yaw_damper_bogie1.damper_force_scale", p.values[0]},
                                                  {"elements.yaw_damper_bogie2.damper_force_scale", p.values[0]}});
    EXPECT_EQ(p.critical_speed_m_per_s, r.critical_speed_m_per_s);
  }
  EXPECT_EQ(points[1].critical_speed_m_per_s, search_with(d, {}).critical_speed_m_per_s);
  EXPECT_GT(std::abs(points[0].critical_speed_m_per_s - points[1].critical_speed_m_per_s), 1.0);
}
