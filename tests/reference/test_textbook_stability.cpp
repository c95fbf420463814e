// railstab's linearisation (AD Jacobian of the full nonlinear model) against
// the closed-form textbook models of reference/textbook_models.hpp on the two
// textbook scenes: same eigenvalues at several speeds, same critical speed
// and hunting frequency.
//
// Every check runs at two linearisation points:
//  - ExactEquilibrium: rhs_jacobian_ad(model, V, 0, equilibrium.state), the
//    product path of a stability analysis;
//  - TinyOffset: the equilibrium with every free coordinate moved by ~1e-8
//    (m or rad). All free states are odd under the lateral mirror, so the
//    right-hand side is odd and its Jacobian even: the offset changes the
//    linearisation by O(1e-16) only, but no generalised force is exactly zero
//    in value. (A smaller offset would be lost to rounding against the
//    absolute positions, ~100 m, and the wheel radii.)
//    Eigen's triangular solver (TriangularSolverVector.h) skips
//    `rhs[i] /= diag` when the value of rhs[i] compares equal to zero, and for
//    AutoDiffScalar only the value is compared: so the derivatives of a
//    rotational acceleration whose generalised force vanishes exactly (yaw at
//    the symmetric equilibrium) are not divided by the inertia in
//    body_accelerations' `mass.partialPivLu().solve(gen_force)` (the yaw rows
//    of the AD Jacobian come out Jz times too large). The ExactEquilibrium
//    variants fail on that until the solve is fixed (e.g. an explicit
//    1x1/2x2/3x3 inverse); the TinyOffset variants show that it is the only
//    difference from the closed form.
#include <railstab/setup/prepare_scene.hpp>
#include <railstab/stability/speed_analysis.hpp>
#include <railstab/linear/jacobian.hpp>
#include <railstab/model/equations_of_motion.hpp>
#include "reference/textbook_models.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>

#include <cstdio>
#include <iostream>
#include <numbers>
#include <sstream>
#include <string>
#include <utility>
#include <vector>
#include "support/test_files.hpp"

using namespace railstab;
namespace tb = railstab::textbook;

namespace {

using railstab::test::case_path;

// Coordinates of a closed-form model, in its order: (body name, coordinate).
using Coordinates = std::vector<std::pair<std::string, int>>;
constexpr int kY = int(CoordinateIndex::y), kYaw = int(CoordinateIndex::yaw);

Coordinates wheelset_coordinates(const tb::RestrainedWheelset& p) {
  return {{p.ws.body, kY}, {p.ws.body, kYaw}};
}
Coordinates bogie_coordinates(const tb::Bogie& p) {
  return {{p.ws[0].body, kY}, {p.ws[0].body, kYaw}, {p.ws[1].body, kY},
          {p.ws[1].body, kYaw}, {p.frame_body, kY},  {p.frame_body, kYaw}};
}

// railstab's state matrix at speed V, rows/columns in the closed-form order
// [q; q'] (states that are not in the closed-form model would be dropped:
// none here, every scene body is free in y and yaw only).
struct RailstabLinearisation {
  Eigen::MatrixXd A;
  int dropped_states = 0;
  std::vector<std::string> state_names;  // in the closed-form order
};

enum class Point { exact_equilibrium, tiny_offset };

std::string point_name(const ::testing::TestParamInfo<Point>& info) {
  return info.param == Point::exact_equilibrium ? "ExactEquilibrium" : "TinyOffset";
}

RailstabLinearisation railstab_state_matrix(const std::string& path, double V,
                                            const Coordinates& coords, Point point) {
  SceneOverrides overrides;
  overrides.speed_m_per_s = V;
  const PreparedScene s = prepare_scene(path, overrides);
  const Model& model = s.model;
  const int n = model.n_coordinates;
  Eigen::VectorXd x = s.equilibrium.state;
  if (point == Point::tiny_offset) {
    for (int k = 0; k < n; ++k) x(k) += 1e-8 * (1.0 + 0.37 * k);
    // No acceleration may vanish exactly (that is what the offset is for).
    const Eigen::VectorXd xdot = rhs(model, s.speed_m_per_s, 0.0, x);
    for (int k = 0; k < n; ++k)
      if (xdot(n + k) == 0.0)
        throw std::runtime_error("tiny offset: zero acceleration of " + model.state_name(n + k));
  }
  std::vector<int> q_index;
  for (const auto& [body, c] : coords) {
    int found = -1;
    for (int k = 0; k < n; ++k) {
      const auto [b, ck] = model.coordinate_of_state[k];
      if (model.bodies[b].name == body && ck == c) found = k;
    }
    if (found < 0) throw std::runtime_error("state " + body + " coordinate missing");
    q_index.push_back(found);
  }
  std::vector<int> index = q_index;
  for (int k : q_index) index.push_back(n + k);
  const Eigen::MatrixXd full = rhs_jacobian_ad(model, s.speed_m_per_s, 0.0, x);
  RailstabLinearisation out;
  out.A = full(index, index);
  out.dropped_states = 2 * n - int(index.size());
  for (int i : index) out.state_names.push_back(model.state_name(i));
  return out;
}

// Pairs each closed-form eigenvalue with the nearest unused railstab one and
// returns the largest |difference| / |closed-form eigenvalue|.
double max_relative_eigenvalue_gap(const Eigen::MatrixXd& A_railstab,
                                   const Eigen::MatrixXd& A_closed, std::string* listing) {
  const Eigen::VectorXcd er = Eigen::EigenSolver<Eigen::MatrixXd>(A_railstab, false).eigenvalues();
  const Eigen::VectorXcd ec = Eigen::EigenSolver<Eigen::MatrixXd>(A_closed, false).eigenvalues();
  std::vector<bool> used(er.size(), false);
  double worst = 0.0;
  std::ostringstream out;
  out.precision(15);
  for (Eigen::Index i = 0; i < ec.size(); ++i) {
    Eigen::Index best = -1;
    for (Eigen::Index j = 0; j < er.size(); ++j)
      if (!used[j] && (best < 0 || std::abs(er(j) - ec(i)) < std::abs(er(best) - ec(i))))
        best = j;
    used[best] = true;
    const double gap = std::abs(er(best) - ec(i)) / std::abs(ec(i));
    worst = std::max(worst, gap);
    out << "  closed " << ec(i) << "  railstab " << er(best) << "  rel " << gap << "\n";
  }
  if (listing) *listing = out.str();
  return worst;
}

// Entries of two state matrices agree to `rel` of their row's largest entry.
void expect_same_matrix(const RailstabLinearisation& r, const Eigen::MatrixXd& A_closed,
                        double rel, double V) {
  ASSERT_EQ(r.A.rows(), A_closed.rows());
  for (Eigen::Index i = 0; i < A_closed.rows(); ++i) {
    const double scale = std::max(A_closed.row(i).cwiseAbs().maxCoeff(), 1e-300);
    for (Eigen::Index j = 0; j < A_closed.cols(); ++j)
      EXPECT_LE(std::abs(r.A(i, j) - A_closed(i, j)), rel * scale)
          << "V = " << V << " row " << r.state_names[i] << " column " << r.state_names[j]
          << ": railstab " << r.A(i, j) << ", closed form " << A_closed(i, j);
  }
}

constexpr double kEigenTolerance = 1e-9;    // relative, eigenvalues
constexpr double kSpeedTolerance = 1e-10;   // m/s, bisection
constexpr double kOnsetTolerance = 1e-6;    // relative, V_crit and frequency
constexpr double kSpeedLow = 1.0, kSpeedHigh = 300.0;  // m/s, search range
constexpr int kScanSteps = 299;             // 1 m/s scan before bisection

void print_onset(const std::string& what, double V, double w) {
  std::printf("[textbook] %-44s V_crit = %.10f m/s (%.4f km/h), omega = %.10f rad/s, f = %.8f Hz\n",
              what.c_str(), V, V * 3.6, w, w / (2.0 * std::numbers::pi));
}

const char* point_label(Point p) {
  return p == Point::exact_equilibrium ? "exact equilibrium" : "equilibrium + 1e-8";
}

struct Onset {
  double V, omega;
};

// Critical speed of railstab's linearisation: bisection on the largest real
// part of the AD state matrix's eigenvalues (round-off zeros excluded).
std::optional<Onset> railstab_onset(const std::string& path, const Coordinates& coords,
                                    Point point) {
  auto max_re = [&](double V) {
    return tb::dominant_eigenvalue(railstab_state_matrix(path, V, coords, point).A).real();
  };
  const std::optional<double> V =
      tb::first_unstable_speed(max_re, kSpeedLow, kSpeedHigh, kSpeedTolerance, kScanSteps);
  if (!V) return std::nullopt;
  const double w =
      std::abs(tb::dominant_eigenvalue(railstab_state_matrix(path, *V, coords, point).A).imag());
  return Onset{*V, w};
}

}  // namespace

class TextbookWheelsetOracle : public ::testing::TestWithParam<Point> {};
class TextbookBogieOracle : public ::testing::TestWithParam<Point> {};
INSTANTIATE_TEST_SUITE_P(Textbook, TextbookWheelsetOracle,
                         ::testing::Values(Point::exact_equilibrium, Point::tiny_offset),
                         point_name);
INSTANTIATE_TEST_SUITE_P(Textbook, TextbookBogieOracle,
                         ::testing::Values(Point::exact_equilibrium, Point::tiny_offset),
                         point_name);

// --- Wheelset on springs to the track ---------------------------------------------

TEST(TextbookWheelset, SceneFitsTheTextbookModel) {
  const PreparedScene s = prepare_scene(case_path("textbook_wheelset"), {});
  const tb::RestrainedWheelset p = tb::restrained_wheelset_from_scene(s.spec);
  EXPECT_DOUBLE_EQ(p.to_track.ky_N_per_m, 1.0e6);         // 2 x 0.5e6
  EXPECT_DOUBLE_EQ(p.to_track.kpsi_N_m_per_rad, 2.0e6);   // 2 x 1e6 x 1.0^2
  EXPECT_EQ(s.model.n_coordinates, 2);
  EXPECT_NEAR(s.equilibrium.state.cwiseAbs().maxCoeff(), 0.0, 1e-12);
}

TEST_P(TextbookWheelsetOracle, EigenvaluesEqualClosedFormAtSeveralSpeeds) {
  const std::string path = case_path("textbook_wheelset");
  const tb::RestrainedWheelset p =
      tb::restrained_wheelset_from_scene(prepare_scene(path, {}).spec);
  double worst = 0.0;
  for (double V : {5.0, 20.0, 30.0, 60.0, 73.0, 100.0, 150.0, 250.0}) {
    const RailstabLinearisation r =
        railstab_state_matrix(path, V, wheelset_coordinates(p), GetParam());
    EXPECT_EQ(r.dropped_states, 0);
    const Eigen::MatrixXd A = tb::restrained_wheelset_state_matrix(p, V);
    std::string listing;
    const double gap = max_relative_eigenvalue_gap(r.A, A, &listing);
    worst = std::max(worst, gap);
    EXPECT_LT(gap, kEigenTolerance) << "V = " << V << "\n" << listing;
    expect_same_matrix(r, A, kEigenTolerance, V);
    // The closed-form polynomial has the same roots as the closed-form A.
    const std::array<double, 5> a = tb::restrained_wheelset_characteristic_polynomial(p, V);
    const Eigen::VectorXcd ev = Eigen::EigenSolver<Eigen::MatrixXd>(A, false).eigenvalues();
    for (Eigen::Index i = 0; i < ev.size(); ++i) {
      const std::complex<double> s = ev(i);
      const std::complex<double> P = (((a[0] * s + a[1]) * s + a[2]) * s + a[3]) * s + a[4];
      const double scale = std::abs(a[0] * std::pow(s, 4)) + std::abs(a[1] * std::pow(s, 3)) +
                           std::abs(a[2] * s * s) + std::abs(a[3] * s) + std::abs(a[4]);
      EXPECT_LT(std::abs(P), 1e-10 * scale) << "V = " << V << " root " << s;
    }
  }
  std::printf("[textbook] wheelset, %s: largest relative eigenvalue gap %.3g\n",
              point_label(GetParam()), worst);
}

TEST_P(TextbookWheelsetOracle, CriticalSpeedAndFrequencyEqualClosedForm) {
  const std::string path = case_path("textbook_wheelset");
  const tb::RestrainedWheelset p =
      tb::restrained_wheelset_from_scene(prepare_scene(path, {}).spec);
  const std::optional<tb::HuntingOnset> closed = tb::restrained_wheelset_critical(p);
  ASSERT_TRUE(closed.has_value()) << "closed form: stable at every speed";
  print_onset("wheelset, closed form (Routh-Hurwitz)", closed->speed_m_per_s,
              closed->angular_frequency_rad_per_s);

  // The derivation's own consistency: bisection on the closed-form A(V).
  auto max_re_closed = [&](double V) {
    return tb::dominant_eigenvalue(tb::restrained_wheelset_state_matrix(p, V)).real();
  };
  const std::optional<double> V_matrix =
      tb::first_unstable_speed(max_re_closed, kSpeedLow, kSpeedHigh, kSpeedTolerance, kScanSteps);
  ASSERT_TRUE(V_matrix.has_value());
  const double w_matrix =
      std::abs(tb::dominant_eigenvalue(tb::restrained_wheelset_state_matrix(p, *V_matrix)).imag());
  print_onset("wheelset, closed-form A(V), bisection", *V_matrix, w_matrix);
  EXPECT_NEAR(*V_matrix, closed->speed_m_per_s, kOnsetTolerance * closed->speed_m_per_s);
  EXPECT_NEAR(w_matrix, closed->angular_frequency_rad_per_s,
              kOnsetTolerance * closed->angular_frequency_rad_per_s);

  const std::optional<Onset> rs = railstab_onset(path, wheelset_coordinates(p), GetParam());
  ASSERT_TRUE(rs.has_value()) << "railstab: no crossing below " << kSpeedHigh << " m/s";
  print_onset(std::string("wheelset, railstab AD, ") + point_label(GetParam()), rs->V, rs->omega);
  EXPECT_NEAR(rs->V, closed->speed_m_per_s, kOnsetTolerance * closed->speed_m_per_s);
  EXPECT_NEAR(rs->omega, closed->angular_frequency_rad_per_s,
              kOnsetTolerance * closed->angular_frequency_rad_per_s);
  RecordProperty("V_crit_m_per_s", std::to_string(rs->V));
  RecordProperty("f_crit_Hz", std::to_string(rs->omega / (2.0 * std::numbers::pi)));
}

// --- Bogie: two wheelsets and a frame on primary springs ------------------------

TEST(TextbookBogie, SceneFitsTheTextbookModel) {
  const PreparedScene s = prepare_scene(case_path("textbook_bogie"), {});
  const tb::Bogie p = tb::bogie_from_scene(s.spec);
  EXPECT_DOUBLE_EQ(p.a_m[0], 1.5);
  EXPECT_DOUBLE_EQ(p.a_m[1], -1.5);
  for (int i = 0; i < 2; ++i) {
    EXPECT_DOUBLE_EQ(p.primary[i].ky_N_per_m, 1.0e7);        // 2 x 5e6
    EXPECT_DOUBLE_EQ(p.primary[i].kpsi_N_m_per_rad, 2.0e7);  // 2 x 1e7 x 1.0^2
  }
  EXPECT_EQ(s.model.n_coordinates, 6);
  EXPECT_NEAR(s.equilibrium.state.cwiseAbs().maxCoeff(), 0.0, 1e-12);
}

TEST_P(TextbookBogieOracle, EigenvaluesEqualClosedFormAtSeveralSpeeds) {
  const std::string path = case_path("textbook_bogie");
  const tb::Bogie p = tb::bogie_from_scene(prepare_scene(path, {}).spec);
  double worst = 0.0;
  for (double V : {5.0, 20.0, 30.0, 60.0, 100.0, 150.0, 250.0}) {
    const RailstabLinearisation r =
        railstab_state_matrix(path, V, bogie_coordinates(p), GetParam());
    EXPECT_EQ(r.dropped_states, 0);
    const Eigen::MatrixXd A = tb::bogie_state_matrix(p, V);
    std::string listing;
    const double gap = max_relative_eigenvalue_gap(r.A, A, &listing);
    worst = std::max(worst, gap);
    EXPECT_LT(gap, kEigenTolerance) << "V = " << V << "\n" << listing;
    expect_same_matrix(r, A, kEigenTolerance, V);
  }
  std::printf("[textbook] bogie, %s: largest relative eigenvalue gap %.3g\n",
              point_label(GetParam()), worst);
}

TEST_P(TextbookBogieOracle, CriticalSpeedAndFrequencyEqualClosedForm) {
  const std::string path = case_path("textbook_bogie");
  const tb::Bogie p = tb::bogie_from_scene(prepare_scene(path, {}).spec);

  auto max_re_closed = [&](double V) {
    return tb::dominant_eigenvalue(tb::bogie_state_matrix(p, V)).real();
  };
  const std::optional<double> V_closed =
      tb::first_unstable_speed(max_re_closed, kSpeedLow, kSpeedHigh, kSpeedTolerance, kScanSteps);
  ASSERT_TRUE(V_closed.has_value()) << "closed form: stable up to " << kSpeedHigh << " m/s";
  const double w_closed =
      std::abs(tb::dominant_eigenvalue(tb::bogie_state_matrix(p, *V_closed)).imag());
  print_onset("bogie, closed-form P(s,V) roots, bisection", *V_closed, w_closed);

  // s = i w_crit is a root of the characteristic polynomial det(M s^2 + C s + K)
  // at V_crit: the 6x6 matrix is singular there.
  {
    const tb::SecondOrderModel m = tb::bogie_matrices(p, *V_closed);
    const std::complex<double> s(0.0, w_closed);
    const Eigen::MatrixXcd P = m.M.cast<std::complex<double>>() * (s * s) +
                               m.C.cast<std::complex<double>>() * s +
                               m.K.cast<std::complex<double>>();
    const Eigen::VectorXd sv = Eigen::JacobiSVD<Eigen::MatrixXcd>(P).singularValues();
    EXPECT_LT(sv(sv.size() - 1), 1e-9 * sv(0));
    // ... and not at a nearby frequency.
    const std::complex<double> s2(0.0, 1.01 * w_closed);
    const double rel_det =
        std::abs(tb::bogie_characteristic_value(p, *V_closed, s)) /
        std::abs(tb::bogie_characteristic_value(p, *V_closed, s2));
    EXPECT_LT(rel_det, 1e-8);
  }

  const std::optional<Onset> rs = railstab_onset(path, bogie_coordinates(p), GetParam());
  ASSERT_TRUE(rs.has_value()) << "railstab: no crossing below " << kSpeedHigh << " m/s";
  print_onset(std::string("bogie, railstab AD, ") + point_label(GetParam()), rs->V, rs->omega);
  EXPECT_NEAR(rs->V, *V_closed, kOnsetTolerance * *V_closed);
  EXPECT_NEAR(rs->omega, w_closed, kOnsetTolerance * w_closed);
  RecordProperty("V_crit_m_per_s", std::to_string(rs->V));
  RecordProperty("f_crit_Hz", std::to_string(rs->omega / (2.0 * std::numbers::pi)));
}

// The critical-speed search reports the hunting frequency at the critical
// speed itself (StabilityPoint at_critical, one more evaluation at the
// interpolated zero), not at the stable end of the bracket: the textbook
// wheelset's frequency equals the closed form (Routh-Hurwitz) to 1e-7, where
// the stable end (0.01 m/s below) was 4e-5 off.
TEST(TextbookWheelsetSearch, FrequencyAtTheCriticalSpeedItselfEqualsClosedForm) {
  const PreparedScene s = prepare_scene(case_path("textbook_wheelset"), {});
  const tb::RestrainedWheelset p = tb::restrained_wheelset_from_scene(s.spec);
  const std::optional<tb::HuntingOnset> closed = tb::restrained_wheelset_critical(p);
  ASSERT_TRUE(closed.has_value());
  CriticalSpeedOptions o;
  o.from_m_per_s = 5.0;
  o.to_m_per_s = 150.0;
  o.grid_step_m_per_s = 5.0;
  o.tolerance_m_per_s = 0.01;
  const CriticalSpeedResult r =
      find_critical_speed(s.model, s.equilibrium.state, s.speed_m_per_s, o);
  ASSERT_TRUE(r.critical_speed_found);
  EXPECT_EQ(r.at_critical.speed_m_per_s, r.critical_speed_m_per_s);
  const ModeReport& m = r.at_critical.modes[size_t(r.at_critical.least_stable)];
  // The interpolated zero is within ~1e-6 m/s of the closed form for a
  // 0.01 m/s bracket (real part linear in V to second order).
  EXPECT_NEAR(r.critical_speed_m_per_s, closed->speed_m_per_s, 1e-5 * closed->speed_m_per_s);
  EXPECT_NEAR(2.0 * std::numbers::pi * m.frequency_hz, closed->angular_frequency_rad_per_s,
              1e-7 * closed->angular_frequency_rad_per_s);
  EXPECT_NEAR(m.eigenvalue.real(), 0.0, 1e-6 * closed->angular_frequency_rad_per_s);
}
