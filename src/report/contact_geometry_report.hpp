#pragma once
// Files of `railstab contact-geometry`: characteristic functions (CSV), the
// equivalent conicity (CSV and JSON) and three plots (gnuplot PNG).
#include "contact_geometry/contact_geometry_summary.hpp"

#include <string>
#include <vector>

namespace railstab {

struct ContactGeometryFiles {
  std::string characteristic_csv, conicity_csv, json;
  std::vector<std::string> plots;
};

// Writes <prefix>_characteristic.csv, <prefix>_conicity.csv, <prefix>.json and
// <prefix>_{profiles,delta_r,conicity}.png (each file whole or not at all;
// a non-finite number is an error). `labels` name the scene and contact in
// titles and JSON. With plots = false no plot data, script or PNG is
// written and gnuplot is not run (files.plots stays empty).
ContactGeometryFiles write_contact_geometry_report(const ProfilePair& pair,
                                                   const ContactGeometrySummary& summary,
                                                   const std::string& scene_name,
                                                   const std::string& contact_name,
                                                   const std::string& prefix,
                                                   bool plots = true);

}  // namespace railstab
