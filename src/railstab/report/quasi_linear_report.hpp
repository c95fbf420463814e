#pragma once
// The quasi-linear critical speed by amplitude as files
// (stability/quasi_linear_critical_speed.hpp): the curve V_c(A) as CSV and
// JSON and, with plots, the diagram with speed on the x axis and the
// amplitude on the y axis (as a bifurcation diagram draws its branch), PNG
// and SVG; and the quasi-linear section of a single-amplitude run's JSON and
// Markdown (write_quasi_linear_json_fields, quasi_linear_markdown).
#include <railstab/io/json_writer.hpp>
#include <railstab/io/output_set.hpp>
#include <railstab/model/model.hpp>
#include <railstab/stability/quasi_linear_critical_speed.hpp>

#include <string>
#include <vector>

namespace railstab {

// Adds <stem>_quasi_linear_curve.csv, .json and, with `plots`, the gnuplot
// data, script, .png and .svg (gnuplot run and checked); returns the names.
// `plain`: the plain critical speed (0: none found), drawn as a line.
std::vector<std::string> write_quasi_linear_curve(const Model& model, const QuasiLinearCurve& curve,
                                                  double plain_critical_speed_m_per_s,
                                                  double from_m_per_s, double to_m_per_s,
                                                  OutputSet& outputs, const std::string& stem,
                                                  bool plots);
std::vector<std::string> quasi_linear_curve_file_names(const std::string& stem);

// The object of a single-amplitude run, under the key "quasi_linear".
void write_quasi_linear_json(JsonWriter& json, const QuasiLinearCriticalSpeed& q);
// Its Markdown section.
std::string quasi_linear_markdown(const QuasiLinearCriticalSpeed& q);

}  // namespace railstab
