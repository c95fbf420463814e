#include <railstab/contact_geometry/contact_geometry_summary.hpp>

#include <cmath>

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

}  // namespace railstab
