// Profile readers and validation: the benchmark SIMPACK files read into the
// documented frame, and every kind of bad input gets an error naming the
// file, the line where relevant and what was expected.
#include <railstab/contact_geometry/rigid_contact.hpp>
#include <railstab/contact_geometry/profile_contact_geometry.hpp>
#include <railstab/setup/contact_tables.hpp>
#include <railstab/profiles/profile_readers.hpp>

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

using namespace railstab;

namespace {

const std::string kProfiles = std::string(RAILSTAB_CASES_DIR) + "/profiles/";

class TempDir {
 public:
  TempDir() {
    path_ = std::filesystem::temp_directory_path() /
            ("railstab_profiles_" + std::to_string(::getpid()) + "_" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(path_);
  }
  ~TempDir() { std::filesystem::remove_all(path_); }
  std::string write(const std::string& name, const std::string& text) const {
    const std::string p = (path_ / name).string();
    std::ofstream(p) << text;
    return p;
  }
 private:
  std::filesystem::path path_;
};

// A plain-text cone wheel in mm, y from -40 to 60 mm, one point per mm.
std::string cone_text(double scale_to_unit = 1.0) {
  std::string s = "# y z (mm)\n";
  for (int y = -40; y <= 60; ++y)
    s += std::to_string(y * scale_to_unit) + " " + std::to_string(0.05 * y * scale_to_unit) + "\n";
  return s;
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST(ProfileReaders, SimpackBenchmarkFilesLandInTheDocumentedFrame) {
  const Profile w = read_simpack_profile(kProfiles + "MBench_S1002_v3.prw", ProfileKind::wheel);
  const Profile r = read_simpack_profile(kProfiles + "MBench_UIC60_v3.prr", ProfileKind::rail);
  // S1002 (EN 13715): mirrored and inverted by the header, in metres, z up;
  // the flange tip is the lowest point, 28 mm below the tape circle, ~55 mm
  // inward of it.
  const auto tip = std::min_element(w.z_m.begin(), w.z_m.end());
  EXPECT_NEAR(*tip, -0.028, 0.0005);
  EXPECT_NEAR(w.y_m[size_t(tip - w.z_m.begin())], -0.055, 0.002);
  EXPECT_TRUE(std::is_sorted(w.y_m.begin(), w.y_m.end()));
  EXPECT_NEAR(w.y_m.front(), -0.0696126, 1e-7);  // file line 45 after mirror.y
  // UIC60 head: 72 mm wide at its base, top at z = 0.
  EXPECT_NEAR(*std::max_element(r.z_m.begin(), r.z_m.end()), 0.0, 1e-6);
  EXPECT_NEAR(r.y_m.back() - r.y_m.front(), 0.0743, 0.001);
}

TEST(ProfileReaders, PlainTextInMillimetresAndMetresAgree) {
  TempDir dir;
  const Profile mm = read_plain_profile(dir.write("w.txt", cone_text()), ProfileKind::wheel,
                                        LengthUnit::millimetre);
  const Profile m = read_plain_profile(dir.write("w_m.txt", cone_text(1e-3)), ProfileKind::wheel,
                                       LengthUnit::metre);
  ASSERT_EQ(mm.y_m.size(), m.y_m.size());
  for (size_t i = 0; i < m.y_m.size(); ++i) EXPECT_NEAR(mm.z_m[i], m.z_m[i], 1e-12);
}

TEST(ProfileReaders, MissingEmptyAndUnreadableFilesAreNamed) {
  TempDir dir;
  const std::string missing = "/nonexistent/railstab/w.txt";
  std::string e = error_of([&] { read_plain_profile(missing, ProfileKind::wheel, LengthUnit::millimetre); });
  EXPECT_NE(e.find(missing), std::string::npos) << e;
  EXPECT_NE(e.find("not found"), std::string::npos) << e;

  const std::string empty = dir.write("empty.txt", "# only a comment\n\n");
  e = error_of([&] { read_plain_profile(empty, ProfileKind::wheel, LengthUnit::millimetre); });
  EXPECT_NE(e.find(empty), std::string::npos) << e;
  EXPECT_NE(e.find("no profile points"), std::string::npos) << e;

  const std::string garbage = dir.write("garbage.txt", "0 0\n1 0.05\nabc def\n");
  e = error_of([&] { read_plain_profile(garbage, ProfileKind::wheel, LengthUnit::millimetre); });
  EXPECT_NE(e.find(garbage + ":3"), std::string::npos) << e;
  EXPECT_NE(e.find("expected two numbers"), std::string::npos) << e;
}

TEST(ProfileReaders, UnreadableFileIsNamed) {
  TempDir dir;
  std::string e;
  const std::string locked = dir.write("locked.txt", cone_text());
  std::filesystem::permissions(locked, std::filesystem::perms::none);
  if (std::ifstream(locked).good()) {
    std::filesystem::permissions(locked, std::filesystem::perms::owner_all);
    GTEST_SKIP() << "running with permission to read any file (root); unreadable case untested";
  }
  e = error_of([&] { read_plain_profile(locked, ProfileKind::wheel, LengthUnit::millimetre); });
  std::filesystem::permissions(locked, std::filesystem::perms::owner_all);
  EXPECT_NE(e.find(locked), std::string::npos) << e;
  EXPECT_NE(e.find("cannot open"), std::string::npos) << e;
}

TEST(ProfileReaders, NonMonotonicProfileNamesTheLine) {
  TempDir dir;
  const std::string p = dir.write("w.txt", "-40 -2\n-20 -1\n0 0\n-5 0.2\n30 1.5\n60 3\n");
  const std::string e = error_of([&] { read_plain_profile(p, ProfileKind::wheel, LengthUnit::millimetre); });
  // y goes back at line 4 (the polyline also crosses itself there or not:
  // either message names line 4 and what was expected).
  EXPECT_NE(e.find(p + ":4"), std::string::npos) << e;
  EXPECT_NE(e.find("expected"), std::string::npos) << e;
}

TEST(ProfileReaders, SelfIntersectingProfileNamesBothSegments) {
  TempDir dir;
  // A loop: the segment of lines 4-5 crosses the one of lines 1-2.
  const std::string p = dir.write("w.txt", "-40 0\n0 0\n10 5\n-20 5\n-20 -5\n60 3\n");
  const std::string e = error_of([&] { read_plain_profile(p, ProfileKind::wheel, LengthUnit::millimetre); });
  EXPECT_NE(e.find("intersects itself"), std::string::npos) << e;
  EXPECT_NE(e.find("lines 1 and 2"), std::string::npos) << e;
}

TEST(ProfileReaders, WrongUnitIsCaughtBySize) {
  TempDir dir;
  // Metres read as millimetres: a profile 0.1 mm wide.
  const std::string m = dir.write("w_m.txt", cone_text(1e-3));
  std::string e = error_of([&] { read_plain_profile(m, ProfileKind::wheel, LengthUnit::millimetre); });
  EXPECT_NE(e.find(m), std::string::npos) << e;
  EXPECT_NE(e.find("unit"), std::string::npos) << e;
  // Millimetres read as metres: coordinates of tens of metres.
  const std::string mm = dir.write("w.txt", cone_text());
  e = error_of([&] { read_plain_profile(mm, ProfileKind::wheel, LengthUnit::metre); });
  EXPECT_NE(e.find("unit"), std::string::npos) << e;
}

TEST(ProfileReaders, SimpackTypeMismatchAndMirrorErrors) {
  const std::string e = error_of([&] {
    read_simpack_profile(kProfiles + "MBench_UIC60_v3.prr", ProfileKind::wheel);
  });
  EXPECT_NE(e.find("MBench_UIC60_v3.prr:12"), std::string::npos) << e;
  EXPECT_NE(e.find("expected 1"), std::string::npos) << e;
  // The wheel without its mirror.y flag has its flange on the field side.
  TempDir dir;
  std::ifstream in(kProfiles + "MBench_S1002_v3.prw");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const size_t at = text.find("mirror.y       =  1");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 19, "mirror.y       =  0");
  const std::string p = dir.write("unmirrored.prw", text);
  const std::string e2 = error_of([&] { read_simpack_profile(p, ProfileKind::wheel); });
  EXPECT_NE(e2.find("mirror"), std::string::npos) << e2;
}

TEST(ProfileReaders, PairWithoutContactAtTheNominalPositionNamesBothFiles) {
  const Profile w = read_simpack_profile(kProfiles + "MBench_S1002_v3.prw", ProfileKind::wheel);
  const Profile r = read_simpack_profile(kProfiles + "MBench_UIC60_v3.prr", ProfileKind::rail);
  ProfilePairParameters p;
  p.flange_back_distance_m = 1.200;  // wheels 80 mm inside their rails: the flange sits on the head
  const ProfilePair pair = make_profile_pair(w, r, p);
  const std::string e = error_of([&] { require_contact_at_nominal_position(pair); });
  EXPECT_NE(e.find("MBench_S1002_v3.prw"), std::string::npos) << e;
  EXPECT_NE(e.find("MBench_UIC60_v3.prr"), std::string::npos) << e;
  EXPECT_NE(e.find("nominal position"), std::string::npos) << e;
}

// The contact-geometry command reads its contact with the scene loader's
// contact reader (load_scene_contacts): the shipped contact file reads, and
// bad keys are named with their path and what was found.
TEST(ProfileContactScene, ShippedCaseReadsAndBadKeysAreNamed) {
  const std::vector<ContactSpec> contacts =
      load_scene_contacts(std::string(RAILSTAB_CASES_DIR) + "/s1002_uic60_contact.toml");
  ASSERT_EQ(contacts.size(), 1u);
  EXPECT_EQ(contacts[0].name, "s1002_uic60");
  EXPECT_DOUBLE_EQ(contacts[0].profile_source.placement.track_gauge_m, 1.435);
  ASSERT_TRUE(contacts[0].profile_geometry);
  EXPECT_GT(contacts[0].profile_geometry->table.slots(), 1);
  TempDir dir;
  const std::string head = "[contacts.a]\ngeometry = \"profiles\"\nnormal = \"hertz\"\n"
                           "tangential = \"kalker_hertz\"\n";
  const std::string scene =
      dir.write("s.toml", head + "wheel_profile = \"w.txt\"\nrail_profile = \"r.prr\"\n"
                                 "track_gauge_m = \"wide\"\n");
  const std::string e = error_of([&] { load_scene_contacts(scene); });
  EXPECT_NE(e.find("contacts.a.wheel_profile"), std::string::npos) << e;  // plain text needs _mm/_m
  const std::string scene2 =
      dir.write("s2.toml", head + "wheel_profile_mm = \"w.txt\"\nrail_profile = \"r.prr\"\n"
                                  "track_gauge_m = \"wide\"\n");
  const std::string e2 = error_of([&] { load_scene_contacts(scene2); });
  EXPECT_NE(e2.find("contacts.a.track_gauge_m"), std::string::npos) << e2;
  EXPECT_NE(e2.find("a number (m), got a string 'wide'"), std::string::npos) << e2;
}

// The EN 15302 keys of a profile contact (docs/en15302.md): the right
// wheel's radius and the gauge point's y are range-checked and named; the
// gauge point is searched or given, not both; the right rail's gauge point
// needs the left's; the keys are refused with another geometry.
TEST(ProfileContactScene, AsymmetricAndGaugePointKeysAreCheckedAndNamed) {
  TempDir dir;
  const std::string profiles = std::string(RAILSTAB_CASES_DIR) + "/profiles/";
  const std::string head = "[contacts.a]\ngeometry = \"profiles\"\nwheel_profile = \"" + profiles +
                           "MBench_S1002_v3.prw\"\nrail_profile = \"" + profiles +
                           "MBench_UIC60_v3.prr\"\n";
  const std::string radius =
      dir.write("r.toml", head + "right_nominal_rolling_radius_m = 2.0\n");
  const std::string e = error_of([&] { load_scene_contacts(radius); });
  EXPECT_NE(e.find("contacts.a.right_nominal_rolling_radius_m"), std::string::npos) << e;
  const std::string both = dir.write(
      "b.toml", head + "rail_gauge_point_y_m = -0.035\ngauge_measuring_height_m = 0.014\n");
  const std::string e2 = error_of([&] { load_scene_contacts(both); });
  EXPECT_NE(e2.find("contacts.a.gauge_measuring_height_m"), std::string::npos) << e2;
  const std::string right_only = dir.write("o.toml", head + "right_rail_gauge_point_y_m = -0.035\n");
  const std::string e3 = error_of([&] { load_scene_contacts(right_only); });
  EXPECT_NE(e3.find("contacts.a.rail_gauge_point_y_m"), std::string::npos) << e3;
  const std::string cone = dir.write(
      "c.toml", "[contacts.a]\ngeometry = \"knife_edge_cone\"\nright_nominal_rolling_radius_m = 0.45\n");
  const std::string e4 = error_of([&] { load_scene_contacts(cone); });
  EXPECT_NE(e4.find("contacts.a.right_nominal_rolling_radius_m"), std::string::npos) << e4;
  // Read: an asymmetric wheelset with its own pair and table.
  const std::string good = dir.write("g.toml", head + "right_nominal_rolling_radius_m = 0.459\n");
  const std::vector<ContactSpec> contacts = load_scene_contacts(good);
  ASSERT_EQ(contacts.size(), 1u);
  ASSERT_TRUE(contacts[0].profile_geometry->asymmetric());
  EXPECT_DOUBLE_EQ(contacts[0].profile_geometry->pair_for(-1).parameters.nominal_rolling_radius_m,
                   0.459);
}
