// A start on a mode (stability/mode_start.hpp): the steady state plus the
// eigenvector scaled so the leading wheelset's lateral shift is M; every
// other entry in the ratio the eigenvector gives.
#include <railstab/model/leading_wheelset.hpp>
#include <railstab/setup/prepare_scene.hpp>
#include <railstab/stability/mode_start.hpp>
#include <railstab/stability/speed_analysis.hpp>

#include "support/test_files.hpp"

#include <gtest/gtest.h>

using namespace railstab;
using railstab::test::case_path;

TEST(ModeStart, TheInitialStateIsTheModeShapeScaledToTheLeadingWheelset) {
  SceneOverrides o;
  o.speed_m_per_s = 36.0;
  const PreparedScene s = prepare_scene(case_path("thesis_bogie_tangent"), o);
  const double M = 1e-3;
  const ModeStart start = mode_start_state(s.model, 36.0, s.equilibrium.state, "hunting", M);
  EXPECT_EQ(start.leading_wheelset, "wheelset1");

  // The eigenvector computed independently, as critical-speed does.
  SpeedStability stability(s.model, s.equilibrium.state, 36.0);
  const StabilityPoint p = stability.at(36.0);
  const ModeReport& mode = p.modes[size_t(least_stable_lateral_mode(p.modes, 20.0))];
  EXPECT_EQ(start.mode_name, mode.name);
  auto entry = [&](int state) {
    for (size_t i = 0; i < p.linear.kept_states.size(); ++i)
      if (p.linear.kept_states[i] == state) return mode.vector(Eigen::Index(i));
    ADD_FAILURE() << "state " << state << " not kept";
    return std::complex<double>(0.0);
  };
  const int y1 = leading_wheelset_lateral_state(s.model);
  const int y2 = s.model.bodies[1].state_index[int(CoordinateIndex::y)];
  const int yaw1 = s.model.bodies[0].state_index[int(CoordinateIndex::yaw)];
  const int frame_y = s.model.bodies[2].state_index[int(CoordinateIndex::y)];
  const Eigen::VectorXd dx = start.state - p.equilibrium.state;
  // The leading wheelset starts at M (round-off of one complex product).
  EXPECT_NEAR(dx(y1), M, 1e-15);
  // Every other entry: Re(v_k conj(v_L)) / |v_L|^2 times M (1e-9 relative:
  // the eigenvector's round-off).
  const std::complex<double> vL = entry(y1);
  for (int k : {y2, yaw1, frame_y, y1 + s.model.n_coordinates}) {
    const double expected = (entry(k) * std::conj(vL)).real() / std::norm(vL) * M;
    EXPECT_NEAR(dx(k), expected, 1e-9 * std::abs(expected) + 1e-18) << s.model.state_name(k);
  }
  // Hunting of a bogie: the trailing wheelset moves too.
  EXPECT_GT(std::abs(dx(y2)), 0.1 * M);

  // By name: the same start.
  const ModeStart by_name = mode_start_state(s.model, 36.0, s.equilibrium.state, mode.name, M);
  EXPECT_EQ((by_name.state - start.state).cwiseAbs().maxCoeff(), 0.0);
}

TEST(ModeStart, AnUnknownModeNameListsTheModes) {
  const PreparedScene s = prepare_scene(case_path("thesis_bogie_tangent"), SceneOverrides{});
  const std::string hunting =
      mode_start_state(s.model, s.speed_m_per_s, s.equilibrium.state, "hunting", 1e-3).mode_name;
  try {
    mode_start_state(s.model, s.speed_m_per_s, s.equilibrium.state, "wobble", 1e-3);
    FAIL() << "an unknown mode was accepted";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("--mode 'wobble': no mode of that name at 20 m/s; expected 'hunting' or one of:"),
              std::string::npos)
        << what;
    EXPECT_NE(what.find("'" + hunting + "'"), std::string::npos) << what;
  }
}
