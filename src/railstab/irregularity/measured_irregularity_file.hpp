#pragma once
// Reading a measured track-geometry record (docs/irregular_track.md,
// "Measured files"): a CSV as track recording cars export it, one row per
// position, the unit of every column in its name:
//
//   # comment lines start with '#'
//   arc_length_m,alignment_mm,level_mm,cross_level_mm,gauge_mm
//   0.00,0.12,-0.31,0.05,0.10
//
// Columns: the arc length (`arc_length_m` or `s_m`, strictly increasing)
// and any of the four channels (irregularity_spec.hpp) with the suffix `_m`
// or `_mm`; a channel left out is zero. Separators: ',' ';' or a tab. Every
// error is an IrregularityFileError naming the file, the line where one
// applies, and what was expected.
#include <railstab/irregularity/irregularity_spec.hpp>

#include <stdexcept>
#include <string>

namespace railstab {

struct IrregularityFileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Largest |value| a channel may take (m): beyond it a record is taken to be
// in the wrong unit (mm read as m) rather than track.
inline constexpr double kLargestMeasuredIrregularity_m = 0.1;
// Fewest rows: a cubic spline needs four points.
inline constexpr int kFewestMeasuredRows = 4;

MeasuredIrregularities read_measured_irregularities(const std::string& path);

}  // namespace railstab
