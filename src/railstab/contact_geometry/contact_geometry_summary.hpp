#pragma once
// Everything `railstab contact-geometry` reports for a profile pair: the
// rigid-contact characteristic functions over lateral shifts -10..+10 mm,
// the EN 15302 equivalent conicity over amplitudes 0.5..10 mm, the flange
// contact shift, and the contact tables' slot borders.
#include <railstab/contact_geometry/characteristic_functions.hpp>
#include <railstab/contact_geometry/equivalent_conicity.hpp>

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

}  // namespace railstab
