// Contact tables: reproduction of the direct computation (resolution error,
// stated per region), C1 continuity across cells, and AD derivatives of the
// table evaluation against central differences, across the tread-to-flange
// transition of S1002/UIC60.
#include <railstab/contact_geometry/contact_tables.hpp>
#include <railstab/contact/wheel_rail.hpp>
#include "contact_geometry/synthetic_profiles.hpp"
#include <railstab/core/scalar.hpp>
#include <railstab/profiles/profile_readers.hpp>

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include "support/benchmark_profiles.hpp"

using namespace railstab;
using namespace railstab::testing;

namespace {

const ProfilePair& benchmark_pair() {
  static const ProfilePair pair = railstab::test::benchmark_profile_pair();
  return pair;
}
const ContactTable& benchmark_table() {
  static const ContactTable table = make_contact_table(benchmark_pair());
  return table;
}

// Pose with AD seeds on lateral (direction 0) and roll (direction 1).
WheelPoseOf<AdScalar> ad_pose(double lateral, double vertical, double roll) {
  WheelPoseOf<AdScalar> p;
  p.lateral_m = AdScalar(lateral, AdDerivatives::Unit(0));
  p.vertical_m = AdScalar(vertical, AdDerivatives::Zero());
  p.roll_rad = AdScalar(roll, AdDerivatives::Unit(1));
  return p;
}

}  // namespace

TEST(ContactTables, BenchmarkPairHasTreadAndFlangeSlots) {
  const ContactTable& t = benchmark_table();
  // Borders where the rigid contact jumps along the wheel: the field-side
  // jump (~16 mm), the near-conformal tread jump (~ -3 mm), the flange root
  // (~ -23 mm) and the flange face (~ -36 mm).
  ASSERT_EQ(t.slots(), 5);
  EXPECT_NEAR(t.slot_borders_m().back(), -0.0358, 0.001);
  // Flange slot in contact beyond the flange-contact shift, tread slot before.
  const double n = t.nominal_lateral_m();
  const auto flange = t.evaluate<double>(4, {n + 0.0070, 0.0, 0.0});
  EXPECT_GT(flange.contact_angle_rad, 1.0);
  EXPECT_LT(flange.on_border, 0.5);
}

// Table resolution, measured at the cell centres (farthest from the nodes)
// against the direct profile computation, for contacts within 1 mm of the
// lowest gap: on smooth branches and in cells where the lowest point of a slot
// jumps (folds: the data are only C0 there). Default grid 0.1 mm x 5 mrad.
// Measured (S1002/UIC60, this grid): gap error 4.5 um on smooth branches and
// 3.4 um across jumps; contact angle 0.024 / 0.003 rad; rolling radius
// 0.26 / 0.035 mm (the worst cells lie next to folds, where a slot's lowest
// point leaves a vanishing local minimum).
TEST(ContactTables, ResolutionErrorOfTheBenchmarkTable) {
  const TableResolution r = measure_table_resolution(benchmark_pair(), benchmark_table());
  ASSERT_GT(r.smooth_cells, 500);
  const int gap = int(TableQuantity::gap0_m), angle = int(TableQuantity::contact_angle_rad),
            radius = int(TableQuantity::rolling_radius_m);
  RecordProperty("smooth_gap_error_m", std::to_string(r.smooth[size_t(gap)]));
  std::printf("table resolution (smooth / across jumps): gap %.3g / %.3g m, contact angle %.3g / %.3g "
              "rad, rolling radius %.3g / %.3g m, cells %d / %d\n",
              r.smooth[size_t(gap)], r.across_jump[size_t(gap)], r.smooth[size_t(angle)],
              r.across_jump[size_t(angle)], r.smooth[size_t(radius)], r.across_jump[size_t(radius)],
              r.smooth_cells, r.jump_cells);
  EXPECT_LT(r.smooth[size_t(gap)], 5e-6);
  EXPECT_LT(r.across_jump[size_t(gap)], 5e-6);
  EXPECT_LT(r.smooth[size_t(radius)], 3e-4);
  EXPECT_LT(r.smooth[size_t(angle)], 0.03);
}

// A cone on a circular rail has one smooth branch: the table reproduces the
// direct computation to ~1e-9 m and gives delta_r = 2 tan(gamma) y at zero roll.
TEST(ContactTables, ConeTableReproducesTwiceTanGammaY) {
  const double t = 0.05, R = 0.3;
  ProfilePairParameters p;
  p.gauge_measuring_height_m = 0.002;
  const double y_g = -std::sqrt(R * R - (R - 0.002) * (R - 0.002));
  p.track_gauge_m = 2.0 * (0.5 * p.flange_back_distance_m + p.tape_circle_from_flange_back_m + y_g);
  const ProfilePair pair = make_profile_pair(cone_wheel(t), circular_rail(R, 0.040), p);
  ContactTableOptions o;
  o.lateral_half_range_m = 0.010;
  const ContactTable table = make_contact_table(pair, o);
  ASSERT_EQ(table.slots(), 1);
  for (double y : {-0.0087, -0.0031, 0.0012, 0.0049, 0.0093}) {
    const auto L = table.evaluate<double>(0, wheel_pose_in_rail_frame<double>(pair, +1, y, 0.0, 0.0));
    const auto Rt = table.evaluate<double>(0, wheel_pose_in_rail_frame<double>(pair, -1, y, 0.0, 0.0));
    EXPECT_NEAR(L.rolling_radius_m - Rt.rolling_radius_m, 2 * t * y, 1e-8) << "y = " << y;
  }
  const TableResolution r = measure_table_resolution(pair, table);
  EXPECT_EQ(r.jump_cells, 0);
  EXPECT_LT(r.smooth[size_t(int(TableQuantity::gap0_m))], 1e-9);
}

// C1: value and both first derivatives continuous across a cell boundary.
TEST(ContactTables, InterpolantIsC1AcrossCellBoundaries) {
  const ContactTable& t = benchmark_table();
  const double n = t.nominal_lateral_m();
  for (int slot = 0; slot < t.slots(); ++slot)
    for (int i : {20, 80, 121, 150, 183, 200}) {
      const double q = t.lateral_at(i), th = t.roll_at(5);
      const auto below = t.evaluate<AdScalar>(slot, ad_pose(n + q - 1e-10, 0.0, th + 1e-4));
      const auto above = t.evaluate<AdScalar>(slot, ad_pose(n + q + 1e-10, 0.0, th + 1e-4));
      const double scale = 1.0 + std::abs(below.vertical_gap_m.derivatives()(0));
      EXPECT_NEAR(below.vertical_gap_m.derivatives()(0), above.vertical_gap_m.derivatives()(0),
                  1e-6 * scale) << "slot " << slot << " node " << i;
      EXPECT_NEAR(below.contact_angle_rad.derivatives()(1), above.contact_angle_rad.derivatives()(1),
                  1e-5 * (1.0 + std::abs(below.contact_angle_rad.derivatives()(1))));
    }
}

// AD through the table evaluation against central differences (step
// cbrt(eps) scaled to the cell), at poses through the tread-to-flange
// transition (q = 6.0 .. 6.6 mm, flange slot 4 and tread slots) and elsewhere.
TEST(ContactTables, AdDerivativesMatchCentralDifferences) {
  const ContactTable& t = benchmark_table();
  const double n = t.nominal_lateral_m();
  const double hq = 1e-9, ht = 1e-8;
    // (off the nodes: the interpolant is C1, so a central difference straddling a
  // node sees the jump of the second derivative)
  for (double q : {-0.00713, 0.00013, 0.00234, 0.00483, 0.00603, 0.00618, 0.00626, 0.00641, 0.00657})
    for (double th : {-0.0113, 0.0004, 0.0087})
      for (int slot = 0; slot < t.slots(); ++slot) {
        const auto ad = t.evaluate<AdScalar>(slot, ad_pose(n + q, 1e-4, th));
        auto value = [&](double dq, double dt) {
          const auto c = t.evaluate<double>(slot, {n + q + dq, 1e-4, th + dt});
          return std::array<double, 4>{c.vertical_gap_m, c.normal_gap_m, c.contact_angle_rad,
                                       c.rolling_radius_m};
        };
        const auto qp = value(hq, 0), qm = value(-hq, 0), tp = value(0, ht), tm = value(0, -ht);
        const AdScalar* quantities[4] = {&ad.vertical_gap_m, &ad.normal_gap_m,
                                         &ad.contact_angle_rad, &ad.rolling_radius_m};
        for (int k = 0; k < 4; ++k) {
          const double dq_fd = (qp[size_t(k)] - qm[size_t(k)]) / (2 * hq);
          const double dt_fd = (tp[size_t(k)] - tm[size_t(k)]) / (2 * ht);
          const double dq_ad = quantities[k]->derivatives()(0), dt_ad = quantities[k]->derivatives()(1);
          EXPECT_NEAR(dq_ad, dq_fd, 1e-5 * (1 + std::abs(dq_fd)))
              << "slot " << slot << " q " << q << " theta " << th << " quantity " << k;
          EXPECT_NEAR(dt_ad, dt_fd, 1e-4 * (1 + std::abs(dt_fd)))
              << "slot " << slot << " q " << q << " theta " << th << " quantity " << k;
        }
      }
}

TEST(ContactTables, OutsideTheTableIsAnError) {
  const ContactTable& t = benchmark_table();
  EXPECT_THROW(t.evaluate<double>(0, {t.nominal_lateral_m() + 0.013, 0.0, 0.0}), std::domain_error);
  EXPECT_THROW(t.evaluate<double>(0, {t.nominal_lateral_m(), 0.0, 0.03}), std::domain_error);
}

// Issue 9: building the tables of a profile pair takes under 1 s (CPU time,
// here with the Release build; analysis/bench_contact_tables prints the median).
TEST(ContactTables, BuildTakesUnderOneSecond) {
  const std::clock_t start = std::clock();
  const ContactTable table = make_contact_table(benchmark_pair());
  const double cpu_s = double(std::clock() - start) / CLOCKS_PER_SEC;
  EXPECT_GT(table.slots(), 1);
  EXPECT_LT(cpu_s, 1.0);
}

// A wheel held at a fixed height (60 um overlap when centred) and moved
// laterally across the two tread slots of S1002/UIC60 (|q| <= 1.2 mm): the
// Hertz force law with one stiffness, F ~ sum_k w_k delta_k^1.5, delta_k the
// slot's penetration after the shared overlap (wheel_rail.hpp). Where two
// slots overlap as one connected region, their common depth is counted once,
// so F follows the geometry: a single contact's logarithmic slope is at
// most 1.5 tan(gamma) / delta ~ 1.5 x 0.09 / 60 um = 2.25 per mm on the
// tread, and the split of the common depth between the lobes may add as
// much again: below 4.5 per mm (measured 3.4). Counting the common depth in
// both slots (before the rule) doubled F within one 0.1 mm cell where the
// second slot appeared: 14.7 per mm.
TEST(ContactTables, SharedOverlapKeepsTheNormalForceContinuous) {
  const ContactTable& t = benchmark_table();
  const double n = t.nominal_lateral_m();
  double lowest = 1.0;
  for (int k = 0; k < t.slots(); ++k) lowest = std::min(lowest, t.vertical_gap<double>(k, {n, 0.0, 0.0}));
  const double vertical = -lowest - 60e-6;
  const auto force = [&](double q, bool share) {
    const WheelPoseOf<double> pose{n + q, vertical, 0.0};
    double f = 0.0;
    for (int k = 0; k < t.slots(); ++k) {
      const TableContact<double> c = t.evaluate<double>(k, pose);
      if (c.vertical_gap_m >= 0.0) continue;
      const double shared =
          share ? wheel_rail_detail::shared_overlap_m<double>(t, pose, k, c.vertical_gap_m) : 0.0;
      const double d = -(c.vertical_gap_m + shared) * std::cos(c.contact_angle_rad);
      if (d > 0.0) f += c.interior_weight * std::pow(d, 1.5);
    }
    return f;
  };
  const double dq = 1e-6;
  double slope = 0.0, slope_counted_twice = 0.0;
  for (double q = -1.2e-3; q < 1.2e-3; q += dq) {
    slope = std::max(slope, std::abs(std::log(force(q + dq, true) / force(q, true))) / dq);
    slope_counted_twice = std::max(
        slope_counted_twice, std::abs(std::log(force(q + dq, false) / force(q, false))) / dq);
  }
  std::printf("largest d ln F / dq: %.3g per mm (common depth counted twice: %.3g per mm)\n",
              slope * 1e-3, slope_counted_twice * 1e-3);
  EXPECT_LT(slope, 4.5e3);
  // The test sees the fault it guards against.
  EXPECT_GT(slope_counted_twice, 10e3);
}
