#pragma once
// The files of `railstab sensitivity`: d(critical speed)/dp per parameter,
// ranked by elasticity (sensitivity/critical_speed_sensitivity.hpp):
//   <stem>_sensitivity.csv, .json, .md; with plots the tornado plot
//   <stem>_sensitivity_tornado.png/.svg (the elasticities of the `top`
//   largest, as bars left and right of zero) with its data and script.
#include <railstab/io/output_set.hpp>
#include <railstab/sensitivity/critical_speed_sensitivity.hpp>

#include <ostream>
#include <string>
#include <vector>

namespace railstab {

struct SensitivityReportContext {
  std::string scene_name, scene_path, mode;
  double hunting_frequency_hz = 0.0;
  std::size_t top = 20;  // bars in the tornado plot
};

std::vector<std::string> write_sensitivity_results(const CriticalSpeedSensitivities& s,
                                                   const SensitivityReportContext& context,
                                                   OutputSet& outputs, const std::string& stem,
                                                   bool plots);

void print_sensitivity_summary(std::ostream& out, const CriticalSpeedSensitivities& s,
                               const SensitivityReportContext& context, std::size_t rows);

}  // namespace railstab
