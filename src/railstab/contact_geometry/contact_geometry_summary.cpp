#include <railstab/contact_geometry/contact_geometry_summary.hpp>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace railstab {

void check_summary_options(const ContactGeometrySummaryOptions& o) {
  auto fail = [](const char* option, const std::string& expected, double got) {
    std::ostringstream msg;
    msg << option << ": expected " << expected << ", got " << got;
    throw std::invalid_argument(msg.str());
  };
  if (!(o.lateral_step_m >= 1e-6 && o.lateral_step_m <= 1e-3))
    fail("delta-r-step-m", "a lateral step in [1e-6, 1e-3] m", o.lateral_step_m);
  if (!(o.lateral_range_m >= o.lateral_step_m && o.lateral_range_m <= 0.03))
    fail("delta-r-half-range-m", "a half range of at least one step and at most 0.03 m",
         o.lateral_range_m);
  if (!(o.amplitude_step_m >= 1e-5 && o.amplitude_step_m <= 0.02))
    fail("amplitude-step-m", "a step in [1e-5, 0.02] m", o.amplitude_step_m);
  if (!(o.amplitude_min_m > 0.0 && o.amplitude_min_m <= o.amplitude_max_m))
    fail("amplitude-min-m", "a positive amplitude not above the largest", o.amplitude_min_m);
  if (!(o.amplitude_max_m <= 0.02))
    fail("amplitude-max-m", "at most 0.02 m", o.amplitude_max_m);
  if (!(o.conicity_delta_r_step_m >= 1e-6 && o.conicity_delta_r_step_m <= 1e-3))
    fail("conicity-delta-r-step-m", "a step in [1e-6, 1e-3] m", o.conicity_delta_r_step_m);
}

namespace {

// Amplitudes min, min + step, ..., max.
std::vector<double> amplitudes(const ContactGeometrySummaryOptions& o) {
  std::vector<double> a;
  const int n = int(std::floor((o.amplitude_max_m - o.amplitude_min_m) / o.amplitude_step_m + 1e-9));
  for (int i = 0; i <= n; ++i) a.push_back(o.amplitude_min_m + i * o.amplitude_step_m);
  return a;
}

// The conicity at every amplitude, and at the reference amplitude; a failure
// is recorded with its reason (and `limit`: why the delta_r function ends
// where it ends, if it ends early).
template <class Summary>
void conicity_points(Summary& s, const DeltaRFunction& dr, const ContactGeometrySummaryOptions& o,
                     double r0, const std::string& limit) {
  s.equivalent_conicity_at_3mm = std::nan("");
  try {
    s.equilibrium = klingel_equilibrium(dr);
  } catch (const std::invalid_argument& e) {
    s.not_computed.push_back({"equilibrium", 0.0, e.what() + limit});
    return;
  }
  for (double A : amplitudes(o)) {
    try {
      s.conicity.push_back(equivalent_conicity(dr, A, s.half_contact_distance_m, r0));
    } catch (const std::invalid_argument& e) {
      s.not_computed.push_back({"equivalent conicity", A, e.what() + limit});
    }
  }
  try {
    s.equivalent_conicity_at_3mm =
        equivalent_conicity(dr, kConicityReferenceAmplitude_m, s.half_contact_distance_m, r0)
            .equivalent_conicity;
  } catch (const std::invalid_argument& e) {
    bool listed = false;
    for (const NotComputed& n : s.not_computed)
      listed |= n.what == "equivalent conicity" &&
                std::abs(n.at_m - kConicityReferenceAmplitude_m) < 1e-12;
    if (!listed)
      s.not_computed.push_back(
          {"equivalent conicity", kConicityReferenceAmplitude_m, e.what() + limit});
  }
}

}  // namespace

ContactGeometrySummary summarise_contact_geometry(const WheelsetProfilePairs& pairs,
                                                  const ContactGeometrySummaryOptions& o) {
  check_summary_options(o);
  require_contact_at_nominal_position(pairs);
  ContactGeometrySummary s;
  s.half_contact_distance_m = pairs.left.wheel_offset_y_m;
  s.nominal_rolling_radius_m = pairs.mean_nominal_rolling_radius_m();
  s.rows = characteristic_functions(pairs, -o.lateral_range_m, o.lateral_range_m,
                                    o.lateral_step_m, o.reference);
  for (const CharacteristicRow& r : s.rows)
    if (!r.computed())
      s.not_computed.push_back({"characteristic functions", r.solution.lateral_m, r.failure});
  // delta_r for the conicity: the rows solved without a gap around y = 0.
  const double range = o.amplitude_max_m + kConicityDeltaRMargin_m;
  const std::vector<CharacteristicRow> fine =
      characteristic_functions(pairs, -range, range, o.conicity_delta_r_step_m, o.reference);
  const size_t centre = fine.size() / 2;
  size_t lo = centre, hi = centre;
  while (lo > 0 && fine[lo - 1].computed()) --lo;
  while (hi + 1 < fine.size() && fine[hi + 1].computed()) ++hi;
  std::string limit;
  for (size_t k : {lo > 0 ? lo - 1 : fine.size(), hi + 1})
    if (k < fine.size() && !fine[k].computed()) {
      std::ostringstream m;
      m << "; the delta_r function ends at " << fine[k].solution.lateral_m * 1e3
        << " mm: " << fine[k].failure;
      limit += m.str();
    }
  DeltaRFunction dr;
  if (fine[centre].computed())
    for (size_t k = lo; k <= hi; ++k) {
      dr.y_m.push_back(fine[k].solution.lateral_m);
      dr.delta_r_m.push_back(fine[k].delta_r_m());
    }
  if (dr.y_m.size() < 3) {
    s.equivalent_conicity_at_3mm = std::nan("");
    s.not_computed.push_back({"equivalent conicity", 0.0,
                              "no delta_r function about y = 0" + limit});
  } else {
    conicity_points(s, dr, o, s.nominal_rolling_radius_m, limit);
  }
  try {
    s.flange = find_flange_contact(pairs, o.reference, range);
  } catch (const ContactGeometryError& e) {
    s.not_computed.push_back({"flange contact", 0.0, e.what()});
  }
  return s;
}

namespace {

// Rows of the table's rigid contact from the centre outwards to `range`
// each way, stopping (symmetrically) where a wheel leaves the table.
std::vector<TableRigidRow> table_rows(const ProfileContactGeometry& g, double range, double step,
                                      LateralShiftReference reference, double& reach) {
  const int n = int(std::lround(range / step));
  std::vector<TableRigidRow> up, down;
  double roll_up = 0.0, roll_down = 0.0;
  int reached = 0;
  for (int i = 0; i <= n; ++i) {
    try {
      TableRigidRow a = table_rigid_contact(g, i * step, roll_up, reference);
      TableRigidRow b = table_rigid_contact(g, -i * step, roll_down, reference);
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
  check_summary_options(o);
  TableContactGeometrySummary s;
  s.half_contact_distance_m = g.pair.wheel_offset_y_m;
  s.rows = table_rows(g, o.lateral_range_m, o.lateral_step_m, o.reference, s.lateral_reach_m);
  double fine_reach = 0.0;
  const std::vector<TableRigidRow> fine = table_rows(
      g, o.amplitude_max_m + kConicityDeltaRMargin_m, o.conicity_delta_r_step_m, o.reference,
      fine_reach);
  DeltaRFunction dr;
  for (const TableRigidRow& r : fine) {
    dr.y_m.push_back(r.lateral_m);
    dr.delta_r_m.push_back(r.delta_r_m());
  }
  std::ostringstream limit;
  limit << "; the table's rigid contact reaches +-" << fine_reach * 1e3 << " mm";
  s.equivalent_conicity_at_3mm = std::nan("");
  if (dr.y_m.size() < 3) {
    s.not_computed.push_back({"equivalent conicity", 0.0, "no delta_r function" + limit.str()});
    return s;
  }
  conicity_points(s, dr, o, g.pairs().mean_nominal_rolling_radius_m(), limit.str());
  return s;
}

}  // namespace railstab
