#include <railstab/contact_geometry/characteristic_functions.hpp>

#include <algorithm>
#include <cmath>
#include <functional>

namespace railstab {

std::vector<CharacteristicRow> characteristic_functions(const ProfilePair& pair, double y_min_m,
                                                        double y_max_m, double step_m) {
  const int n = int(std::lround((y_max_m - y_min_m) / step_m));
  // Start at the centre and continue outwards both ways: the roll guess of
  // each row is its neighbour's solution.
  std::vector<CharacteristicRow> result(size_t(n + 1));
  const int centre = int(std::lround(-y_min_m / step_m));
  const int first = std::clamp(centre, 0, n);
  double roll = 0.0;
  for (int i = first; i <= n; ++i) {
    result[size_t(i)].solution = solve_rigid_contact(pair, y_min_m + i * step_m, roll);
    roll = result[size_t(i)].solution.roll_rad;
  }
  roll = first <= n ? result[size_t(first)].solution.roll_rad : 0.0;
  for (int i = first - 1; i >= 0; --i) {
    result[size_t(i)].solution = solve_rigid_contact(pair, y_min_m + i * step_m, roll);
    roll = result[size_t(i)].solution.roll_rad;
  }
  return result;
}

std::vector<CharacteristicRow> characteristic_functions(const WheelsetProfilePairs& pairs,
                                                        double y_min_m, double y_max_m,
                                                        double step_m,
                                                        LateralShiftReference reference) {
  const int n = int(std::lround((y_max_m - y_min_m) / step_m));
  std::vector<CharacteristicRow> result(size_t(n + 1));
  const int first = std::clamp(int(std::lround(-y_min_m / step_m)), 0, n);
  auto solve = [&](int i, double& roll) {
    const double y = y_min_m + i * step_m;
    CharacteristicRow& row = result[size_t(i)];
    try {
      row.solution = solve_rigid_contact(pairs, y, roll, reference);
      roll = row.solution.roll_rad;
    } catch (const ContactGeometryError& e) {
      row.solution = RigidContactSolution{};
      row.solution.lateral_m = y;
      row.failure = e.what();
    }
  };
  double roll = 0.0;
  for (int i = first; i <= n; ++i) solve(i, roll);
  roll = result[size_t(first)].computed() ? result[size_t(first)].solution.roll_rad : 0.0;
  for (int i = first - 1; i >= 0; --i) solve(i, roll);
  return result;
}

FlangeContact find_flange_contact(const ProfilePair& pair, double y_max_m, double step_m,
                                  double tolerance_m, double flange_contact_angle_rad) {
  return find_flange_contact(WheelsetProfilePairs{pair, pair},
                             LateralShiftReference::wheelset_centre, y_max_m, step_m, tolerance_m,
                             flange_contact_angle_rad);
}

FlangeContact find_flange_contact(const WheelsetProfilePairs& pairs,
                                  LateralShiftReference reference, double y_max_m, double step_m,
                                  double tolerance_m, double flange_contact_angle_rad) {
  FlangeContact fc;
  auto on_flange = [&](const RigidContactSolution& s) {
    return s.left.front().contact_angle_rad > flange_contact_angle_rad;
  };
  auto solve = [&](double y, double roll) {
    return solve_rigid_contact(pairs, y, roll, reference);
  };
  RigidContactSolution prev = solve(0.0, 0.0);
  if (on_flange(prev)) return fc;  // flange contact already when centred: not a flange pair
  for (double y = step_m; y <= y_max_m + 1e-12; y += step_m) {
    RigidContactSolution cur = solve(y, prev.roll_rad);
    if (on_flange(cur)) {
      double lo = prev.lateral_m, hi = cur.lateral_m;
      RigidContactSolution at_lo = prev, at_hi = cur;
      while (hi - lo > tolerance_m) {
        const double mid = 0.5 * (lo + hi);
        RigidContactSolution s = solve(mid, at_lo.roll_rad);
        if (on_flange(s)) hi = mid, at_hi = std::move(s);
        else lo = mid, at_lo = std::move(s);
      }
      fc.found = true;
      fc.lateral_shift_m = 0.5 * (lo + hi);
      fc.tread_wheel_u_m = at_lo.left.front().wheel_u_m;
      fc.flange_wheel_u_m = at_hi.left.front().wheel_u_m;
      fc.tread_contact_angle_rad = at_lo.left.front().contact_angle_rad;
      fc.flange_contact_angle_rad = at_hi.left.front().contact_angle_rad;
      return fc;
    }
    prev = std::move(cur);
  }
  return fc;
}

std::vector<double> contact_jump_borders(const ProfilePair& pair, double half_range_m,
                                         double step_m, double jump_m) {
  // Shifts without a rigid contact (a wheel whose contact runs off its
  // profile before half_range_m) are skipped: the borders come from the
  // shifts that have one.
  const std::vector<CharacteristicRow> rows =
      characteristic_functions(WheelsetProfilePairs{pair, pair}, -half_range_m, half_range_m,
                               step_m, LateralShiftReference::wheelset_centre);
  std::vector<double> borders;
  for (size_t i = 1; i < rows.size(); ++i) {
    if (!rows[i - 1].computed() || !rows[i].computed()) continue;
    const double u0 = rows[i - 1].solution.left.front().wheel_u_m;
    const double u1 = rows[i].solution.left.front().wheel_u_m;
    if (std::abs(u1 - u0) > jump_m) borders.push_back(0.5 * (u0 + u1));
  }
  std::sort(borders.begin(), borders.end(), std::greater<double>());
  return borders;
}

}  // namespace railstab
