// Any combination of free coordinates and element internal states is a model
// that the stability analysis describes without crashing (issue 24: the coach
// with `free = []` on every body died with signal 11, the series dampers'
// internal states remaining when no body coordinate did).
//
// Oracle for the extreme combination: with every body held, each yaw damper
// (damper c in series with k_s) is a first-order system with its ends fixed,
//   c de_d/dt = k_s (e - e_d)  =>  lambda = -k_s / c,
// c = the damper table's slope at 0 (9000 N / 0.02 m/s), k_s = 6 MN/m.
#include <railstab/setup/prepare_scene.hpp>
#include <railstab/stability/speed_analysis.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <ostream>
#include <regex>
#include <string>
#include <vector>

#include "cli/run_cli.hpp"
#include "support/test_files.hpp"

namespace railstab {
namespace {

namespace fs = std::filesystem;

// Free lists by role (wheelsets, bogie frames, car body), as TOML arrays.
struct FreeSet {
  const char* name;
  const char* wheelsets;
  const char* bogies;
  const char* carbody;
  int internal_only_modes;  // expected eigenvalues at -k_s/c (all held: 4)
};

// GoogleTest names a parameter by its bytes otherwise.
void PrintTo(const FreeSet& set, std::ostream* out) { *out << set.name; }

// coach_tangent with `free` of every body replaced.
fs::path coach_with_free(const fs::path& dir, const FreeSet& set) {
  std::string text = railstab::test::read_text(railstab::test::case_path("coach_tangent"));
  const std::string held = "free = [\"y\", \"z\", \"roll\", \"pitch\", \"yaw\"]";
  text.erase(text.find(held), held.size());  // the car body's; re-added below
  auto add_free = [&](const std::string& body, const std::string& list) {
    const std::string key = "name = \"" + body + "\"\n";
    const size_t at = text.find(key);
    EXPECT_NE(at, std::string::npos) << body;
    text.insert(at + key.size(), "free = " + list + "\n");
  };
  for (const char* w : {"wheelset1", "wheelset2", "wheelset3", "wheelset4"})
    add_free(w, set.wheelsets);
  for (const char* b : {"bogie1", "bogie2"}) add_free(b, set.bogies);
  add_free("carbody", set.carbody);
  const fs::path path = dir / (std::string(set.name) + ".toml");
  std::ofstream(path) << text;
  return path;
}

const FreeSet kSets[] = {
    {"all_held", "[]", "[]", "[]", 4},
    {"car_body_only", "[]", "[]", "[\"y\", \"yaw\"]", 0},
    {"bogie_yaw_only", "[]", "[\"yaw\"]", "[]", 0},
    {"wheelsets_only", "[\"y\", \"z\", \"roll\", \"yaw\"]", "[]", "[]", 4},
    {"wheelsets_and_car_body", "[\"y\", \"z\", \"roll\", \"yaw\"]", "[]", "[\"y\", \"roll\"]", 0},
};

class FreeCoordinateSets : public ::testing::TestWithParam<FreeSet> {};

TEST_P(FreeCoordinateSets, StabilityPointIsFiniteWithEveryState) {
  const FreeSet& set = GetParam();
  const fs::path dir = railstab::test::fresh_dir("free_sets", set.name);
  const PreparedScene s = prepare_scene(coach_with_free(dir, set).string(), {});
  EXPECT_EQ(s.model.n_internal_states, 4);  // four yaw dampers (two mirrored pairs)
  StabilityOptions options;
  options.solver = EigenSolverKind::dense;
  SpeedStability stability(s.model, s.equilibrium.state, s.speed_m_per_s, options);
  const StabilityPoint p = stability.at(s.speed_m_per_s);
  ASSERT_FALSE(p.modes.empty());
  const double relaxation = -6.0e6 / (9000.0 / 0.02);  // -13.33 1/s
  int at_relaxation = 0;
  for (const ModeReport& m : p.modes) {
    EXPECT_TRUE(std::isfinite(m.eigenvalue.real()) && std::isfinite(m.eigenvalue.imag()))
        << set.name;
    EXPECT_TRUE(std::isfinite(m.frequency_hz) && std::isfinite(m.damping_ratio)) << set.name;
    if (std::abs(m.eigenvalue - relaxation) < 1e-8 * std::abs(relaxation)) ++at_relaxation;
  }
  // With the bogie frames and car body held the dampers' ends do not move
  // (wheelset motion does not reach them): each damper relaxes alone.
  if (set.internal_only_modes > 0) {
    EXPECT_EQ(at_relaxation, set.internal_only_modes) << set.name;
  }
  if (std::string(set.name) == "all_held") {
    ASSERT_EQ(p.modes.size(), 4u);  // nothing but the internal states
    // Each named after its damper, not after a body that does not move.
    std::vector<std::string> names;
    for (const ModeReport& m : p.modes) {
      EXPECT_NE(m.name.find("yaw_damper_bogie"), std::string::npos) << m.name;
      EXPECT_NE(m.name.find("damper_elongation_m (internal state, no body motion)"),
                std::string::npos)
          << m.name;
      EXPECT_EQ(m.name.find("wheelset"), std::string::npos) << m.name;
      names.push_back(m.name);
    }
    std::sort(names.begin(), names.end());
    EXPECT_EQ(std::unique(names.begin(), names.end()), names.end());
  }
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Coach, FreeCoordinateSets, ::testing::ValuesIn(kSets),
                         [](const ::testing::TestParamInfo<FreeSet>& info) {
                           return std::string(info.param.name);
                         });

// The commands on the coach with every body held: no signal 11.
TEST(FreeCoordinateSetsCli, EigenAndCriticalSpeedRunWithNoFreeCoordinate) {
  const fs::path dir = railstab::test::fresh_dir("free_sets", "cli");
  const fs::path scene = coach_with_free(dir, kSets[0]);
  const auto eigen = railstab::test::run_railstab({"eigen", scene.string(), "--out", "eigen"}, dir);
  EXPECT_EQ(eigen.exit_code, 0) << eigen.output;
  EXPECT_NE(eigen.output.find("-13.3333"), std::string::npos) << eigen.output;
  const auto critical = railstab::test::run_railstab(
      {"critical-speed", scene.string(), "--from", "10", "--to", "60", "--step", "10", "--no-plots",
       "--out", "critical"},
      dir);
  EXPECT_EQ(critical.exit_code, 0) << critical.output;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace railstab
