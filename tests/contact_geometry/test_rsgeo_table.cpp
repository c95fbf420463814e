// DYTSI's RSGEO table as a contact geometry (contact/rsgeo_table.hpp):
// - a cone on a knife-edge rail written as RSGEO (every column in closed
//   form) gives the thesis bogie the critical speed of its knife_edge_cone
//   scene within 0.25 % (measured 0.10 %; the differences: A = cos(delta) /
//   (2 r) against the knife edge's 1 / (2 r), the first-order roll extension);
// - an RSGEO written from railstab's rigid contact of S1002 on UIC60
//   reproduces the profiles' delta r away from the contact jumps (1e-5 m,
//   measured 2.5e-6 m), the rigid roll (1e-5 rad, measured 1.7e-6 rad) and
//   the equivalent conicity at 3 mm (0.1 %, measured 0.022 %);
// - bad files are errors naming the file, the line and the column.
#include <gtest/gtest.h>

#include "support/test_files.hpp"

#include <railstab/contact/hertz.hpp>
#include <railstab/contact/rsgeo_table.hpp>
#include <railstab/contact_geometry/characteristic_functions.hpp>
#include <railstab/contact_geometry/contact_geometry_summary.hpp>
#include <railstab/contact_geometry/table_rigid_contact.hpp>
#include <railstab/setup/contact_tables.hpp>
#include <railstab/setup/prepare_scene.hpp>
#include <railstab/stability/speed_analysis.hpp>

#include <cmath>
#include <fstream>
#include <iostream>
#include <regex>
#include <sstream>

using namespace railstab;
namespace fs = std::filesystem;

namespace {

using Row = std::array<double, kRsgeoColumns>;

const ElasticPair kSteel = combine_materials(2.1e11, 0.25, 2.1e11, 0.25);

// The Hertz columns (N0, a, b, penetration) of a contact with curvatures A, B.
void hertz_columns(Row& row, double A, double B) {
  const double N0 = 5e4;
  const HertzShape<double> h = hertz_shape<double>(A, B, kSteel.effective_modulus_Pa);
  row[size_t(RsgeoColumn::normal_force_N)] = N0;
  row[size_t(RsgeoColumn::semi_axis_a_m)] = h.semi_axis_a_per_force_13 * std::cbrt(N0);
  row[size_t(RsgeoColumn::semi_axis_b_m)] = h.semi_axis_b_per_force_13 * std::cbrt(N0);
  row[size_t(RsgeoColumn::penetration_m)] = h.approach_per_force_23 * std::pow(N0, 2.0 / 3.0);
  row[size_t(RsgeoColumn::c11)] = 4.5;
  row[size_t(RsgeoColumn::c22)] = 4.0;
  row[size_t(RsgeoColumn::c23)] = 1.5;
}

// The thesis knife edge: cone of half-angle gamma, wire rail at e0; the
// left wheel's rigid contact at shift y sits on the wire: a_w = e0 - y,
// r = r0 + tan(gamma) y, delta = gamma, rail height 0.
std::vector<Row> cone_rows(double gamma, double e0, double r0, double rail_radius) {
  std::vector<Row> rows;
  for (int k = -1700; k <= 1700; ++k) {
    const double y = k * 1e-5;
    Row row{};
    row[size_t(RsgeoColumn::y_m)] = y;
    row[size_t(RsgeoColumn::contact_angle_rad)] = gamma;
    row[size_t(RsgeoColumn::wheel_lateral_m)] = e0 - y;
    row[size_t(RsgeoColumn::rolling_radius_m)] = r0 + std::tan(gamma) * y;
    row[size_t(RsgeoColumn::rail_height_m)] = 0.0;
    hertz_columns(row, 0.5 / row[size_t(RsgeoColumn::rolling_radius_m)], 0.5 / rail_radius);
    rows.push_back(row);
  }
  return rows;
}

fs::path write_rsgeo(const fs::path& dir, const std::string& name, const std::vector<Row>& rows) {
  std::ofstream out(dir / name);
  write_rsgeo_table(out, rows);
  return dir / name;
}

fs::path write_file(const fs::path& dir, const std::string& name, const std::string& text) {
  std::ofstream(dir / name) << text;
  return dir / name;
}

CriticalSpeedOptions search() {
  CriticalSpeedOptions o;
  o.from_m_per_s = 20;
  o.to_m_per_s = 60;
  o.grid_step_m_per_s = 5;
  o.mode_shapes_at_critical = false;
  return o;
}

}  // namespace

TEST(RsgeoTable, ConeGivesTheKnifeEdgeCriticalSpeed) {
  const fs::path dir = test::fresh_dir("rsgeo", "cone");
  const fs::path file = write_rsgeo(dir, "cone.dat", cone_rows(0.1, 0.75, 0.45, 0.30));
  std::string scene = test::read_text(test::case_path("thesis_bogie_tangent"));
  for (const char* key : {"cone_angle_rad", "half_contact_distance_m", "rail_head_transverse_radius_m"})
    scene = std::regex_replace(scene, std::regex(std::string("\n") + key + " = [^\n]*"), "");
  scene = std::regex_replace(scene, std::regex("\ngeometry = \"knife_edge_cone\""),
                             "\ngeometry = \"table\"\ncontact_table_format = \"rsgeo\"\n"
                             "contact_table = \"" + file.string() + "\"");
  const fs::path table_scene = write_file(dir, "bogie_rsgeo.toml", scene);
  const PreparedScene knife = prepare_scene(test::case_path("thesis_bogie_tangent"), {});
  const PreparedScene rsgeo = prepare_scene(table_scene.string(), {});
  ASSERT_EQ(rsgeo.model.contacts.front().spec.geometry, ContactGeometryKind::table);
  const CriticalSpeedResult a =
      find_critical_speed(knife.model, knife.equilibrium.state, knife.speed_m_per_s, search());
  const CriticalSpeedResult b =
      find_critical_speed(rsgeo.model, rsgeo.equilibrium.state, rsgeo.speed_m_per_s, search());
  ASSERT_TRUE(a.critical_speed_found);
  ASSERT_TRUE(b.critical_speed_found);
  std::cout << "critical speed: knife edge " << a.critical_speed_m_per_s << " m/s, RSGEO cone "
            << b.critical_speed_m_per_s << " m/s\n";
  EXPECT_NEAR(b.critical_speed_m_per_s, a.critical_speed_m_per_s, 0.0025 * a.critical_speed_m_per_s);
  // The cone's rigid functions on the converted table: delta r = 2 tan(gamma) y.
  const ProfileContactGeometry& g = *rsgeo.model.contacts.front().spec.profile_geometry;
  for (double y : {-8e-3, -2e-3, 1e-3, 5e-3}) {
    const TableRigidRow r = table_rigid_contact(g, y);
    EXPECT_NEAR(r.delta_r_m(), 2 * std::tan(0.1) * y, 1e-8) << "y = " << y;
    EXPECT_NEAR(r.left.contact_angle_rad - r.roll_rad, 0.1, 1e-9) << "y = " << y;
  }
  fs::remove_all(dir);
}

TEST(RsgeoTable, S1002WrittenAsRsgeoKeepsDeltaRAndConicity) {
  const std::vector<ContactSpec> contacts =
      load_scene_contacts(test::case_path("thesis_bogie_s1002_tangent"));
  const ProfileContactGeometry& g = *contacts.front().profile_geometry;
  // The converter: railstab's rigid contact of the left wheel as RSGEO rows.
  std::vector<Row> rows;
  for (const CharacteristicRow& c : characteristic_functions(g.pair, -0.013, 0.013, 2e-5)) {
    const RigidContactSolution& s = c.solution;
    const ContactPoint& p = s.left.front();
    Row row{};
    row[size_t(RsgeoColumn::y_m)] = s.lateral_m;
    row[size_t(RsgeoColumn::contact_angle_rad)] = p.wheel_slope_rad;  // of the normal to the axle
    row[size_t(RsgeoColumn::wheel_lateral_m)] = g.pair.wheel_offset_y_m + p.wheel_u_m;
    row[size_t(RsgeoColumn::rolling_radius_m)] = p.rolling_radius_m;
    row[size_t(RsgeoColumn::rail_height_m)] = p.rail_z_m - g.pair.rail_top_z_m;
    hertz_columns(row, p.A_per_m, std::max(p.B_per_m, 0.03));
    rows.push_back(row);
  }
  const fs::path dir = test::fresh_dir("rsgeo", "s1002");
  const fs::path file = write_rsgeo(dir, "s1002.dat", rows);
  const std::shared_ptr<const ProfileContactGeometry> r =
      read_rsgeo_contact_geometry(file.string(), ContactTableOptions{}, 0.45);
  const std::vector<CharacteristicRow> direct = characteristic_functions(g.pair, -7e-3, 7e-3, 5e-4);
  int compared = 0;
  double worst_dr = 0, worst_roll = 0;
  for (const CharacteristicRow& d : direct) {
    const double y = d.solution.lateral_m;
    if (std::abs(std::abs(y) - 0.2e-3) < 0.6e-3 || std::abs(std::abs(y) - 4.8e-3) < 0.6e-3) continue;
    const TableRigidRow t = table_rigid_contact(*r, y, d.solution.roll_rad);
    ++compared;
    worst_dr = std::max(worst_dr, std::abs(t.delta_r_m() - d.delta_r_m()));
    worst_roll = std::max(worst_roll, std::abs(t.roll_rad - d.solution.roll_rad));
    EXPECT_NEAR(t.delta_r_m(), d.delta_r_m(), 1e-5) << "y = " << y;
    EXPECT_NEAR(t.roll_rad, d.solution.roll_rad, 1e-5) << "y = " << y;
  }
  EXPECT_GE(compared, 13);
  std::cout << "away from the jumps: |delta r - profiles'| <= " << worst_dr
            << " m, |roll - profiles'| <= " << worst_roll << " rad\n";
  const TableContactGeometrySummary t = summarise_table_contact_geometry(*r);
  const ContactGeometrySummary p = summarise_contact_geometry(g.pair);
  ASSERT_TRUE(std::isfinite(t.equivalent_conicity_at_3mm));
  std::cout << "equivalent conicity at 3 mm: profiles " << p.equivalent_conicity_at_3mm
            << ", RSGEO " << t.equivalent_conicity_at_3mm << "\n";
  EXPECT_NEAR(t.equivalent_conicity_at_3mm, p.equivalent_conicity_at_3mm,
              0.001 * p.equivalent_conicity_at_3mm);
  ASSERT_TRUE(r->flange_contact_shift_m.has_value());
  EXPECT_NEAR(*r->flange_contact_shift_m, find_flange_contact(g.pair).lateral_shift_m, 5e-5);
  fs::remove_all(dir);
}

TEST(RsgeoTable, BadFilesAreNamedErrors) {
  const fs::path dir = test::fresh_dir("rsgeo", "bad");
  std::ostringstream good_stream;
  write_rsgeo_table(good_stream, cone_rows(0.1, 0.75, 0.45, 0.30));
  const std::string good = good_stream.str();
  auto error_of = [&](const std::string& text) -> std::string {
    const fs::path p = write_file(dir, "x.dat", text);
    try {
      read_rsgeo_contact_geometry(p.string(), ContactTableOptions{}, 0.45);
    } catch (const ContactTableFileError& e) {
      return e.what();
    }
    return "no error";
  };
  const std::string x = (dir / "x.dat").string();
  EXPECT_EQ(error_of(good), "no error");
  EXPECT_NE(error_of("y N\n1 2\n").find(x + ":2: expected a line starting with '#'"), std::string::npos);
  EXPECT_NE(error_of("#\n\"y\" \"N\"\n").find(x + ":2: expected 13 column names"), std::string::npos);
  {  // line 5 (the third row): a bad number in column 7
    std::string t = good;
    size_t at = 0;
    for (int l = 0; l < 4; ++l) at = t.find('\n', at) + 1;
    size_t field = at;
    for (int c = 0; c < 6; ++c) field = t.find(' ', field) + 1;
    t.replace(field, t.find(' ', field) - field, "0.4x");
    const std::string e = error_of(t);
    EXPECT_NE(e.find(x + ":5: column 7 (rolling radius): expected a finite number, got '0.4x'"),
              std::string::npos) << e;
  }
  {  // a row short of a column
    std::string t = good;
    const size_t at = t.find('\n', t.find('\n', t.find('\n') + 1) + 1);  // end of line 3
    t.erase(t.rfind(' ', at), at - t.rfind(' ', at));
    const std::string e = error_of(t);
    EXPECT_NE(e.find(x + ":3: expected 13 numbers (as the column names), got 12"), std::string::npos) << e;
  }
  {  // y not increasing: the third row repeated
    std::string t = good;
    size_t a = 0;
    for (int l = 0; l < 4; ++l) a = t.find('\n', a) + 1;
    const size_t b = t.find('\n', a) + 1;
    t.insert(b, t.substr(a, b - a));
    const std::string e = error_of(t);
    EXPECT_NE(e.find(x + ":6: column 1 (y): expected y increasing down the file"), std::string::npos) << e;
  }
  {  // DYTSI's own layout (the head of its input/RSGEO/1o40/RSGEO.dat, tab-separated
     // quoted names): read as written; one-sided in y, so the conversion refuses it.
    const std::string head =
        "#\n\"rh(51)\"\t\"Normalforce\"\t\"DATAN(TANDJA(1,1))\"\t\"a(1,1)\"\t\"b(1,1)\"\t"
        "\"BJA(2,1,1)+0,75\"\t\"R0J(1,1)\"\t\"c11\"\t\"c22\"\t\"c23\"\t\"BJA(3,1,1)\"\t"
        "\"Penetration\"\t\"BJA(2,1,1)+0.75+rh(51)\"\n";
    std::string rows;
    for (int k = 0; k < 5; ++k)
      rows += std::to_string(-1.7e-2 + k * 1e-5) +
              " 6.6604470702e+04 4.3652537000e-02 6.5693100000e-03 3.5227100000e-03 "
              "7.7517370700e-01 4.2454303000e-01 5.0797987282e+00 4.8039449537e+00 "
              "2.4918722160e+00 -5.2853178000e-05 1.1849300000e-04 0.0000000000e+00\n";
    const fs::path p = write_file(dir, "dytsi.dat", head + rows);
    const RsgeoTable t = read_rsgeo_table(p.string());
    ASSERT_EQ(t.rows.size(), 5u);
    EXPECT_DOUBLE_EQ(t.rows[0][size_t(RsgeoColumn::rolling_radius_m)], 0.42454303);
    EXPECT_DOUBLE_EQ(t.rows[0][size_t(RsgeoColumn::rail_height_m)], -5.2853178e-05);
    EXPECT_EQ(t.line[0], 3);
    try {
      rsgeo_contact_geometry(t, ContactTableOptions{}, 0.425);
      ADD_FAILURE() << "expected the one-sided table to be refused";
    } catch (const ContactTableFileError& e) {
      EXPECT_NE(std::string(e.what()).find("column 1 (y): expected shifts on both sides of 0"),
                std::string::npos) << e.what();
    }
  }
  {  // a grid the file does not cover: the key named
    ContactTableOptions wide;
    wide.lateral_half_range_m = 0.025;
    const fs::path p = write_file(dir, "y.dat", good);
    try {
      read_rsgeo_contact_geometry(p.string(), wide, 0.45);
      ADD_FAILURE() << "expected a range error";
    } catch (const ContactTableFileError& e) {
      EXPECT_NE(std::string(e.what()).find("table_lateral_half_range_m = 0.025: expected a lateral "
                                           "half range the file covers"),
                std::string::npos) << e.what();
    }
  }
  fs::remove_all(dir);
}
