#pragma once
// Everything `railstab contact-geometry` reports for a profile pair: the
// rigid-contact characteristic functions over lateral shifts -10..+10 mm,
// the EN 15302 equivalent conicity over amplitudes 0.5..10 mm, the flange
// contact shift, and the contact tables' slot borders.
#include <railstab/contact_geometry/characteristic_functions.hpp>
#include <railstab/contact_geometry/equivalent_conicity.hpp>
#include <railstab/contact_geometry/table_rigid_contact.hpp>

namespace railstab {

struct ContactGeometrySummaryOptions {
  double lateral_range_m = 0.010;         // characteristic functions: -range..+range
  double lateral_step_m = 1e-4;
  // delta_r for the conicity is sampled finer and wider than the CSV (the
  // motion at 10 mm amplitude may swing slightly beyond -10 mm).
  double conicity_delta_r_range_m = 0.014;
  double conicity_delta_r_step_m = 5e-5;
  double amplitude_min_m = 0.0005, amplitude_max_m = 0.010, amplitude_step_m = 0.0005;
};

// The amplitude of the single equivalent conicity figure EN 15302 asks for
// (the JSON's reference_amplitude_m).
inline constexpr double kConicityReferenceAmplitude_m = 0.003;

struct ContactGeometrySummary {
  std::vector<CharacteristicRow> rows;
  std::vector<ConicityPoint> conicity;
  double equivalent_conicity_at_3mm = 0;  // at kConicityReferenceAmplitude_m
  FlangeContact flange;
  double half_contact_distance_m = 0;  // e0 of the Klingel formula
};

ContactGeometrySummary summarise_contact_geometry(const ProfilePair& pair,
                                                  const ContactGeometrySummaryOptions& o = {});

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
};
TableContactGeometrySummary summarise_table_contact_geometry(
    const ProfileContactGeometry& geometry, const ContactGeometrySummaryOptions& o = {});

}  // namespace railstab
