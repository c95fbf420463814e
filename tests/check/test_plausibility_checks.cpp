// Plausibility checks (docs/commands.md, "Plausibility checks"): each input
// mistake of issue 24 item 3 built from a shipped case by --set or a small
// edit, the check that catches it, and the expected numbers from the closed
// form of the rule (not from the code's output).
#include <railstab/check/model_check.hpp>
#include <railstab/check/run_check.hpp>
#include <railstab/contact_geometry/characteristic_functions.hpp>
#include <railstab/contact_geometry/profile_contact_geometry.hpp>
#include <railstab/profiles/profile_readers.hpp>
#include <railstab/profiles/profile_validation.hpp>
#include <railstab/scene_reading/load_scene.hpp>
#include <railstab/setup/prepare_scene.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli/run_cli.hpp"
#include "support/test_files.hpp"

namespace railstab {
namespace {

namespace fs = std::filesystem;
using railstab::test::case_path;
using railstab::test::read_text;

constexpr double kPi = 3.14159265358979323846;

std::string listing(const ModelCheckReport& r) {
  std::string s;
  for (const ModelWarning& w : r.warnings) s += w.kind + ": " + w.message + "\n";
  for (const std::string& e : r.errors) s += "error: " + e + "\n";
  return s;
}

const ModelWarning* find_warning(const ModelCheckReport& r, const std::string& kind) {
  for (const ModelWarning& w : r.warnings)
    if (w.kind == kind) return &w;
  return nullptr;
}

// `railstab check CASE --set ... [--speed V] [--arc-length S]` as a library call.
ModelCheckReport check_case(const std::string& name, const std::vector<SceneValueSetting>& set,
                            std::optional<double> speed = {},
                            std::optional<double> arc_length = {}) {
  SceneOverrides o;
  o.values = set;
  o.speed_m_per_s = speed;
  o.reference_arc_length_m = arc_length;
  ModelCheckOptions options;
  options.natural_frequencies = false;
  return check_scene(load_scene_with_overrides(case_path(name), o), options);
}

// The number as the check's messages print it (ostream, 6 digits).
std::string printed(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// --- profile orientation ------------------------------------------------------------------
const std::string kProfiles = std::string(RAILSTAB_CASES_DIR) + "/profiles/";

// A profile written as two columns in metres, each point mapped by `map`.
fs::path write_mapped_profile(const fs::path& dir, const std::string& file, const Profile& p,
                              double sy, double sz) {
  const fs::path path = dir / file;
  std::ofstream out(path);
  out.precision(17);
  for (size_t i = 0; i < p.y_m.size(); ++i) out << sy * p.y_m[i] << " " << sz * p.z_m[i] << "\n";
  return path;
}

// thesis_bogie_s1002_tangent with its profile files given by absolute paths
// (the scene is written to a temporary folder).
fs::path s1002_bogie_with(const fs::path& dir, const std::string& wheel_key,
                          const std::string& rail_key) {
  std::string text = read_text(case_path("thesis_bogie_s1002_tangent"));
  const std::string wheel = "wheel_profile = \"profiles/MBench_S1002_v3.prw\"";
  const std::string rail = "rail_profile = \"profiles/MBench_UIC60_v3.prr\"";
  EXPECT_NE(text.find(wheel), std::string::npos);
  EXPECT_NE(text.find(rail), std::string::npos);
  text.replace(text.find(wheel), wheel.size(), wheel_key);
  text.replace(text.find(rail), rail.size(), rail_key);
  const fs::path scene = dir / "bogie.toml";
  std::ofstream(scene) << text;
  return scene;
}

std::string load_error(const fs::path& scene) {
  try {
    load_scene_with_overrides(scene.string(), {});
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

// S1002 rotated by 180 degrees ((y, z) -> (-y, -z)): the flange points up and
// out, the inner end is still lower than the field end (the check before
// this one passed it: conicity 0.018, "no flange contact up to 14 mm").
TEST(PlausibilityProfile, WheelRotatedBy180DegreesIsAnErrorNamingTheFile) {
  const fs::path dir = railstab::test::fresh_dir("plaus", "rotated_wheel");
  const Profile s1002 = read_simpack_profile(kProfiles + "MBench_S1002_v3.prw", ProfileKind::wheel);
  const fs::path rotated = write_mapped_profile(dir, "s1002_rotated.txt", s1002, -1.0, -1.0);
  const fs::path upright = write_mapped_profile(dir, "s1002_upright.txt", s1002, 1.0, 1.0);
  const std::string rail = "rail_profile = \"" + kProfiles + "MBench_UIC60_v3.prr\"";
  const std::string e = load_error(
      s1002_bogie_with(dir, "wheel_profile_m = \"" + rotated.string() + "\"", rail));
  EXPECT_NE(e.find("s1002_rotated.txt"), std::string::npos) << e;
  EXPECT_NE(e.find("flange points up"), std::string::npos) << e;
  EXPECT_NE(e.find("rotated by 180"), std::string::npos) << e;
  // The flange tip of S1002 (its lowest point, 28.0 mm below the tape
  // circle): rotated, the highest point, at the mirrored y.
  const size_t tip = size_t(std::min_element(s1002.z_m.begin(), s1002.z_m.end()) - s1002.z_m.begin());
  EXPECT_NE(e.find("rises to z = " + printed(-s1002.z_m[tip]) + " m at y = " + printed(-s1002.y_m[tip])),
            std::string::npos)
      << e;
  // `railstab check` and an analysis stop with it, exit 1, nothing written.
  for (const char* command : {"check", "critical-speed"}) {
    const auto run = railstab::test::run_railstab(
        {command, (dir / "bogie.toml").string(), "--out", "out"}, dir);
    EXPECT_EQ(run.exit_code, 1) << run.output;
    EXPECT_NE(run.output.find("s1002_rotated.txt"), std::string::npos) << run.output;
    EXPECT_FALSE(fs::exists(dir / "out")) << command;
  }
  // The same points upright are accepted (the rule rejects the orientation only).
  EXPECT_EQ(load_error(s1002_bogie_with(dir, "wheel_profile_m = \"" + upright.string() + "\"",
                                        rail)),
            "");
  fs::remove_all(dir);
}

TEST(PlausibilityProfile, WheelMirroredInYWithTheFlangeOnTheFieldSideIsAnError) {
  // A flat tread with a 28 mm flange at y = +55 mm reaching down and a field
  // end raised 10 mm beyond it, so that z(inner end) < z(field end) still
  // holds and only the flange's side gives the mirror away.
  std::vector<RawProfilePoint> pts;
  for (int i = 0; i <= 100; ++i) {
    const double y = -0.03 + 0.1 * i / 100.0;
    const double flange = -0.028 * std::exp(-std::pow((y - 0.055) / 0.006, 2));
    pts.push_back({y, flange + (y > 0.065 ? 0.01 : 0.0), i + 1});
  }
  try {
    make_profile(ProfileKind::wheel, "mirrored.txt", pts);
    FAIL() << "accepted a flange on the field side";
  } catch (const ProfileError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("mirrored.txt"), std::string::npos) << m;
    EXPECT_NE(m.find("on the field side"), std::string::npos) << m;
  }
}

// UIC60 upside down ((y, z) -> (-y, -z)): the head's sides become its highest points.
TEST(PlausibilityProfile, RailUpsideDownIsAnErrorNamingTheFile) {
  const fs::path dir = railstab::test::fresh_dir("plaus", "rail_upside_down");
  const Profile uic60 = read_simpack_profile(kProfiles + "MBench_UIC60_v3.prr", ProfileKind::rail);
  const fs::path flipped = write_mapped_profile(dir, "uic60_upside_down.txt", uic60, -1.0, -1.0);
  const std::string e = load_error(s1002_bogie_with(
      dir, "wheel_profile = \"" + kProfiles + "MBench_S1002_v3.prw\"",
      "rail_profile_m = \"" + flipped.string() + "\""));
  EXPECT_NE(e.find("uic60_upside_down.txt"), std::string::npos) << e;
  EXPECT_NE(e.find("highest point of the rail profile is at an end"), std::string::npos) << e;
  fs::remove_all(dir);
}

// --- series stiffness against the damper's corner frequency -------------------------------
// coach_tangent's yaw dampers: table slope at 0 = 9000 N / 0.02 m/s = 450 kN s/m.
constexpr double kYawDamperC = 9000.0 / 0.02;

TEST(PlausibilitySeriesDamper, StiffnessInMNPerMGivenAsNPerMIsCaught) {
  const ModelCheckReport r =
      check_case("coach_tangent", {{"elements.yaw_damper_bogie1.series_stiffness_N_per_m", 6.0}});
  const ModelWarning* w = find_warning(r, "series_damper_corner_below_band");
  ASSERT_NE(w, nullptr) << listing(r);
  EXPECT_EQ(w->subject.rfind("yaw_damper_bogie1", 0), 0u) << w->subject;
  // f_c = k_s / (2 pi c) = 6 / (2 pi 450000) = 2.12e-6 Hz.
  EXPECT_NE(w->message.find(printed(6.0 / (2.0 * kPi * kYawDamperC)) + " Hz"), std::string::npos)
      << w->message;
  EXPECT_NE(w->message.find("MN/m"), std::string::npos) << w->message;
  // Only bogie 1's two dampers (mirrored pair) are wrong.
  int count = 0;
  for (const ModelWarning& x : r.warnings) count += x.kind == "series_damper_corner_below_band";
  EXPECT_EQ(count, 2) << listing(r);
}

TEST(PlausibilitySeriesDamper, ShippedStiffnessIsInTheBandAndNPerMmIsAbove) {
  // 6 MN/m: f_c = 2.12 Hz, inside [0.5, 20] Hz.
  const ModelCheckReport shipped = check_case("coach_tangent", {});
  EXPECT_FALSE(shipped.has_warning("series_damper_corner_below_band")) << listing(shipped);
  EXPECT_FALSE(shipped.has_warning("series_damper_corner_above_band")) << listing(shipped);
  // 6 MN/m read in N/mm: 6e9 N/m, f_c = 2122 Hz > 100 x 20 Hz.
  const ModelCheckReport stiff = check_case(
      "coach_tangent", {{"elements.yaw_damper_bogie2.series_stiffness_N_per_m", 6e9}});
  const ModelWarning* w = find_warning(stiff, "series_damper_corner_above_band");
  ASSERT_NE(w, nullptr) << listing(stiff);
  EXPECT_NE(w->message.find(printed(6e9 / (2.0 * kPi * kYawDamperC)) + " Hz"), std::string::npos)
      << w->message;
  // The study's 1000 MN/m (f_c = 354 Hz) is a legitimate stiff mount: no warning.
  const ModelCheckReport study = check_case(
      "coach_tangent", {{"elements.yaw_damper_bogie2.series_stiffness_N_per_m", 1e9}});
  EXPECT_FALSE(study.has_warning("series_damper_corner_above_band")) << listing(study);
}

// --- cant: direction, deficiency, excess ---------------------------------------------------
// coach_curve: left-hand arc R = 1000 m (track.segments[2]) after a clothoid
// (segments[1]); cant 50 mm; D = 1.5 m. Arc length 2000 m is inside the arc.
constexpr double kArc_m = 2000.0, kR_m = 1000.0, kD_m = 1.5, kG = 9.81;

TEST(PlausibilityCant, CantOnTheInnerRailIsCaught) {
  const ModelCheckReport r = check_case("coach_curve",
                                        {{"track.segments[1].end_cant_m", -0.05},
                                         {"track.segments[2].end_cant_m", -0.05}},
                                        30.0, kArc_m);
  const ModelWarning* w = find_warning(r, "cant_on_inner_rail");
  ASSERT_NE(w, nullptr) << listing(r);
  EXPECT_NE(w->message.find("R = 1000 m left"), std::string::npos) << w->message;
  EXPECT_NE(w->message.find("cant -50 mm"), std::string::npos) << w->message;
  EXPECT_NE(w->message.find("wheelset1"), std::string::npos) << w->message;
  // The shipped curve, same place: cant on the outer rail.
  const ModelCheckReport shipped = check_case("coach_curve", {}, 30.0, kArc_m);
  EXPECT_FALSE(shipped.has_warning("cant_on_inner_rail")) << listing(shipped);
  EXPECT_FALSE(shipped.has_warning("cant_deficiency_beyond_limit")) << listing(shipped);
}

TEST(PlausibilityCant, DeficiencyAndExcessBeyondTheLineLimits) {
  // 45 m/s: I = D V^2 / (g R) - cant = 1.5 * 2025 / 9810 - 0.05 = 259.6 mm > 150 mm.
  const double V = 45.0;
  const ModelCheckReport fast = check_case("coach_curve", {}, V, kArc_m);
  const ModelWarning* d = find_warning(fast, "cant_deficiency_beyond_limit");
  ASSERT_NE(d, nullptr) << listing(fast);
  EXPECT_NE(d->message.find("cant deficiency " + printed((kD_m * V * V / (kG * kR_m) - 0.05) * 1e3) +
                            " mm"),
            std::string::npos)
      << d->message;
  // 35 m/s: I = 1.5 * 1225 / 9810 - 0.05 = 137.3 mm, inside the 150 mm limit.
  EXPECT_FALSE(check_case("coach_curve", {}, 35.0, kArc_m).has_warning("cant_deficiency_beyond_limit"));
  // Cant 150 mm at 5 m/s: E = 0.15 - 1.5 * 25 / 9810 = 146.2 mm > 110 mm.
  const double slow = 5.0;
  const ModelCheckReport excess = check_case(
      "coach_curve", {{"track.segments[1].end_cant_m", 0.15}, {"track.segments[2].end_cant_m", 0.15}},
      slow, kArc_m);
  const ModelWarning* e = find_warning(excess, "cant_excess_beyond_limit");
  ASSERT_NE(e, nullptr) << listing(excess);
  EXPECT_NE(e->message.find("cant excess " +
                            printed((0.15 - kD_m * slow * slow / (kG * kR_m)) * 1e3) + " mm"),
            std::string::npos)
      << e->message;
}

// A canted straight: no speed balances the cant, so all of it is excess
// (h_d = -|h|), whichever rail it raises; 120 mm > the 110 mm excess limit.
TEST(PlausibilityCant, CantOnAStraightIsExcess) {
  for (const double cant : {0.12, -0.12}) {
    const ModelCheckReport r = check_case(
        "coach_tangent", {{"track.start_cant_m", cant}, {"track.segments[0].end_cant_m", cant}}, 30.0);
    const ModelWarning* e = find_warning(r, "cant_excess_beyond_limit");
    ASSERT_NE(e, nullptr) << listing(r);
    EXPECT_NE(e->message.find("cant excess " + printed(120.0) + " mm"), std::string::npos)
        << e->message;
    EXPECT_FALSE(r.has_warning("cant_deficiency_beyond_limit")) << listing(r);
  }
}

// --- wheel-load balance and the steady shift -------------------------------------------------
// Cant on the wrong rail at speed: the 80 kN against 22 kN.
TEST(PlausibilityEquilibrium, UnbalancedWheelLoadsAreCaught) {
  const ModelCheckReport r = check_case("coach_curve",
                                        {{"track.segments[1].end_cant_m", -0.15},
                                         {"track.segments[2].end_cant_m", -0.15}},
                                        40.0, kArc_m);
  ASSERT_TRUE(r.errors.empty()) << listing(r);
  const ModelWarning* w = find_warning(r, "wheel_loads_unbalanced");
  ASSERT_NE(w, nullptr) << listing(r);
  // The rule on the report's own wheel loads: every axle whose larger over
  // smaller load exceeds 2.5 is named, and no other (here 3.3 to 6.8).
  for (const AxleLoad& a : r.axle_loads) {
    const double ratio = std::max(a.left_N, a.right_N) / std::min(a.left_N, a.right_N);
    bool named = false;
    for (const ModelWarning& x : r.warnings)
      named = named || (x.kind == "wheel_loads_unbalanced" && x.subject == a.wheelset);
    EXPECT_EQ(named, ratio > 2.5) << a.wheelset << " ratio " << ratio;
  }
  // The shipped curve at 37 m/s, 159 mm deficiency (ratio 2.17): within it.
  EXPECT_FALSE(check_case("coach_curve", {}, 37.0, kArc_m).has_warning("wheel_loads_unbalanced"));
}

// The knife-edge coach in the R = 1000 m arc with its flange clearance cut
// to 1 mm: the steady shift (several mm outwards at 40 m/s) is beyond it.
TEST(PlausibilityEquilibrium, SteadyShiftBeyondTheFlangeClearanceIsCaught) {
  const ModelCheckReport r = check_case(
      "coach_curve", {{"contacts.equivalent_cone.flange_clearance_m", 0.001}}, 40.0, kArc_m);
  ASSERT_TRUE(r.errors.empty()) << listing(r);
  const ModelWarning* w = find_warning(r, "lateral_shift_beyond_flange_clearance");
  ASSERT_NE(w, nullptr) << listing(r);
  EXPECT_NE(w->message.find("flange_clearance_m = 1 mm"), std::string::npos) << w->message;
  EXPECT_NE(w->message.find("steady lateral shift"), std::string::npos) << w->message;
  EXPECT_FALSE(check_case("coach_curve", {}, 40.0, kArc_m)
                   .has_warning("lateral_shift_beyond_flange_clearance"));
}

// --- the speed-dependent checks over a sweep's speeds (issue 24, item 3) -----------------------
// The steady states of coach_curve in its R = 1000 m arc (cant 50 mm) at
// `speeds`, with the settings, as a critical-speed grid holds them.
struct SweepStates {
  PreparedScene scene;
  std::vector<Eigen::VectorXd> states;
  std::vector<SpeedSteadyState> points;
};
SweepStates coach_curve_states(const std::vector<double>& speeds,
                               const std::vector<SceneValueSetting>& set = {}) {
  SceneOverrides o;
  o.values = set;
  o.reference_arc_length_m = kArc_m;
  o.speed_m_per_s = speeds.front();
  SweepStates s{prepare_scene(case_path("coach_curve"), o), {}, {}};
  Eigen::VectorXd x = s.scene.equilibrium.state;
  for (double V : speeds) {
    x = solve_equilibrium(s.scene.model, V, x).state;  // continued in speed, as the grid does
    s.states.push_back(x);
  }
  for (size_t i = 0; i < speeds.size(); ++i) s.points.push_back({speeds[i], &s.states[i]});
  return s;
}

const ModelWarning* find_in(const std::vector<ModelWarning>& ws, const std::string& kind,
                            const std::string& subject = "") {
  for (const ModelWarning& w : ws)
    if (w.kind == kind && (subject.empty() || w.subject == subject)) return &w;
  return nullptr;
}

// Deficiency I(V) = D V^2 / (g R) - cant exceeds 150 mm above
// V = sqrt(g R (0.15 + 0.05) / D) = 36.17 m/s: of 30, 35, 40 and 45 m/s the
// last two, the worst at 45 m/s (259.6 mm). check_model at the scene's
// 30 m/s alone says nothing.
TEST(PlausibilitySpeedRange, CantDeficiencyIsFoundAtTheSpeedsOfTheRangeBeyondTheLimit) {
  const SweepStates s = coach_curve_states({30.0, 35.0, 40.0, 45.0});
  EXPECT_FALSE(check_model(s.scene.spec, s.scene.model, 30.0, s.scene.equilibrium, {})
                   .has_warning("cant_deficiency_beyond_limit"));
  const std::vector<ModelWarning> ws = check_speed_range(s.scene.model, s.points);
  const ModelWarning* d = find_in(ws, "cant_deficiency_beyond_limit");
  ASSERT_NE(d, nullptr);
  EXPECT_NE(d->message.find("at 2 of 4 speeds checked (40 to 45 m/s)"), std::string::npos) << d->message;
  const double worst_mm = (kD_m * 45.0 * 45.0 / (kG * kR_m) - 0.05) * 1e3;
  EXPECT_NE(d->message.find("cant deficiency " + printed(worst_mm) + " mm at 45 m/s"), std::string::npos)
      << d->message;
  // Every speed-dependent warning is check_model's at the speeds where
  // check_model, run at each speed alone, raises it (here also the trailing
  // wheelsets' load ratio 3.2 at 45 m/s, 260 mm deficiency), and no other.
  const std::vector<std::string> kinds = {"cant_deficiency_beyond_limit", "cant_excess_beyond_limit",
                                          "wheel_loads_unbalanced", "lateral_shift_beyond_flange_clearance"};
  std::map<std::pair<std::string, std::string>, std::vector<double>> single;
  for (size_t i = 0; i < s.points.size(); ++i) {
    EquilibriumResult eq;
    eq.state = s.states[i];
    const double V = s.points[i].speed_m_per_s;
    for (const ModelWarning& w : check_model(s.scene.spec, s.scene.model, V, eq, {}).warnings)
      if (std::find(kinds.begin(), kinds.end(), w.kind) != kinds.end()) single[{w.kind, w.subject}].push_back(V);
  }
  EXPECT_EQ(ws.size(), single.size());
  EXPECT_NE(single.find({"wheel_loads_unbalanced", "wheelset2"}), single.end());
  for (const auto& [id, speeds] : single) {
    const ModelWarning* w = find_in(ws, id.first, id.second);
    ASSERT_NE(w, nullptr) << id.first << " " << id.second;
    std::ostringstream range;
    range << "at " << speeds.size() << " of 4 speeds checked (" << speeds.front();
    if (speeds.size() > 1) range << " to " << speeds.back();
    range << " m/s)";
    EXPECT_NE(w->message.find(range.str()), std::string::npos) << range.str() << " in: " << w->message;
  }
  // A speed without a steady state (the grid stopped below the top speed
  // asked) is checked for the cant alone.
  std::vector<SpeedSteadyState> with_top = s.points;
  with_top.push_back({50.0, nullptr});
  const ModelWarning* top = find_in(check_speed_range(s.scene.model, with_top), "cant_deficiency_beyond_limit");
  ASSERT_NE(top, nullptr);
  EXPECT_NE(top->message.find("at 3 of 5 speeds checked (40 to 50 m/s)"), std::string::npos) << top->message;
}

// Cant 150 mm: excess E = cant - D V^2 / (g R) beyond 110 mm below
// V = sqrt(g R (0.15 - 0.11) / D) = 16.17 m/s, worst at the lowest speed.
TEST(PlausibilitySpeedRange, CantExcessIsWorstAtTheLowestSpeed) {
  const SweepStates s = coach_curve_states(
      {5.0, 10.0, 15.0, 20.0},
      {{"track.segments[1].end_cant_m", 0.15}, {"track.segments[2].end_cant_m", 0.15}});
  const ModelWarning* e = find_in(check_speed_range(s.scene.model, s.points), "cant_excess_beyond_limit");
  ASSERT_NE(e, nullptr);
  EXPECT_NE(e->message.find("at 3 of 4 speeds checked (5 to 15 m/s)"), std::string::npos) << e->message;
  EXPECT_NE(e->message.find("cant excess " + printed((0.15 - kD_m * 25.0 / (kG * kR_m)) * 1e3) + " mm at 5 m/s"),
            std::string::npos)
      << e->message;
}

// The cant on the wrong rail: at walking pace the wheel loads are
// near balanced; at 40 m/s the check_model test above finds ratios of 3.3
// to 6.8. Each wheelset is named once, with the speeds where it exceeds 2.5,
// and the ratios in the worst message are those of the steady state at that
// speed.
TEST(PlausibilitySpeedRange, UnbalancedWheelLoadsAreFoundPerWheelsetAtTheirSpeeds) {
  const SweepStates s = coach_curve_states(
      {5.0, 40.0}, {{"track.segments[1].end_cant_m", -0.15}, {"track.segments[2].end_cant_m", -0.15}});
  const std::vector<ModelWarning> ws = check_speed_range(s.scene.model, s.points);
  EquilibriumResult at40;
  at40.state = s.states[1];
  const ModelCheckReport single = check_model(s.scene.spec, s.scene.model, 40.0, at40, {});
  int named = 0;
  for (const AxleLoad& a : single.axle_loads) {
    const double ratio = std::max(a.left_N, a.right_N) / std::min(a.left_N, a.right_N);
    const ModelWarning* w = find_in(ws, "wheel_loads_unbalanced", a.wheelset);
    ASSERT_EQ(w != nullptr, ratio > 2.5) << a.wheelset << " ratio " << ratio;
    if (!w) continue;
    ++named;
    EXPECT_NE(w->message.find("(40 m/s)"), std::string::npos) << w->message;
    EXPECT_NE(w->message.find("ratio " + printed(ratio)), std::string::npos) << w->message;
  }
  EXPECT_GT(named, 0);
}

// The command: a sweep through the limit warns on stderr, naming the range.
TEST(PlausibilitySpeedRange, CriticalSpeedSweepWarnsOnStderr) {
  const fs::path dir = fs::temp_directory_path() / ("railstab_speed_range_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const auto run = railstab::test::run_railstab(
      {"critical-speed", case_path("thesis_bogie_curve"), "--arc-length", "2000", "--from", "20",
       "--to", "45", "--step", "5", "--no-plots", "--out", "out"},
      dir);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  // I > 150 mm above 36.17 m/s: 40 and 45 m/s of the grid (and no warning
  // at the scene's own 20 m/s before the search).
  EXPECT_NE(run.output.find("warning: in the speed range, at 2 of 6 speeds checked (40 to 45 m/s); "
                            "the worst: cant deficiency"),
            std::string::npos)
      << run.output;
  fs::remove_all(dir);
}

// --- a run that stays in flange contact (simulate) --------------------------------------------
// The S1002 bogie's states with wheelset1 shifted by `y_of(t)`: the rule looks
// only at the last quarter of the run against the pair's flange-contact shift.
TEST(PlausibilityRun, WheelsetInFlangeContactToTheEndIsCaught) {
  const PreparedScene s = prepare_scene(case_path("thesis_bogie_s1002_tangent"), {});
  const Body& ws = s.model.bodies[0];
  ASSERT_TRUE(ws.wheelset());
  const int k = ws.state_index[int(CoordinateIndex::y)];
  ASSERT_GE(k, 0);
  const FlangeContact flange =
      find_flange_contact(s.model.contacts[size_t(ws.wheelset()->contact)].spec.profile_geometry->pair);
  ASSERT_TRUE(flange.found);
  const double y_f = flange.lateral_shift_m;
  EXPECT_GT(y_f, 0.004);  // new S1002 on UIC60 1:40: flange contact at ~6-7 mm
  EXPECT_LT(y_f, 0.010);
  auto run = [&](auto y_of) {
    Trajectory traj;
    for (int i = 0; i <= 40; ++i) {
      traj.times_s.push_back(0.1 * i);
      traj.states.push_back(s.equilibrium.state);
      traj.states.back()(k) = y_of(0.1 * i);
    }
    return check_run(s.model, traj);
  };
  // Settles at -1.3 y_f from t = 2 s: beyond it through the last 1 s of 4 s.
  const std::vector<ModelWarning> settled = run([&](double t) { return t < 2.0 ? 0.0 : -1.3 * y_f; });
  ASSERT_EQ(settled.size(), 1u);
  EXPECT_EQ(settled[0].kind, "flanging_to_the_end");
  EXPECT_EQ(settled[0].subject, ws.name);
  EXPECT_NE(settled[0].message.find("through the last 1 s"), std::string::npos) << settled[0].message;
  EXPECT_NE(settled[0].message.find(printed(-1.3 * y_f * 1e3) + " mm at t = 4 s"), std::string::npos)
      << settled[0].message;
  // A flange contact that passes (back on the tread after 3.5 s) and a run
  // just inside the shift are not reported.
  EXPECT_TRUE(run([&](double t) { return t < 3.5 ? 1.3 * y_f : 0.0; }).empty());
  EXPECT_TRUE(run([&](double) { return 0.99 * y_f; }).empty());
}

// --- scene reader ranges: cone angle, gravity, minimum speed -------------------------------
std::string scene_error(const std::string& name, const std::vector<SceneValueSetting>& set,
                        std::optional<double> speed = {}) {
  SceneOverrides o;
  o.values = set;
  o.speed_m_per_s = speed;
  try {
    load_scene_with_overrides(case_path(name), o);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

TEST(PlausibilityRanges, ConeAngleOutsideTheDocumentedRangeIsRejected) {
  for (double gamma : {0.0, 0.005, 0.41, 0.5}) {
    const std::string e =
        scene_error("thesis_bogie_tangent", {{"contacts.thesis_knife_edge.cone_angle_rad", gamma}});
    EXPECT_NE(e.find("contacts.thesis_knife_edge.cone_angle_rad: expected a knife-edge cone angle "
                     "in [0.01, 0.4] rad"),
              std::string::npos)
        << gamma << ": " << e;
  }
  for (double gamma : {0.01, 0.025, 0.4})
    EXPECT_EQ(scene_error("thesis_bogie_tangent",
                          {{"contacts.thesis_knife_edge.cone_angle_rad", gamma}}),
              "")
        << gamma;
}

TEST(PlausibilityRanges, GravityBelowOneWithHertzContactIsRejected) {
  const std::string e = scene_error("thesis_bogie_tangent", {{"scene.gravity_m_per_s2", 0.0}});
  EXPECT_NE(e.find("scene.gravity_m_per_s2: expected a gravity (a Hertz wheel-rail contact "
                   "carries the weight) in [1, 100] m/s2, got 0"),
            std::string::npos)
      << e;
}

TEST(PlausibilityRanges, SpeedBelowTheCreepLawsValidityIsRejected) {
  const std::string e = scene_error("thesis_bogie_s1002_tangent", {{"scene.speed_m_per_s", 1e-9}});
  EXPECT_NE(e.find("scene.speed_m_per_s: expected at least kMinimumCreepSpeed_m_per_s = 0.1 m/s"),
            std::string::npos)
      << e;
  // --speed takes the same check.
  const std::string flag = scene_error("thesis_bogie_s1002_tangent", {}, 0.05);
  EXPECT_NE(flag.find("kMinimumCreepSpeed_m_per_s = 0.1 m/s"), std::string::npos) << flag;
  EXPECT_EQ(scene_error("thesis_bogie_s1002_tangent", {}, 0.1), "");
}

// --- every shipped case: no plausibility warning it does not deserve ------------------------
// The extreme cases are built to exceed line limits; each listed warning is
// the one its header describes.
TEST(PlausibilityShippedCases, NoNewWarningOnAnyShippedCase) {
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
      {"coach_curve", {}},
      {"coach_s1002_curve", {}},
      {"coach_tangent", {}},
      {"extreme_cant_deficiency", {}},
      {"extreme_cant_excess", {}},
      {"extreme_conservative", {}},
      {"extreme_high_speed", {}},
      {"extreme_lift_off", {}},
      {"extreme_low_speed", {}},
      {"extreme_near_critical", {}},
      {"extreme_stiff_contact", {}},
      {"extreme_tight_curve", {}},
      {"extreme_zero_damping", {}},
      {"s1002_uic60_contact", {}},
      {"textbook_bogie", {}},
      {"textbook_wheelset", {}},
      {"thesis_bogie_curve", {}},
      {"thesis_bogie_s1002_curve", {}},
      {"thesis_bogie_s1002_tangent", {}},
      {"thesis_bogie_tangent", {}},
      {"thesis_train_4", {}},
      {"thesis_vehicle_curve", {}},
      {"thesis_vehicle_s1002_curve", {}},
      {"thesis_vehicle_s1002_tangent", {}},
      {"thesis_vehicle_tangent", {}},
  };
  const std::vector<std::string> plausibility = {
      "series_damper_corner_below_band", "series_damper_corner_above_band", "cant_on_inner_rail",
      "cant_deficiency_beyond_limit",    "cant_excess_beyond_limit",        "wheel_loads_unbalanced",
      "lateral_shift_beyond_flange_clearance"};
  for (const auto& [name, expected] : cases) {
    const std::string text = read_text(case_path(name));
    if (text.find("[[bodies]]") == std::string::npos && text.find("[train") == std::string::npos)
      continue;  // a contact-geometry case: no vehicle
    const ModelCheckReport r = check_case(name, {});
    std::vector<std::string> found;
    for (const ModelWarning& w : r.warnings)
      if (std::find(plausibility.begin(), plausibility.end(), w.kind) != plausibility.end() &&
          std::find(found.begin(), found.end(), w.kind) == found.end())
        found.push_back(w.kind);
    EXPECT_EQ(found, expected) << name << ":\n" << listing(r);
  }
}

}  // namespace
}  // namespace railstab
