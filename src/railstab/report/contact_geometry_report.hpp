#pragma once
// Files of `railstab contact-geometry`: characteristic functions (CSV), the
// equivalent conicity (CSV and JSON) and three plots (gnuplot PNG).
#include <railstab/contact_geometry/contact_geometry_summary.hpp>

#include <string>
#include <vector>

namespace railstab {

class OutputSet;

// Writes, through `outputs` (all or nothing, committed by the caller),
// <stem>_characteristic.csv, <stem>_conicity.csv, <stem>.json and, with
// plots, <stem>_{profiles,delta_r,conicity}.png with their data and script
// (gnuplot without a shell, in the staging folder; every plot checked).
// A non-finite number is an error. `scene_name`, `contact_name` name the
// scene and contact in titles (any text: quoted for gnuplot); the JSON holds
// `scene_file` (the path as given) and `contact` (the contact's name).
// With plots = false gnuplot is not run and an earlier run's plots of the
// same names are removed at commit.
void write_contact_geometry_report(const WheelsetProfilePairs& pairs,
                                   const ContactGeometrySummary& summary,
                                   const std::string& scene_name, const std::string& scene_file,
                                   const std::string& contact_name, OutputSet& outputs,
                                   const std::string& stem, bool plots = true);

// For a contact read from a table file (geometry = "table"; no profiles to
// plot): <stem>_characteristic.csv (the table's rigid contact: y_m,
// delta_r_m, roll_rad, per side contact angle, rolling radius, rail and
// wheel contact positions and slot) and <stem>_conicity.csv, and
// <stem>.json (the table file, e0, r0, the conicity at 3 mm where the rows
// reach, the flange contact shift the file states). No plots.
void write_table_contact_geometry_report(const ProfileContactGeometry& geometry,
                                         const TableContactGeometrySummary& summary,
                                         const std::string& scene_file,
                                         const std::string& contact_name, OutputSet& outputs,
                                         const std::string& stem);

}  // namespace railstab
