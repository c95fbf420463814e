#pragma once
// Everything `railstab contact-geometry` reports for a wheelset's profile
// pairs: the rigid-contact characteristic functions over a grid of lateral
// shifts (default -10..+10 mm in 0.1 mm), the EN 15302 equivalent conicity
// over a grid of amplitudes (default 0.5..10 mm in 0.5 mm) about the
// equilibrium, the flange contact shift. Shifts are EN 15302's lateral
// displacement of the wheelset relative to the track (rigid_contact.hpp).
//
// A shift without a rigid contact, or an amplitude whose conicity cannot be
// computed, is recorded in `not_computed` with its reason; the other points
// are still computed (and written by the report).
#include <railstab/contact_geometry/characteristic_functions.hpp>
#include <railstab/contact_geometry/equivalent_conicity.hpp>
#include <railstab/contact_geometry/table_rigid_contact.hpp>

#include <string>

namespace railstab {

struct ContactGeometrySummaryOptions {
  double lateral_range_m = 0.010;         // characteristic functions: -range..+range
  double lateral_step_m = 1e-4;
  // delta_r for the conicity is sampled at this step over
  // +-(amplitude_max_m + kConicityDeltaRMargin_m) (the motion about an
  // equilibrium off the centre swings beyond the amplitude).
  double conicity_delta_r_step_m = 5e-5;
  double amplitude_min_m = 0.0005, amplitude_max_m = 0.010, amplitude_step_m = 0.0005;
  LateralShiftReference reference = LateralShiftReference::en15302;
};
inline constexpr double kConicityDeltaRMargin_m = 0.004;

// Checks the grid (positive steps, ranges that hold at least one point);
// throws std::invalid_argument naming the option by its contact-geometry
// flag without the dashes ("amplitude-min-m: expected ...") and what was
// expected.
void check_summary_options(const ContactGeometrySummaryOptions& o);

// The amplitude of the single equivalent conicity figure EN 15302 asks for
// (the JSON's reference_amplitude_m).
inline constexpr double kConicityReferenceAmplitude_m = 0.003;

// A point that could not be computed: what ("characteristic functions" or
// "equivalent conicity"), where (the shift or the amplitude), why.
struct NotComputed {
  std::string what;
  double at_m = 0;
  std::string reason;
};

struct ContactGeometrySummary {
  std::vector<CharacteristicRow> rows;   // some may have failed (row.computed())
  std::vector<ConicityPoint> conicity;   // the amplitudes that could be computed
  double equivalent_conicity_at_3mm = 0; // at kConicityReferenceAmplitude_m; NaN if not computed
  FlangeContact flange;
  double half_contact_distance_m = 0;    // e0 of the Klingel formula
  double nominal_rolling_radius_m = 0;   // r0 of the Klingel formula (mean of both wheels)
  // The bottom of the Klingel potential well (equivalent_conicity.hpp);
  // NaN if delta_r has none.
  KlingelEquilibrium equilibrium{std::nan(""), std::nan("")};
  std::vector<NotComputed> not_computed;
};

ContactGeometrySummary summarise_contact_geometry(const WheelsetProfilePairs& pairs,
                                                  const ContactGeometrySummaryOptions& o = {});
inline ContactGeometrySummary summarise_contact_geometry(
    const ProfilePair& pair, const ContactGeometrySummaryOptions& o = {}) {
  return summarise_contact_geometry(WheelsetProfilePairs{pair, pair}, o);
}

// The same from a contact table alone (geometry = "table"; no profiles):
// the rigid contact on the table (table_rigid_contact.hpp) over the lateral
// shifts the table covers (rows stop where a wheel would leave it), the
// conicity at the amplitudes whose motion stays inside them, the flange
// contact shift the table file states.
struct TableContactGeometrySummary {
  std::vector<TableRigidRow> rows;
  std::vector<ConicityPoint> conicity;
  double equivalent_conicity_at_3mm = 0;  // NaN if the motion at 3 mm leaves the rows
  double half_contact_distance_m = 0;
  double lateral_reach_m = 0;  // the rows cover -reach..+reach (at most lateral_range_m)
  KlingelEquilibrium equilibrium{std::nan(""), std::nan("")};
  std::vector<NotComputed> not_computed;
};
TableContactGeometrySummary summarise_table_contact_geometry(
    const ProfileContactGeometry& geometry, const ContactGeometrySummaryOptions& o = {});

}  // namespace railstab
