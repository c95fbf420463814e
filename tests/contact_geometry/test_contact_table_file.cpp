// A contact table written by `railstab contact-geometry` and read back
// (contact_geometry/contact_table_file.hpp): every node value and
// derivative, the slots, the grid and the placement come back bit for bit,
// so the table evaluates exactly as the one built from the profiles; the
// characteristic functions on the table agree with the profiles' to the
// table's interpolation error (stated below); a scene with geometry =
// "table" gives the same critical speed as the profiles scene (exactly) and
// refuses the quasi-linear linearisation, naming the key; a bad file is an
// error naming the file, the line, the key or column and what was expected.
#include <gtest/gtest.h>

#include "support/test_files.hpp"

#include <railstab/contact_geometry/characteristic_functions.hpp>
#include <railstab/contact_geometry/contact_geometry_summary.hpp>
#include <railstab/contact_geometry/contact_table_file.hpp>
#include <railstab/contact_geometry/table_rigid_contact.hpp>
#include <railstab/setup/contact_tables.hpp>
#include <railstab/setup/prepare_scene.hpp>
#include <railstab/stability/quasi_linear_critical_speed.hpp>

#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <regex>
#include <sstream>

using namespace railstab;
namespace fs = std::filesystem;

namespace {

// The S1002/UIC60 contact of the thesis bogie scene (r0 = 0.45 m), built
// from its profiles once.
const ContactSpec& s1002_contact() {
  static const std::vector<ContactSpec> contacts =
      load_scene_contacts(test::case_path("thesis_bogie_s1002_tangent"));
  return contacts.front();
}

std::string table_text(const ProfileContactGeometry& g) {
  std::ostringstream out;
  write_contact_table_file(out, g, "test");
  return out.str();
}

fs::path write_file(const fs::path& dir, const std::string& name, const std::string& text) {
  std::ofstream(dir / name) << text;
  return dir / name;
}

// The thesis bogie scene on S1002 with its contact replaced by the table file.
std::string table_scene_text(const fs::path& table) {
  std::string s = test::read_text(test::case_path("thesis_bogie_s1002_tangent"));
  for (const char* key : {"wheel_profile", "rail_profile", "track_gauge_m", "gauge_measuring_height_m",
                          "flange_back_distance_m", "tape_circle_from_flange_back_m",
                          "rail_inclination_rad"})
    s = std::regex_replace(s, std::regex(std::string("\n") + key + " = [^\n]*"), "");
  s = std::regex_replace(s, std::regex("\ngeometry = \"profiles\""),
                         "\ngeometry = \"table\"\ncontact_table = \"" + table.string() + "\"");
  return s;
}

}  // namespace

TEST(ContactTableFile, ReadBackIsBitIdentical) {
  const ProfileContactGeometry& g = *s1002_contact().profile_geometry;
  const fs::path dir = test::fresh_dir("ctf", "roundtrip");
  const fs::path file = write_file(dir, "s1002.csv", table_text(g));
  const auto t0 = std::chrono::steady_clock::now();
  const std::shared_ptr<const ProfileContactGeometry> back = read_contact_table_file(file.string());
  const double read_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::cout << "contact table file " << fs::file_size(file) / 1e6 << " MB, read in " << read_s
            << " s\n";
  EXPECT_FALSE(back->has_profiles());
  EXPECT_EQ(back->table_source, file.string());
  const ContactTable &a = g.table, &b = back->table;
  ASSERT_EQ(a.slots(), b.slots());
  ASSERT_EQ(a.lateral_nodes(), b.lateral_nodes());
  ASSERT_EQ(a.roll_nodes(), b.roll_nodes());
  EXPECT_EQ(a.slot_borders_m(), b.slot_borders_m());
  EXPECT_EQ(a.nominal_lateral_m(), b.nominal_lateral_m());
  for (int i : {0, a.lateral_nodes() / 2, a.lateral_nodes() - 1}) {
    EXPECT_EQ(a.lateral_at(i), b.lateral_at(i));
  }
  for (int j = 0; j < a.roll_nodes(); ++j) EXPECT_EQ(a.roll_at(j), b.roll_at(j));
  long differing = 0;
  for (int s = 0; s < a.slots(); ++s)
    for (int q = 0; q < kTableQuantities; ++q)
      for (int i = 0; i < a.lateral_nodes(); ++i)
        for (int j = 0; j < a.roll_nodes(); ++j) {
          const ContactTable::Node &x = a.node_data(s, TableQuantity(q), i, j),
                                   &y = b.node_data(s, TableQuantity(q), i, j);
          differing += x.f != y.f || x.fq != y.fq || x.ft != y.ft || x.fqt != y.fqt;
        }
  EXPECT_EQ(differing, 0);
  // The placement the model's wheel pose uses, and the flange numbers.
  EXPECT_EQ(g.pair.wheel_offset_y_m, back->pair.wheel_offset_y_m);
  EXPECT_EQ(g.pair.rail_offset_y_m, back->pair.rail_offset_y_m);
  EXPECT_EQ(g.pair.rail_top_z_m, back->pair.rail_top_z_m);
  EXPECT_EQ(g.pair.parameters.nominal_rolling_radius_m, back->pair.parameters.nominal_rolling_radius_m);
  EXPECT_EQ(g.flange_angle_rad, back->flange_angle_rad);
  const FlangeContact flange = find_flange_contact(g.pair);
  ASSERT_TRUE(flange.found);
  ASSERT_TRUE(back->flange_contact_shift_m.has_value());
  EXPECT_EQ(*back->flange_contact_shift_m, flange.lateral_shift_m);
  // Evaluations off the nodes, AD-free: equal.
  for (double y : {-7e-3, -1.3e-3, 0.0, 0.37e-3, 4.9e-3, 6.3e-3})
    for (double roll : {-3e-3, 0.0, 1.7e-3}) {
      const WheelPoseOf<double> pa = wheel_pose_in_rail_frame<double>(g.pair, +1, y, 0.45, roll);
      const WheelPoseOf<double> pb = wheel_pose_in_rail_frame<double>(back->pair, +1, y, 0.45, roll);
      EXPECT_EQ(pa.lateral_m, pb.lateral_m);
      EXPECT_EQ(pa.vertical_m, pb.vertical_m);
      for (int s = 0; s < a.slots(); ++s) {
        const TableContact<double> ca = a.evaluate<double>(s, pa), cb = b.evaluate<double>(s, pb);
        EXPECT_EQ(ca.vertical_gap_m, cb.vertical_gap_m);
        EXPECT_EQ(ca.contact_angle_rad, cb.contact_angle_rad);
        EXPECT_EQ(ca.rolling_radius_m, cb.rolling_radius_m);
        EXPECT_EQ(ca.B_per_m, cb.B_per_m);
      }
    }
  fs::remove_all(dir);
}

// The characteristic functions from the table (rigid contact on the table)
// are those of the table built from the profiles, bit for bit, and agree
// with the profiles' own to the table's interpolation error: delta r within
// 2e-6 m and the roll within 5e-7 rad away from the contact jumps (measured:
// 4.6e-7 m, 9.2e-8 rad; the table's C1 interpolation rounds a jump over one
// 0.1 mm lateral step, so near a jump compare the conicity, an integral of
// delta r: within 0.1 %, measured 0.011 %).
TEST(ContactTableFile, CharacteristicFunctionsOnTheTable) {
  const ProfileContactGeometry& g = *s1002_contact().profile_geometry;
  const fs::path dir = test::fresh_dir("ctf", "characteristic");
  const auto back = read_contact_table_file(write_file(dir, "t.csv", table_text(g)).string());
  const std::vector<TableRigidRow> from_table = table_characteristic_functions(g, -6e-3, 6e-3, 5e-4);
  const std::vector<TableRigidRow> from_file = table_characteristic_functions(*back, -6e-3, 6e-3, 5e-4);
  const std::vector<CharacteristicRow> direct = characteristic_functions(g.pair, -6e-3, 6e-3, 5e-4);
  ASSERT_EQ(from_table.size(), direct.size());
  int compared = 0;
  double worst_dr = 0, worst_roll = 0;
  for (size_t k = 0; k < direct.size(); ++k) {
    EXPECT_EQ(from_table[k].delta_r_m(), from_file[k].delta_r_m());
    EXPECT_EQ(from_table[k].roll_rad, from_file[k].roll_rad);
    const double y = direct[k].solution.lateral_m;
    // Away from the jumps (S1002/UIC60: near 0.2 mm and 4.8 mm, both signs).
    if (std::abs(std::abs(y) - 0.2e-3) < 0.6e-3 || std::abs(std::abs(y) - 4.8e-3) < 0.6e-3) continue;
    ++compared;
    worst_dr = std::max(worst_dr, std::abs(from_table[k].delta_r_m() - direct[k].delta_r_m()));
    worst_roll = std::max(worst_roll, std::abs(from_table[k].roll_rad - direct[k].solution.roll_rad));
    EXPECT_NEAR(from_table[k].delta_r_m(), direct[k].delta_r_m(), 2e-6) << "y = " << y;
    EXPECT_NEAR(from_table[k].roll_rad, direct[k].solution.roll_rad, 5e-7) << "y = " << y;
  }
  EXPECT_GE(compared, 10);
  std::cout << "away from the jumps: |delta r - profiles'| <= " << worst_dr
            << " m, |roll - profiles'| <= " << worst_roll << " rad\n";
  const TableContactGeometrySummary t = summarise_table_contact_geometry(*back);
  const ContactGeometrySummary p = summarise_contact_geometry(g.pair);
  ASSERT_TRUE(std::isfinite(t.equivalent_conicity_at_3mm));
  std::cout << "equivalent conicity at 3 mm: profiles " << p.equivalent_conicity_at_3mm
            << ", table " << t.equivalent_conicity_at_3mm << "\n";
  EXPECT_NEAR(t.equivalent_conicity_at_3mm, p.equivalent_conicity_at_3mm,
              0.001 * p.equivalent_conicity_at_3mm);
  fs::remove_all(dir);
}

// The test: a scene on the table read back gives the critical speed
// of the profiles scene it was written from, exactly (the same node values,
// derivatives and placement numbers, so the same floating-point operations).
TEST(ContactTableFile, CriticalSpeedOfTheTableSceneEqualsTheProfilesScene) {
  const fs::path dir = test::fresh_dir("ctf", "critical");
  const fs::path table = write_file(dir, "s1002.csv", table_text(*s1002_contact().profile_geometry));
  const fs::path scene = write_file(dir, "bogie_table.toml", table_scene_text(table));
  CriticalSpeedOptions o;
  o.from_m_per_s = 20;
  o.to_m_per_s = 60;
  o.grid_step_m_per_s = 5;
  o.mode_shapes_at_critical = false;
  const PreparedScene profiles = prepare_scene(test::case_path("thesis_bogie_s1002_tangent"), {});
  const PreparedScene tabled = prepare_scene(scene.string(), {});
  ASSERT_EQ(tabled.model.contacts.front().spec.geometry, ContactGeometryKind::table);
  EXPECT_TRUE(profiles.equilibrium.state == tabled.equilibrium.state);
  const CriticalSpeedResult a =
      find_critical_speed(profiles.model, profiles.equilibrium.state, profiles.speed_m_per_s, o);
  const CriticalSpeedResult b =
      find_critical_speed(tabled.model, tabled.equilibrium.state, tabled.speed_m_per_s, o);
  ASSERT_TRUE(a.critical_speed_found);
  ASSERT_TRUE(b.critical_speed_found);
  std::cout << "critical speed: profiles " << a.critical_speed_m_per_s << " m/s, table "
            << b.critical_speed_m_per_s << " m/s\n";
  EXPECT_EQ(a.critical_speed_m_per_s, b.critical_speed_m_per_s);
  EXPECT_EQ(a.at_critical.max_real_part, b.at_critical.max_real_part);
  // The quasi-linear linearisation needs the profiles: refused, naming the key.
  try {
    QuasiLinearModelBuilder builder(tabled.model, tabled.equilibrium.state);
    ADD_FAILURE() << "expected the quasi-linear builder to refuse a table contact";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("contacts.s1002_uic60.geometry = \"table\""),
              std::string::npos)
        << e.what();
  }
  fs::remove_all(dir);
}

// Bad files: each error names the file, the line, the key or column and
// what was expected; nothing crashes.
TEST(ContactTableFile, BadFilesAreNamedErrors) {
  const std::string good = table_text(*s1002_contact().profile_geometry);
  const fs::path dir = test::fresh_dir("ctf", "bad");
  auto error_of = [&](const std::string& name, const std::string& text) -> std::string {
    const fs::path p = write_file(dir, name, text);
    try {
      read_contact_table_file(p.string());
    } catch (const ContactTableFileError& e) {
      return e.what();
    }
    return "no error";
  };
  auto line_of = [&](const std::string& text, const std::string& start) {
    std::istringstream in(text);
    std::string l;
    int n = 0;
    while (std::getline(in, l)) {
      ++n;
      if (l.rfind(start, 0) == 0) return n;
    }
    return -1;
  };
  const fs::path base = dir / "x.csv";
  // Not a railstab table.
  EXPECT_NE(error_of("x.csv", "#\n\"rh(51)\" \"N\"\n").find(base.string() + ":2: expected the first line 'key,value'"),
            std::string::npos);
  EXPECT_NE(error_of("x.csv", "key,value\nformat,railstab_contact_table_2\n")
                .find(base.string() + ":2: expected the line 'format,railstab_contact_table_1' after 'key,value'"),
            std::string::npos);
  // A key left out.
  {
    const std::string t = std::regex_replace(good, std::regex("\nflange_angle_rad,[^\n]*"), "");
    const std::string e = error_of("x.csv", t);
    EXPECT_NE(e.find("key 'flange_angle_rad': expected it before the column header"), std::string::npos) << e;
  }
  // An unknown key, with its line.
  {
    std::string t = good;
    t.insert(t.find("slots,"), "slotz,3\n");
    const std::string e = error_of("x.csv", t);
    EXPECT_NE(e.find(base.string() + ":" + std::to_string(line_of(t, "slotz")) + ": key 'slotz'"),
              std::string::npos) << e;
  }
  // A bad number in a node row: file, line and column named.
  {
    std::string t = good;
    const size_t row = t.find("\n0,3,2,");
    const size_t field = t.find(',', t.find(',', t.find(',', t.find(',', row + 1) + 1) + 1) + 1);
    t.replace(field + 1, t.find(',', field + 1) - field - 1, "1.2.3");
    const std::string e = error_of("x.csv", t);
    EXPECT_NE(e.find(base.string() + ":" + std::to_string(line_of(t, "0,3,2,")) +
                     ": column gap0_dq: expected a finite number, got '1.2.3'"),
              std::string::npos) << e;
  }
  // Rows missing at the end.
  {
    const std::string t = good.substr(0, good.rfind('\n', good.size() - 2) + 1);  // last row gone
    const std::string e = error_of("x.csv", t);
    EXPECT_NE(e.find("node rows (slots x lateral nodes 241 x roll nodes 9), got the end of the file"),
              std::string::npos) << e;
  }
  // A grid that does not fit the rows: the counts are named.
  {
    const std::string t = std::regex_replace(good, std::regex("\ntable_roll_step_rad,[^\n]*"),
                                             "\ntable_roll_step_rad,0.01");
    const std::string e = error_of("x.csv", t);
    EXPECT_NE(e.find("(rows run slot by slot, i by i, j by j)"), std::string::npos) << e;
  }
  // A grid too large to allocate is refused before reading the rows.
  {
    std::string t = std::regex_replace(good, std::regex("\ntable_lateral_step_m,[^\n]*"),
                                       "\ntable_lateral_step_m,2e-5");
    t = std::regex_replace(t, std::regex("\ntable_roll_step_rad,[^\n]*"), "\ntable_roll_step_rad,4e-5");
    const std::string e = error_of("x.csv", t);
    EXPECT_NE(e.find("expected at most 2000000 nodes over all slots"), std::string::npos) << e;
  }
  // A missing file and a bad scene r0.
  EXPECT_EQ(error_of("y.csv", good), "no error");
  try {
    read_contact_table_file((dir / "none.csv").string());
    ADD_FAILURE();
  } catch (const ContactTableFileError& e) {
    EXPECT_NE(std::string(e.what()).find("none.csv: contact table file not found"), std::string::npos);
  }
  {
    const fs::path table = write_file(dir, "s1002.csv", good);
    std::string scene = table_scene_text(table);
    scene = std::regex_replace(scene, std::regex("nominal_rolling_radius_m = 0.45"),
                               "nominal_rolling_radius_m = 0.46");
    const fs::path p = write_file(dir, "r0.toml", scene);
    try {
      prepare_scene(p.string(), {});
      ADD_FAILURE() << "expected the r0 mismatch to be refused";
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find("contacts.s1002_uic60.nominal_rolling_radius_m: expected "
                                           "the contact table's nominal rolling radius 0.45"),
                std::string::npos) << e.what();
    }
    // A profile key beside the table is refused by the reader.
    scene = table_scene_text(table);
    scene = std::regex_replace(scene, std::regex("\ncontact_table = "), "\ntrack_gauge_m = 1.435\ncontact_table = ");
    try {
      prepare_scene(write_file(dir, "gauge.toml", scene).string(), {});
      ADD_FAILURE() << "expected track_gauge_m to be refused";
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find("track_gauge_m"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("geometry = \"table\""), std::string::npos) << e.what();
    }
  }
  fs::remove_all(dir);
}
