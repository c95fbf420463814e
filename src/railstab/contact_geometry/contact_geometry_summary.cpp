#include <railstab/contact_geometry/contact_geometry_summary.hpp>

#include <cmath>
#include <stdexcept>

namespace railstab {

ContactGeometrySummary summarise_contact_geometry(const ProfilePair& pair,
                                                  const ContactGeometrySummaryOptions& o) {
  require_contact_at_nominal_position(pair);
  ContactGeometrySummary s;
  s.half_contact_distance_m = pair.wheel_offset_y_m;
  s.rows = characteristic_functions(pair, -o.lateral_range_m, o.lateral_range_m, o.lateral_step_m);
  const std::vector<CharacteristicRow> fine = characteristic_functions(
      pair, -o.conicity_delta_r_range_m, o.conicity_delta_r_range_m, o.conicity_delta_r_step_m);
  DeltaRFunction dr;
  for (const CharacteristicRow& r : fine) {
    dr.y_m.push_back(r.solution.lateral_m);
    dr.delta_r_m.push_back(r.delta_r_m());
  }
  const double r0 = pair.parameters.nominal_rolling_radius_m;
  const int n = int(std::lround((o.amplitude_max_m - o.amplitude_min_m) / o.amplitude_step_m));
  for (int i = 0; i <= n; ++i)
    s.conicity.push_back(equivalent_conicity(dr, o.amplitude_min_m + i * o.amplitude_step_m,
                                             s.half_contact_distance_m, r0));
  s.equivalent_conicity_at_3mm =
      equivalent_conicity(dr, kConicityReferenceAmplitude_m, s.half_contact_distance_m, r0)
          .equivalent_conicity;
  s.flange = find_flange_contact(pair, o.conicity_delta_r_range_m);
  return s;
}

namespace {

// Rows of the table's rigid contact from the centre outwards to `range`
// each way, stopping (symmetrically) where a wheel leaves the table.
std::vector<TableRigidRow> table_rows(const ProfileContactGeometry& g, double range, double step,
                                      double& reach) {
  const int n = int(std::lround(range / step));
  std::vector<TableRigidRow> up, down;
  double roll_up = 0.0, roll_down = 0.0;
  int reached = 0;
  for (int i = 0; i <= n; ++i) {
    try {
      TableRigidRow a = table_rigid_contact(g, i * step, roll_up);
      TableRigidRow b = table_rigid_contact(g, -i * step, roll_down);
      roll_up = a.roll_rad, roll_down = b.roll_rad;
      up.push_back(a), down.push_back(b);
      reached = i;
    } catch (const ContactGeometryError&) {
      break;
    }
  }
  reach = reached * step;
  if (down.empty()) return {};
  std::vector<TableRigidRow> rows(down.rbegin(), down.rend() - 1);  // without the centre twice
  rows.insert(rows.end(), up.begin(), up.end());
  return rows;
}

}  // namespace

TableContactGeometrySummary summarise_table_contact_geometry(const ProfileContactGeometry& g,
                                                             const ContactGeometrySummaryOptions& o) {
  TableContactGeometrySummary s;
  s.half_contact_distance_m = g.pair.wheel_offset_y_m;
  s.rows = table_rows(g, o.lateral_range_m, o.lateral_step_m, s.lateral_reach_m);
  double fine_reach = 0.0;
  const std::vector<TableRigidRow> fine =
      table_rows(g, o.conicity_delta_r_range_m, o.conicity_delta_r_step_m, fine_reach);
  DeltaRFunction dr;
  for (const TableRigidRow& r : fine) {
    dr.y_m.push_back(r.lateral_m);
    dr.delta_r_m.push_back(r.delta_r_m());
  }
  const double r0 = g.pair.parameters.nominal_rolling_radius_m;
  const int n = int(std::lround((o.amplitude_max_m - o.amplitude_min_m) / o.amplitude_step_m));
  s.equivalent_conicity_at_3mm = std::nan("");
  if (dr.y_m.size() < 3) return s;
  for (int i = 0; i <= n; ++i) {
    const double A = o.amplitude_min_m + i * o.amplitude_step_m;
    try {
      s.conicity.push_back(equivalent_conicity(dr, A, s.half_contact_distance_m, r0));
    } catch (const std::invalid_argument&) {
      break;  // the motion leaves the rows: larger amplitudes too
    }
  }
  try {
    s.equivalent_conicity_at_3mm =
        equivalent_conicity(dr, kConicityReferenceAmplitude_m, s.half_contact_distance_m, r0)
            .equivalent_conicity;
  } catch (const std::invalid_argument&) {
  }
  return s;
}

}  // namespace railstab
