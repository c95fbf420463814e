#include <railstab/irregularity/measured_irregularity_file.hpp>

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace railstab {

namespace {

std::string where(const std::string& path, int line) { return path + ":" + std::to_string(line); }

std::string trimmed(std::string_view t) {
  const auto first = t.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = t.find_last_not_of(" \t\r");
  return std::string(t.substr(first, last - first + 1));
}

// Splits at ',' ';' or tab (one kind per file: the header's).
std::vector<std::string> fields_of(const std::string& line, char separator) {
  std::vector<std::string> out;
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, separator)) out.push_back(trimmed(field));
  if (!line.empty() && line.back() == separator) out.emplace_back();
  return out;
}

char separator_of(const std::string& header) {
  for (char c : {',', ';', '\t'})
    if (header.find(c) != std::string::npos) return c;
  return ',';
}

// What a header column holds: -1 the arc length, 0..3 a channel; the factor
// to metres.
struct Column {
  int channel = -2;  // -2: not recognised
  double to_m = 1.0;
};

Column column_of(const std::string& name) {
  if (name == "arc_length_m" || name == "s_m") return {-1, 1.0};
  for (int c = 0; c < kIrregularityChannels; ++c) {
    const std::string base(name_in(kIrregularityChannelNames, IrregularityChannel(c)));
    if (name == base + "_m") return {c, 1.0};
    if (name == base + "_mm") return {c, 1e-3};
  }
  return {};
}

const char* kExpectedColumns =
    "arc_length_m (or s_m) and any of alignment, level, cross_level, gauge with the unit "
    "suffix _m or _mm (e.g. alignment_mm)";

}  // namespace

MeasuredIrregularities read_measured_irregularities(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
    throw IrregularityFileError(path + ": track irregularity file not found; expected an existing file");
  if (std::filesystem::is_directory(path, ec))
    throw IrregularityFileError(path + ": is a directory; expected a track irregularity file (CSV)");
  std::ifstream in(path);
  if (!in) throw IrregularityFileError(path + ": cannot open the track irregularity file for reading");
  MeasuredIrregularities m;
  m.path = path;
  std::vector<Column> columns;
  char separator = ',';
  int arc_column = -1;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    const std::string t = trimmed(line);
    if (t.empty() || t[0] == '#') continue;
    if (columns.empty()) {  // the header
      separator = separator_of(t);
      const std::vector<std::string> names = fields_of(t, separator);
      for (size_t i = 0; i < names.size(); ++i) {
        const Column c = column_of(names[i]);
        if (c.channel == -2)
          throw IrregularityFileError(where(path, number) + ": column '" + names[i] +
                                      "': expected " + kExpectedColumns);
        if ((c.channel == -1 && arc_column >= 0) || (c.channel >= 0 && m.in_file[size_t(c.channel)]))
          throw IrregularityFileError(where(path, number) + ": column '" + names[i] +
                                      "' appears twice; expected each quantity once");
        if (c.channel == -1) arc_column = int(i);
        if (c.channel >= 0) m.in_file[size_t(c.channel)] = true;
        columns.push_back(c);
      }
      if (arc_column < 0)
        throw IrregularityFileError(where(path, number) + ": expected an arc_length_m (or s_m) column in the header, got '" + t + "'");
      if (columns.size() < 2)
        throw IrregularityFileError(where(path, number) + ": expected at least one channel column besides the arc length (" +
                                    kExpectedColumns + ")");
      continue;
    }
    const std::vector<std::string> fields = fields_of(t, separator);
    if (fields.size() != columns.size())
      throw IrregularityFileError(where(path, number) + ": expected " + std::to_string(columns.size()) +
                                  " values (as the header's columns), got " + std::to_string(fields.size()));
    for (size_t i = 0; i < fields.size(); ++i) {
      double v = 0.0;
      const std::string& f = fields[i];
      const auto r = std::from_chars(f.data(), f.data() + f.size(), v);
      if (f.empty() || r.ec != std::errc() || r.ptr != f.data() + f.size() || !std::isfinite(v))
        throw IrregularityFileError(where(path, number) + ": column " + std::to_string(i + 1) +
                                    ": expected a finite number, got '" + f + "'");
      const Column& c = columns[i];
      v *= c.to_m;
      if (c.channel == -1) {
        if (!m.arc_length_m.empty() && !(v > m.arc_length_m.back()))
          throw IrregularityFileError(where(path, number) + ": arc length " + f +
                                      " m: expected arc lengths strictly increasing down the file");
        m.arc_length_m.push_back(v);
      } else {
        if (!(std::abs(v) <= kLargestMeasuredIrregularity_m))
          throw IrregularityFileError(
              where(path, number) + ": column " + std::to_string(i + 1) + ": expected |value| <= " +
              std::to_string(int(kLargestMeasuredIrregularity_m * 1e3)) +
              " mm (a larger value is more likely a unit mistake than track), got " + f);
        m.channels_m[size_t(c.channel)].push_back(v);
      }
    }
  }
  if (in.bad()) throw IrregularityFileError(path + ": read error");
  if (columns.empty())
    throw IrregularityFileError(path + ": expected a header line (" + std::string(kExpectedColumns) + "), got none");
  if (int(m.arc_length_m.size()) < kFewestMeasuredRows)
    throw IrregularityFileError(path + ": expected at least " + std::to_string(kFewestMeasuredRows) +
                                " rows of values (a cubic spline's points), got " +
                                std::to_string(m.arc_length_m.size()));
  for (std::vector<double>& channel : m.channels_m)
    if (channel.empty()) channel.assign(m.arc_length_m.size(), 0.0);
  return m;
}

}  // namespace railstab
