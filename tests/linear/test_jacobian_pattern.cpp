// The Jacobian's sparsity pattern from the model's structure, its column
// colouring, and the coloured AD Jacobian:
//  - the pattern holds every non-zero of the dense AD Jacobian (one AD
//    direction per column, the reference) on every scene in cases/ and on a
//    test model with every kind of coupling (track ends, internal states,
//    partly frozen bodies, a wheelset, a body the others do not touch);
//  - the coloured Jacobian equals the dense one bit for bit there, whole or
//    for chosen rows and columns (the equilibrium's);
//  - the greedy colouring is valid and optimal on patterns whose chromatic
//    number is known (diagonal, tridiagonal, full, arrow).
#include <railstab/linear/jacobian.hpp>
#include <railstab/linear/jacobian_pattern.hpp>
#include <railstab/equilibrium/equilibrium.hpp>
#include <railstab/linear/linearization.hpp>
#include "model/scene_builders.hpp"
#include <railstab/setup/prepare_scene.hpp>

#include "support/state_index.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace railstab;

namespace {

// Entries of `dense` that are non-zero where the pattern says zero.
std::string nonzeros_outside(const Model& model, const SparsityPattern& p,
                             const Eigen::MatrixXd& dense) {
  std::ostringstream out;
  int count = 0;
  for (int r = 0; r < dense.rows(); ++r)
    for (int c = 0; c < dense.cols(); ++c)
      if (dense(r, c) != 0.0 && !p.contains(r, c) && count++ < 5)
        out << " d(" << model.state_name(r) << ")/d(" << model.state_name(c)
            << ") = " << dense(r, c) << ";";
  return count == 0 ? "" : std::to_string(count) + " entries:" + out.str();
}

// Entries that differ in any bit (== also equates +0 and -0, which the
// colouring may not preserve and nothing downstream can tell apart).
std::string differences(const Model& model, const Eigen::MatrixXd& a, const Eigen::MatrixXd& b,
                        const std::vector<int>& rows, const std::vector<int>& cols) {
  std::ostringstream out;
  int count = 0;
  for (int i = 0; i < a.rows(); ++i)
    for (int j = 0; j < a.cols(); ++j)
      if (!(a(i, j) == b(i, j)) && count++ < 5)
        out << " (" << model.state_name(rows[size_t(i)]) << ", " << model.state_name(cols[size_t(j)])
            << "): " << a(i, j) << " vs " << b(i, j) << ";";
  return count == 0 ? "" : std::to_string(count) + " entries:" + out.str();
}

std::vector<int> iota(int n) {
  std::vector<int> v(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) v[size_t(i)] = i;
  return v;
}

// The checks every model gets at a state x.
void check_model_at(const Model& model, double V, double t, const Eigen::VectorXd& x) {
  const SparsityPattern p = rhs_jacobian_pattern(model);
  const RhsJacobianPlan plan = plan_rhs_jacobian(model);
  ASSERT_TRUE(is_valid_colouring(plan.pattern, plan.colouring));
  EXPECT_GE(plan.colouring.colours, p.max_row_nonzeros());
  for (ForceSelection forces : {ForceSelection::all, ForceSelection::contact_and_inertia}) {
    const Eigen::MatrixXd dense = rhs_jacobian_ad_dense(model, V, t, x, forces);
    EXPECT_EQ(nonzeros_outside(model, p, dense), "") << model.name;
    const Eigen::MatrixXd coloured = rhs_jacobian_ad(model, plan, V, t, x, forces);
    const std::vector<int> all = iota(model.state_size());
    EXPECT_EQ(differences(model, coloured, dense, all, all), "") << model.name;
  }
  // The equilibrium's rows (accelerations, internal rates) and unknowns.
  std::vector<int> rows;
  for (int k = model.n_coordinates; k < model.state_size(); ++k) rows.push_back(k);
  const std::vector<int> cols = equilibrium_unknowns(model);
  const RhsJacobianPlan sub = plan_rhs_jacobian(model, rows, cols);
  ASSERT_TRUE(is_valid_colouring(sub.pattern, sub.colouring));
  const Eigen::MatrixXd dense = rhs_jacobian_ad_dense(model, V, t, x);
  Eigen::MatrixXd block(rows.size(), cols.size());
  for (size_t i = 0; i < rows.size(); ++i)
    for (size_t j = 0; j < cols.size(); ++j) block(Eigen::Index(i), Eigen::Index(j)) = dense(rows[i], cols[j]);
  EXPECT_EQ(differences(model, rhs_jacobian_ad(model, sub, V, t, x), block, rows, cols), "")
      << model.name << " (equilibrium rows and unknowns)";
}

// Off every symmetric point: small random offsets of every coordinate and
// rate (laterally at most 0.5 mm, so every wheel stays in contact).
Eigen::VectorXd perturbed(const Model& model, Eigen::VectorXd x, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int k = 0; k < model.n_coordinates; ++k) {
    const int c = model.coordinate_of_state[size_t(k)].second;
    if (c != int(CoordinateIndex::z)) x(k) += 5e-4 * u(gen);
    x(model.n_coordinates + k) += 1e-2 * u(gen);
  }
  for (int i = model.internal_state_offset(); i < model.state_size(); ++i) x(i) += 1e-4 * u(gen);
  return x;
}

}  // namespace

// --- every scene in cases/ ---------------------------------------------------

// A vehicle scene has bodies (cases/ also holds a profile-contact scene).
bool is_vehicle_scene(const std::filesystem::path& path) {
  std::ifstream in(path);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return text.find("[[bodies]]") != std::string::npos;
}

std::vector<std::string> case_names() {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(RAILSTAB_CASES_DIR))
    if (entry.path().extension() == ".toml" && is_vehicle_scene(entry.path()))
      names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

class JacobianPatternOnCase : public ::testing::TestWithParam<std::string> {};

TEST_P(JacobianPatternOnCase, HoldsEveryNonzeroAndColouredEqualsDenseBitForBit) {
  const PreparedScene scene =
      prepare_scene(std::string(RAILSTAB_CASES_DIR) + "/" + GetParam() + ".toml", {});
  const double V = scene.speed_m_per_s;
  check_model_at(scene.model, V, 0.0, scene.equilibrium.state);
  check_model_at(scene.model, V, 0.3, perturbed(scene.model, perturbed_initial_state(scene), 7));
}

INSTANTIATE_TEST_SUITE_P(Cases, JacobianPatternOnCase, ::testing::ValuesIn(case_names()),
                         [](const auto& info) { return info.param; });

// Guards the list above: the directory holds the scenes this test is for.
TEST(JacobianPatternCases, FindsTheShippedScenes) {
  const std::vector<std::string> names = case_names();
  EXPECT_GE(names.size(), 15u);
  EXPECT_NE(std::find(names.begin(), names.end(), "thesis_vehicle_tangent"), names.end());
  EXPECT_NE(std::find(names.begin(), names.end(), "coach_tangent"), names.end());
}

// The thesis vehicle: 82 states, and 2 coloured passes where dense AD takes
// 4 (the bogie frames' accelerations read 44 columns: their own 12, 11 of
// each wheelset (not the spin angle) and the car body's 10, so at least 44
// colours: 2 passes of kAdChunk = 24 directions, the width chosen for it,
// where 16 took 3). The equilibrium's rows and unknowns need 23 colours: one
// pass.
TEST(JacobianPattern, ThesisVehicleNeedsTwoPasses) {
  const PreparedScene scene =
      prepare_scene(std::string(RAILSTAB_CASES_DIR) + "/thesis_vehicle_tangent.toml", {});
  const RhsJacobianPlan plan = plan_rhs_jacobian(scene.model);
  EXPECT_EQ(scene.model.state_size(), 82);
  EXPECT_EQ(plan.pattern.max_row_nonzeros(), 44);
  EXPECT_EQ(plan.colouring.colours, 44);
  EXPECT_EQ(kAdChunk, 24);
  EXPECT_EQ(plan.passes(), 2);
  const RhsJacobianPlan equilibrium = equilibrium_jacobian_plan(scene.model);
  EXPECT_EQ(equilibrium.colouring.colours, 23);
  EXPECT_EQ(equilibrium.passes(), 1);
}

// --- a test model with every kind of coupling -----------------------------------

namespace {

ElementEnds ends(const std::string& name, const std::string& b1, const std::string& b2,
                 Eigen::Vector3d p1, Eigen::Vector3d p2) {
  ElementEnds e;
  e.name = name;
  e.body1_name = b1;
  e.body2_name = b2;
  e.point1_m = p1;
  e.point2_m = p2;
  return e;
}

SceneSpec coupling_test_scene() {
  using namespace railstab::test;
  SceneSpec s = two_body_oscillator(straight_track(), 20.0);  // a on the track, b on a
  s.name = "coupling_test";
  BodySpec c = rigid_body("c", 2.0, 1.5);
  c.free = {false, true, true, true, false, true};  // x and pitch frozen
  s.bodies.push_back(c);
  s.bodies.push_back(rigid_body("d", 6.0, 1.0));   // hangs from the track only
  SceneSpec w = lone_knife_edge_wheelset(20.0);
  s.contacts = w.contacts;
  w.bodies[0].track_offset_m = -4.0;
  s.bodies.push_back(w.bodies[0]);

  SeriesSpringDamper<double> yaw_damper;  // b - c, one internal state
  yaw_damper.ends = ends("bc_series", "b", "c", {0.5, 1.0, 0.0}, {-1.5, 1.2, 0.1});
  yaw_damper.series_stiffness_N_per_m = 5e6;
  yaw_damper.set_damper(ForceCharacteristic<double>::linear(2e5));
  s.elements.push_back(yaw_damper);
  SeriesSpringDamper<double> to_track;  // track - c, one internal state
  to_track.ends = ends("tc_series", kTrackBodyName, "c", {0.0, 1.0, 1.0}, {0.0, 1.0, -0.2});
  to_track.series_stiffness_N_per_m = 1e6;
  to_track.set_damper(ForceCharacteristic<double>::linear(1e5));
  s.elements.push_back(to_track);
  RotationalSpringDamper<double> bush;
  bush.ends = ends("ab_bush", "a", "b", {0, 0, 0}, {0, 0, 0});
  bush.stiffness_N_m_per_rad = Eigen::Vector3d(1e5, 2e5, 3e5);
  bush.damping_N_m_s_per_rad = Eigen::Vector3d(1e3, 2e3, 3e3);
  s.elements.push_back(bush);
  AntiRollBar<double> bar;
  bar.ends = ends("cb_bar", "c", "b", {0.0, 0.0, 0.2}, {0.0, 0.0, -0.3});
  bar.roll_stiffness_N_m_per_rad = 1e6;
  s.elements.push_back(bar);
  s.elements.push_back(spring("td", kTrackBodyName, "d", {0.3, 0.2, 0.5}, {0.3, 0.2, -0.5},
                              {2e5, 3e5, 5e5}, {1e3, 1e3, 1e3}));
  s.elements.push_back(spring("aw", "a", "wheelset", {-3.0, 0.8, -0.4}, {1.0, 0.8, 0.0},
                              {1e6, 2e6, 3e6}, {1e4, 1e4, 1e4}));
  return s;
}

}  // namespace

TEST(JacobianPattern, CouplingTestModel) {
  const Model model = assemble_model(coupling_test_scene());
  const double V = 20.0;
  const Eigen::VectorXd x = perturbed(model, lowered_nominal_state(model, V), 11);
  ASSERT_EQ(model.n_internal_states, 2);
  check_model_at(model, V, 0.1, x);

  // The structure says what it must: d (on the track only) and a are not
  // coupled; the series elements' states feed their bodies; the wheelset's
  // spin angle feeds nothing, its spin rate does.
  const SparsityPattern p = rhs_jacobian_pattern(model);
  const int n = model.n_coordinates;
  auto state = [&](const std::string& name) { return test::state_index(model, name); };
  EXPECT_FALSE(p.contains(state("d.y_m/s"), state("a.y_m")));
  EXPECT_FALSE(p.contains(state("a.y_m/s"), state("d.y_m")));
  EXPECT_TRUE(p.contains(state("d.y_m/s"), state("d.roll_rad")));
  const int z_bc = state("bc_series.damper_elongation_m");
  const int z_tc = state("tc_series.damper_elongation_m");
  EXPECT_TRUE(p.contains(state("b.yaw_rad/s"), z_bc));
  EXPECT_TRUE(p.contains(z_bc, state("b.yaw_rad")));
  EXPECT_FALSE(p.contains(z_tc, state("b.yaw_rad")));
  EXPECT_FALSE(p.contains(state("a.y_m/s"), z_bc));
  for (int r = 0; r < model.state_size(); ++r)
    EXPECT_FALSE(p.contains(r, state("wheelset.pitch_rad")));
  EXPECT_TRUE(p.contains(state("wheelset.yaw_rad/s"), state("wheelset.pitch_rad/s")));
  EXPECT_EQ(p.columns_of_row[size_t(state("c.y_m"))], std::vector<int>{n + state("c.y_m")});
  // The colouring reaches its lower bound here (a's accelerations read a,
  // b and the wheelset but its spin angle: 12 + 12 + 9 columns), well below
  // the 56 states.
  const RhsJacobianPlan plan = plan_rhs_jacobian(model);
  EXPECT_EQ(p.max_row_nonzeros(), 33);
  EXPECT_EQ(plan.colouring.colours, 33);
}

// --- the colouring on patterns with a known chromatic number -------------------

namespace {
SparsityPattern banded(int n, int half_width) {
  SparsityPattern p;
  p.rows = p.cols = n;
  p.columns_of_row.resize(size_t(n));
  for (int r = 0; r < n; ++r)
    for (int c = std::max(0, r - half_width); c <= std::min(n - 1, r + half_width); ++c)
      p.columns_of_row[size_t(r)].push_back(c);
  return p;
}
}  // namespace

TEST(ColumnColouring, OptimalOnBandedAndFullPatterns) {
  for (int hw : {0, 1, 2, 5}) {
    const SparsityPattern p = banded(30, hw);
    const ColumnColouring c = colour_columns(p);
    EXPECT_TRUE(is_valid_colouring(p, c));
    EXPECT_EQ(c.colours, 2 * hw + 1) << "half width " << hw;  // = max row length
  }
  const SparsityPattern full = banded(10, 10);
  EXPECT_EQ(colour_columns(full).colours, 10);
}

TEST(ColumnColouring, ArrowPatternNeedsAllColours) {
  // Row 0 full, then a diagonal: column j shares row 0 with every other.
  SparsityPattern p = banded(12, 0);
  p.columns_of_row[0] = iota(12);
  const ColumnColouring c = colour_columns(p);
  EXPECT_TRUE(is_valid_colouring(p, c));
  EXPECT_EQ(c.colours, 12);
  // Without row 0 the columns are independent: one colour.
  const SparsityPattern lower = sub_pattern(p, {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11}, iota(12));
  EXPECT_EQ(colour_columns(lower).colours, 1);
}

TEST(ColumnColouring, ValidityCheckRejectsAClash) {
  const SparsityPattern p = banded(5, 1);
  ColumnColouring bad;
  bad.colour_of_column = {0, 1, 0, 1, 1};  // columns 3 and 4 share rows 3 and 4
  bad.colours = 2;
  EXPECT_FALSE(is_valid_colouring(p, bad));
  bad.colour_of_column = {0, 1, 2, 0, 1};
  bad.colours = 3;
  EXPECT_TRUE(is_valid_colouring(p, bad));
}

TEST(JacobianPattern, BadRowsAndColumnsAreRefused) {
  const Model model = assemble_model(coupling_test_scene());
  const int n = model.state_size();
  EXPECT_THROW(plan_rhs_jacobian(model, {0}, {n}), std::invalid_argument);
  EXPECT_THROW(plan_rhs_jacobian(model, {-1}, {0}), std::invalid_argument);
  EXPECT_THROW(plan_rhs_jacobian(model, {0}, {1, 1}), std::invalid_argument);
  EXPECT_THROW(rhs_jacobian_ad(model, 20.0, 0.0, Eigen::VectorXd::Zero(n + 1)),
               std::invalid_argument);
}

// Plans made once and passed in (a speed sweep does) give the same results
// as plans made per call; a plan for something else is refused.
TEST(JacobianPattern, PlansPassedInAreCheckedAndGiveTheSameResults) {
  const PreparedScene scene =
      prepare_scene(std::string(RAILSTAB_CASES_DIR) + "/thesis_bogie_tangent.toml", {});
  const Model& model = scene.model;
  const double V = scene.speed_m_per_s;
  const RhsJacobianPlan whole = plan_rhs_jacobian(model);
  const RhsJacobianPlan eq_plan = equilibrium_jacobian_plan(model);

  EquilibriumOptions eq_opt;
  eq_opt.jacobian_plan = &eq_plan;
  const Eigen::VectorXd guess = lowered_nominal_state(model, V);
  const EquilibriumResult with_plan = solve_equilibrium(model, V, guess, eq_opt);
  const EquilibriumResult without = solve_equilibrium(model, V, guess);
  EXPECT_EQ(with_plan.state, without.state);
  EXPECT_EQ(with_plan.iterations, without.iterations);

  LinearizationOptions lin_opt;
  lin_opt.jacobian_plan = &whole;
  EXPECT_EQ(linearize(model, V, without.state, lin_opt).A, linearize(model, V, without.state).A);

  eq_opt.jacobian_plan = &whole;  // all rows and columns: not the equilibrium's
  EXPECT_THROW(solve_equilibrium(model, V, guess, eq_opt), std::invalid_argument);
  lin_opt.jacobian_plan = &eq_plan;
  EXPECT_THROW(linearize(model, V, without.state, lin_opt), std::invalid_argument);
}
